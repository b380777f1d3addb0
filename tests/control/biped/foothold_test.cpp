#include "engine/control/biped/foothold.h"

#include <gtest/gtest.h>

#include <cmath>

#include "control/biped/boxes.h"

using control_test::Box;
using control_test::Boxes;
using control_test::two_crates;
using eng::control::find_foothold;
using eng::control::foothold_ok;
using V = Eigen::Vector2d;

TEST(Foothold, ASoleInsideOneCrateNeedsNoShift) {
  const Boxes crates = two_crates();
  const auto a = crates.ground();
  EXPECT_TRUE(foothold_ok(a, V(-0.25, 0.0), 0.0));
  const auto f = find_foothold(a, V(-0.25, 0.0), 0.0, 0.0);
  EXPECT_TRUE(f.found);
  EXPECT_EQ(f.shift, V::Zero());
}

TEST(Foothold, AnOverhangOverALowerCrateIsFineOverAHigherOneIsNot) {
  const Boxes crates = two_crates();
  const auto a = crates.ground();
  // Toes along +X on the high crate, heel 2 cm out over the low one: flat on the high crate.
  EXPECT_TRUE(foothold_ok(a, V(0.06, 0.0), 0.0));
  // Toes along -X on the low crate, heel resting on the high crate's edge: the foot would tilt over that edge.
  EXPECT_FALSE(foothold_ok(a, V(-0.06, 0.0), M_PI));
}

TEST(Foothold, AStraddlingSoleMovesTheLeastGridStepThatLandsItFlat) {
  const Boxes crates = two_crates();
  const auto a = crates.ground();
  const V ankle(-0.10, 0.0);  // sole x in [-0.18, 0.08]: toe on the high crate, core mostly on the low one
  ASSERT_FALSE(foothold_ok(a, ankle, 0.0));
  const eng::control::FootholdParams p;
  const auto f = find_foothold(a, ankle, 0.0, 0.0, p);
  ASSERT_TRUE(f.found);
  EXPECT_TRUE(foothold_ok(a, ankle + f.shift, 0.0));
  // Back until the toe leaves the high crate (its edge at x = 0.006): ankle <= -0.174, i.e. 8 cm on the grid.
  EXPECT_NEAR(f.shift.x(), -0.08, 1e-9);
  EXPECT_NEAR(f.shift.y(), 0.0, 1e-9);
  // No cheaper grid shift is good (brute force over the same grid and cost).
  const double cost = f.shift.squaredNorm();
  for (int i = -20; i <= 20; ++i)
    for (int j = -20; j <= 20; ++j) {
      const V s(i * p.grid, j * p.grid);
      if (s.x() * s.x() + p.lateral_cost * s.y() * s.y() < cost - 1e-12) {
        EXPECT_FALSE(foothold_ok(a, ankle + s, 0.0)) << s.transpose();
      }
    }
}

TEST(Foothold, NothingWithinTheSearchRadiusLeavesTheSpotAndSaysSo) {
  Boxes post;  // a 10 cm post: no sole fits on it; the floor around it is clear of it only 14 cm away
  post.boxes.push_back(Box{{0.0, 0.0, 0.2}, {0.05, 0.05, 0.2}});
  const auto a = post.ground();
  eng::control::FootholdParams p;
  p.max_shift = 0.10;
  const auto f = find_foothold(a, V(0.0, 0.0), 0.0, 0.0, p);
  EXPECT_FALSE(f.found);
  EXPECT_EQ(f.shift, V::Zero());
  p.max_shift = 0.20;
  const auto g = find_foothold(a, V(0.0, 0.0), 0.0, 0.0, p);
  ASSERT_TRUE(g.found);
  // Forward until the heel (ankle - 0.08) clears the post edge at 0.05: 0.14 on the grid (backward needs 0.24).
  EXPECT_NEAR(g.shift.x(), 0.14, 1e-9);
}

// FootholdParams::clearance (the balance steps' footholds): a landing beside a higher top keeps that far from it, so a
// landing a few cm off does not come down on its edge; an overhang over a LOWER top stays fine.
TEST(Foothold, TheClearanceKeepsALandingThatFarFromAHigherTopButNotFromALowerOne) {
  const Boxes crates = two_crates();
  const auto a = crates.ground();
  eng::control::FootholdParams clear;
  clear.clearance = 0.05;
  // Toes along +X on the low crate, the toe (ankle + 0.18) 1.4 cm short of the high crate's side (x = 0.006).
  const V ankle(-0.20, 0.0);
  ASSERT_TRUE(foothold_ok(a, ankle, 0.0));
  EXPECT_FALSE(foothold_ok(a, ankle, 0.0, clear));
  const auto f = find_foothold(a, ankle, 0.0, 0.0, clear);
  ASSERT_TRUE(f.found);
  // Back until the sample 5 cm past the toe leaves the high crate: ankle + 0.23 < 0.006, on the 1 cm grid -0.03.
  EXPECT_NEAR(f.shift.x(), -0.03, 1e-9);
  EXPECT_NEAR(f.shift.y(), 0.0, 1e-9);
  EXPECT_LE(ankle.x() + f.shift.x() + clear.sole.toe + clear.clearance, 0.006);
  // On the high crate with the heel 2 cm out over the low one: still flat on the high one.
  EXPECT_TRUE(foothold_ok(a, V(0.06, 0.0), 0.0, clear));
}

// FootholdParams::back_cost (the carried steps' footholds): of two shifts that land a straddling sole flat, one along
// frame_yaw and one against it, the one against costs back_cost times more. Symmetric (1), the nearer wins; with the
// cost high enough the farther one along frame_yaw wins (a carried step lands short of the stance foot's side).
TEST(Foothold, TheBackCostPrefersTheShiftAlongFrameYaw) {
  const Boxes crates = two_crates();
  const auto a = crates.ground();
  const V ankle(-0.10, 0.0);  // straddling: 8 cm back (onto the low crate) or 11 cm forward (onto the high one)
  ASSERT_FALSE(foothold_ok(a, ankle, 0.0));
  eng::control::FootholdParams p;
  const auto near = find_foothold(a, ankle, 0.0, 0.0, p);
  ASSERT_TRUE(near.found);
  EXPECT_NEAR(near.shift.x(), -0.08, 1e-9);
  // Toward +X preferred: the backward 8 cm costs 4 x 0.0064 = 0.0256, the forward shift (0.11^2 = 0.0121) wins.
  p.back_cost = 4.0;
  const auto fwd = find_foothold(a, ankle, 0.0, 0.0, p);
  ASSERT_TRUE(fwd.found);
  EXPECT_TRUE(foothold_ok(a, ankle + fwd.shift, 0.0, p));
  EXPECT_GT(fwd.shift.x(), 0.0);
  EXPECT_LT(fwd.shift.squaredNorm(), p.back_cost * near.shift.squaredNorm());
  // frame_yaw turned round (toward -X): the backward shift is along it again, and the cheapest.
  const auto back = find_foothold(a, ankle, 0.0, M_PI, p);
  ASSERT_TRUE(back.found);
  EXPECT_NEAR(back.shift.x(), -0.08, 1e-9);
}
