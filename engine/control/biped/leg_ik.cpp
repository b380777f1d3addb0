#include "engine/control/biped/leg_ik.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/control/servo/world_pose.h"

namespace eng::control {

namespace {

void solve_leg(const anim::Skeleton& skel, const LegBones& L, const std::vector<Eigen::Quaterniond>& W,
               const std::vector<Eigen::Vector3d>& P, const Eigen::Vector3d& ankle, anim::Pose& pose) {
    const Eigen::Vector3d hip = P[L.thigh];

    const Eigen::Vector3d thigh_off = skel.offset[L.shank], shank_off = skel.offset[L.foot];
    const double l1 = thigh_off.norm(), l2 = shank_off.norm();
    const double d = std::clamp((ankle - hip).norm(), std::abs(l1 - l2) + 1e-3, l1 + l2 - 1e-3);
    // Knee flexion from the law of cosines: the interior angle phi, flexion = pi - phi (hinge about +Y).
    const double cos_phi = std::clamp((l1 * l1 + l2 * l2 - d * d) / (2 * l1 * l2), -1.0, 1.0);
    const double flex = M_PI - std::acos(cos_phi);
    const Eigen::Quaterniond knee(Eigen::AngleAxisd(flex, Eigen::Vector3d::UnitY()));

    // Re-aim the thigh: the smallest world rotation taking the current hip->ankle direction to the target's.
    const Eigen::Vector3d current = W[L.thigh] * (thigh_off + knee * shank_off);
    const Eigen::Quaterniond aim = Eigen::Quaterniond::FromTwoVectors(current, ankle - hip);
    const Eigen::Quaterniond thigh_w = (aim * W[L.thigh]).normalized();
    const Eigen::Quaterniond shank_w = (thigh_w * knee).normalized();
    const int pelvis = skel.parent[L.thigh];
    pose.rotation[L.thigh] = (W[pelvis].conjugate() * thigh_w).normalized();
    pose.rotation[L.shank] = knee;
    pose.rotation[L.foot] = (shank_w.conjugate() * W[L.foot]).normalized();
}

}  // namespace

void fit_legs_to_ground(const anim::Skeleton& skel, const LegBones legs[2], double base_top,
                        GroundHeight ground, anim::Pose& pose,
                        const Eigen::Vector3d& foot_centre) {
  // Scratch for the pose's forward kinematics, kept between calls (no allocation per tick).
  thread_local std::vector<Eigen::Quaterniond> W;
  thread_local std::vector<Eigen::Vector3d> P;
  pose_fk(skel, pose, W, P);
  for (int k = 0; k < 2; ++k) {
    const LegBones& L = legs[k];
    Eigen::Vector3d ankle = P[L.foot];
    // The foot's sole is flat under the ankle: sample the ground at the middle of the foot.
    const Eigen::Vector3d mid = ankle + W[L.foot] * foot_centre;
    ankle.z() += ground(mid.x(), mid.y()) - base_top;
    solve_leg(skel, L, W, P, ankle, pose);
  }
}

void fit_legs_to_ankles(const anim::Skeleton& skel, const LegBones legs[2], const Eigen::Vector3d ankles[2],
                        anim::Pose& pose) {
  // Scratch for the pose's forward kinematics, kept between calls (no allocation per tick).
  thread_local std::vector<Eigen::Quaterniond> W;
  thread_local std::vector<Eigen::Vector3d> P;
  pose_fk(skel, pose, W, P);
  for (int k = 0; k < 2; ++k) solve_leg(skel, legs[k], W, P, ankles[k], pose);
}

}  // namespace eng::control
