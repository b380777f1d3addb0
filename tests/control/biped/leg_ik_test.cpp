// Two-bone leg IK: a clip's legs fitted onto uneven ground keep their lengths and their soles' orientation.
#include "engine/control/biped/leg_ik.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/control/servo/world_pose.h"

using namespace eng::control;

namespace {
eng::anim::Skeleton leg_skeleton() {
  eng::anim::Skeleton s;
  s.name = {"pelvis", "thigh_l", "shank_l", "foot_l", "thigh_r", "shank_r", "foot_r"};
  s.parent = {-1, 0, 1, 2, 0, 4, 5};
  s.offset = {Eigen::Vector3d::Zero(), {0, 0.09, -0.04}, {0, 0, -0.43}, {0, 0, -0.42},
              {0, -0.09, -0.04}, {0, 0, -0.43}, {0, 0, -0.42}};
  return s;
}
}  // namespace

TEST(LegIk, FeetLandOnTheirCratesFlatAndLegLengthsArePreserved) {
  const auto s = leg_skeleton();
  eng::anim::Pose pose;
  pose.root_position = {0, 0, 0.90};
  pose.rotation.assign(s.size(), Eigen::Quaterniond::Identity());
  // Knees bent 20 degrees, thighs forward so the ankles are under the hips (a guard-like stance).
  for (int k : {1, 4}) pose.rotation[k] = Eigen::AngleAxisd(-0.175, Eigen::Vector3d::UnitY());
  for (int k : {2, 5}) pose.rotation[k] = Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitY());
  for (int k : {3, 6}) pose.rotation[k] = Eigen::AngleAxisd(-0.175, Eigen::Vector3d::UnitY());
  std::vector<Eigen::Quaterniond> W0;
  std::vector<Eigen::Vector3d> P0;
  pose_fk(s, pose, W0, P0);
  // Left foot on a crate 12 cm higher than the base the clip was authored on.
  auto ground_fn = [](double, double y) { return y > 0 ? 0.12 : 0.0; };
  const auto ground = GroundHeight::of(ground_fn);
  const LegBones legs[2] = {{1, 2, 3}, {4, 5, 6}};
  fit_legs_to_ground(s, legs, 0.0, ground, pose);
  std::vector<Eigen::Quaterniond> W;
  std::vector<Eigen::Vector3d> P;
  pose_fk(s, pose, W, P);
  EXPECT_NEAR(P[3].z(), P0[3].z() + 0.12, 1e-9);  // left ankle raised by the crate's height
  EXPECT_NEAR(P[6].z(), P0[6].z(), 1e-9);         // right ankle where the clip put it
  EXPECT_NEAR((P[3] - P0[3]).head<2>().norm(), 0.0, 1e-9);
  for (int f : {3, 6}) EXPECT_LT(W[f].angularDistance(W0[f]), 1e-9) << "the sole stays flat";
  EXPECT_NEAR((P[2] - P[1]).norm(), 0.43, 1e-12);
  EXPECT_NEAR((P[3] - P[2]).norm(), 0.42, 1e-12);
  EXPECT_GT(2 * std::acos(std::min(1.0, std::abs(pose.rotation[2].w()))), 0.35) << "the raised leg bends more";
}
