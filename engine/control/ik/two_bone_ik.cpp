#include "engine/control/ik/two_bone_ik.h"

#include <algorithm>
#include <cmath>

namespace eng::control {

Eigen::Quaterniond solve_two_bone(const anim::Skeleton& skel, const TwoBoneChain& c,
                                  const std::vector<Eigen::Quaterniond>& W, const std::vector<Eigen::Vector3d>& P,
                                  const Eigen::Vector3d& target, anim::Pose& pose) {
  const Eigen::Vector3d root = P[c.upper];
  const Eigen::Vector3d upper_off = skel.offset[c.lower], lower_off = skel.offset[c.end];
  const double l1 = upper_off.norm(), l2 = lower_off.norm();
  const double d = std::clamp((target - root).norm(), std::abs(l1 - l2) + 1e-3, l1 + l2 - 1e-3);
  // Hinge flexion from the law of cosines: the interior angle phi, flexion = pi - phi.
  const double cos_phi = std::clamp((l1 * l1 + l2 * l2 - d * d) / (2 * l1 * l2), -1.0, 1.0);
  const double flex = M_PI - std::acos(cos_phi);
  const Eigen::Quaterniond hinge(Eigen::AngleAxisd(c.bend_sign * flex, c.hinge_axis));
  // Re-aim the upper bone: the smallest world rotation taking the current root->end direction to the target's.
  const Eigen::Vector3d current = W[c.upper] * (upper_off + hinge * lower_off);
  const Eigen::Quaterniond aim = Eigen::Quaterniond::FromTwoVectors(current, target - root);
  const Eigen::Quaterniond upper_w = (aim * W[c.upper]).normalized();
  const int parent = skel.parent[c.upper];
  pose.rotation[c.upper] = (W[parent].conjugate() * upper_w).normalized();
  pose.rotation[c.lower] = hinge;
  return upper_w;
}

double two_bone_reach(const anim::Skeleton& skel, const TwoBoneChain& c) {
  return skel.offset[c.lower].norm() + skel.offset[c.end].norm();
}

}  // namespace eng::control
