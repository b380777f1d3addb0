// Two-bone IK (engine/control/ik/two_bone_ik.h) against closed-form geometry: a reachable target is met exactly by
// the chain's end joint, the hinge bends the way its sign says with the angle the law of cosines gives, the bones keep
// their lengths (forward kinematics of the solved pose), and an unreachable target is approached along its line.
#include "engine/control/ik/two_bone_ik.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/control/servo/world_pose.h"

using namespace eng::control;

namespace {
// root -> shoulder (upper arm) -> elbow (forearm, hinge about -X like the boxer's) -> wrist (glove).
eng::anim::Skeleton arm_skeleton() {
  eng::anim::Skeleton s;
  s.name = {"chest", "upper_arm", "forearm", "glove"};
  s.parent = {-1, 0, 1, 2};
  s.offset = {Eigen::Vector3d::Zero(), {0, 0.2, 0.3}, {0, 0.3, 0}, {0, 0.28, 0}};
  return s;
}

eng::anim::Pose rest(const eng::anim::Skeleton& s) {
  eng::anim::Pose p;
  p.root_position = {0.1, -0.2, 1.3};
  p.rotation.assign(s.size(), Eigen::Quaterniond::Identity());
  p.rotation[0] = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ());
  p.rotation[2] = Eigen::AngleAxisd(0.8, -Eigen::Vector3d::UnitX());  // elbow bent like a guard
  return p;
}

const TwoBoneChain kArm{1, 2, 3, -Eigen::Vector3d::UnitX(), 1.0};
}  // namespace

TEST(TwoBoneIk, ReachableTargetIsMetExactlyAndBonesKeepTheirLengths) {
  const auto s = arm_skeleton();
  std::vector<Eigen::Quaterniond> W;
  std::vector<Eigen::Vector3d> P;
  for (const Eigen::Vector3d& off : {Eigen::Vector3d(0.35, 0.1, 0.0), Eigen::Vector3d(0.1, 0.4, -0.2),
                                     Eigen::Vector3d(0.2, -0.1, 0.25)}) {
    auto pose = rest(s);
    pose_fk(s, pose, W, P);
    const Eigen::Vector3d target = P[1] + off;
    solve_two_bone(s, kArm, W, P, target, pose);
    std::vector<Eigen::Quaterniond> W2;
    std::vector<Eigen::Vector3d> P2;
    pose_fk(s, pose, W2, P2);
    EXPECT_LT((P2[3] - target).norm(), 1e-9);
    EXPECT_NEAR((P2[2] - P2[1]).norm(), 0.3, 1e-12);
    EXPECT_NEAR((P2[3] - P2[2]).norm(), 0.28, 1e-12);
    // The hinge angle is the law of cosines' flexion, about the hinge axis with the chain's sign.
    const double d = off.norm();
    const double flex = M_PI - std::acos((0.3 * 0.3 + 0.28 * 0.28 - d * d) / (2 * 0.3 * 0.28));
    const Eigen::AngleAxisd elbow(pose.rotation[2]);
    EXPECT_NEAR(elbow.angle(), flex, 1e-9);
    EXPECT_GT(elbow.axis().dot(kArm.hinge_axis), 0.999);
  }
}

TEST(TwoBoneIk, UnreachableTargetEndsAtFullReachOnTheLineToIt) {
  const auto s = arm_skeleton();
  std::vector<Eigen::Quaterniond> W;
  std::vector<Eigen::Vector3d> P;
  auto pose = rest(s);
  pose_fk(s, pose, W, P);
  const Eigen::Vector3d dir = Eigen::Vector3d(1, 0.3, -0.2).normalized();
  solve_two_bone(s, kArm, W, P, P[1] + 2.0 * dir, pose);
  pose_fk(s, pose, W, P);
  const Eigen::Vector3d reach = P[3] - P[1];
  EXPECT_NEAR(reach.norm(), two_bone_reach(s, kArm) - 1e-3, 1e-9);
  EXPECT_GT(reach.normalized().dot(dir), 1.0 - 1e-12);
}

TEST(TwoBoneIk, OnlyTheChainMovesAndTheEndKeepsItsParentRelativeRotation) {
  const auto s = arm_skeleton();
  std::vector<Eigen::Quaterniond> W;
  std::vector<Eigen::Vector3d> P;
  auto pose = rest(s);
  pose.rotation[3] = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
  const auto before = pose;
  pose_fk(s, pose, W, P);
  solve_two_bone(s, kArm, W, P, P[1] + Eigen::Vector3d(0.3, 0.2, 0.1), pose);
  EXPECT_TRUE(pose.rotation[0].isApprox(before.rotation[0], 0.0));
  EXPECT_TRUE(pose.rotation[3].isApprox(before.rotation[3], 0.0));
  EXPECT_EQ(pose.root_position, before.root_position);
}
