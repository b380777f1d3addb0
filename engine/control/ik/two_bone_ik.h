#pragma once
// Two-bone IK on a parent-space pose: an upper bone on a ball joint and a lower bone on a hinge (a leg: thigh and
// shank; an arm: upper arm and forearm) put the chain's end joint (ankle, wrist) on a world target. Analytic: the
// hinge angle from the law of cosines, then the upper bone re-aimed at the target by the smallest world rotation, so
// the chain keeps the swivel (knee / elbow direction) the pose had. Unreachable targets end at full reach (less 1 mm)
// along the line to the target.
#include <vector>

#include "engine/anim/skeleton.h"

namespace eng::control {

struct TwoBoneChain {
  int upper = -1, lower = -1, end = -1;  // bones: end's joint is the point that is placed
  Eigen::Vector3d hinge_axis = Eigen::Vector3d::UnitY();  // the lower bone's hinge axis (its frame = parent's at rest)
  double bend_sign = 1.0;  // +1: the hinge flexes by a positive angle about hinge_axis, -1: negative
  bool valid() const { return upper >= 0 && lower >= 0 && end >= 0; }
};

// W, P: the pose's forward kinematics (world bone orientations, world joint positions; pose_fk). Writes
// pose.rotation[upper] and pose.rotation[lower]; the end bone keeps its parent-relative rotation (callers that want
// it fixed in the world, a foot, set it from the returned upper's world orientation). Returns the upper bone's new
// world orientation.
Eigen::Quaterniond solve_two_bone(const anim::Skeleton& skel, const TwoBoneChain& chain,
                                  const std::vector<Eigen::Quaterniond>& W, const std::vector<Eigen::Vector3d>& P,
                                  const Eigen::Vector3d& target, anim::Pose& pose);

// The end joint's reach from the upper joint: |offset[lower]| + |offset[end]| (m).
double two_bone_reach(const anim::Skeleton& skel, const TwoBoneChain& chain);

}  // namespace eng::control
