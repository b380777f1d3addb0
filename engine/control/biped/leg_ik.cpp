#include "engine/control/biped/leg_ik.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/control/ik/two_bone_ik.h"
#include "engine/control/servo/world_pose.h"

namespace eng::control {

namespace {

void solve_leg(const anim::Skeleton& skel, const LegBones& L, const std::vector<Eigen::Quaterniond>& W,
               const std::vector<Eigen::Vector3d>& P, const Eigen::Vector3d& ankle, anim::Pose& pose) {
  // The knee: a hinge flexing about +Y; the foot keeps its world orientation so the sole stays flat.
  const TwoBoneChain leg{L.thigh, L.shank, L.foot, Eigen::Vector3d::UnitY(), 1.0};
  const Eigen::Quaterniond thigh_w = solve_two_bone(skel, leg, W, P, ankle, pose);
  const Eigen::Quaterniond shank_w = (thigh_w * pose.rotation[L.shank]).normalized();
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
