// The arena layout: seeded, uneven by construction, and the stance IK that fits clip legs onto crates.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/anim/skeleton.h"
#include "game/arena.h"
#include "game/stance_ik.h"

using namespace boxing;

TEST(Arena, SameSeedGivesTheSameLayoutAndOtherSeedsDiffer) {
  const Arena a = make_arena(7), b = make_arena(7), c = make_arena(8);
  ASSERT_EQ(a.crates.size(), b.crates.size());
  for (size_t i = 0; i < a.crates.size(); ++i) EXPECT_EQ(a.crates[i].center, b.crates[i].center);
  bool differs = a.crates.size() != c.crates.size();
  for (size_t i = 0; !differs && i < a.crates.size(); ++i) differs = a.crates[i].center != c.crates[i].center;
  EXPECT_TRUE(differs);
}

TEST(Arena, EveryBoxerHasOneFootAtLeastTenCentimetresHigher) {
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    const Arena a = make_arena(seed);
    for (const Stance& s : a.stances) {
      EXPECT_GE(std::abs(s.lead_top - s.rear_top), 0.10 - 1e-12) << "seed " << seed;
      EXPECT_GT(std::min(s.lead_top, s.rear_top), 0.1) << "both feet stand on crates, seed " << seed;
    }
  }
}

TEST(Arena, TopAtIsTheHighestCrateUnderThePointAndZeroOffThePlatform) {
  const Arena a = make_arena(3);
  EXPECT_EQ(a.top_at(10.0, 10.0), 0.0);
  const Crate& c = a.crates.front();
  EXPECT_GE(a.top_at(c.center.x(), c.center.y()), c.center.z() + c.half_extents.z() - 1e-12);
}

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

TEST(StanceIk, FeetLandOnTheirCratesFlatAndLegLengthsArePreserved) {
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
  auto ground = [](double, double y) { return y > 0 ? 0.12 : 0.0; };
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
