#include "game/foothold.h"

#include <gtest/gtest.h>

#include <cmath>

using boxing::Arena;
using boxing::Crate;
using boxing::find_foothold;
using boxing::foothold_ok;
using V = Eigen::Vector2d;

namespace {
// Two crates side by side along X with a 1.2 cm seam: the low one (top 0.30) at x < 0, the high one (top 0.40) at
// x > 0, both 0.488 m square (the arena's cells).
Arena two_crates() {
  Arena a;
  a.crates.push_back(Crate{{-0.25, 0.0, 0.15}, {0.244, 0.244, 0.15}, {}});
  a.crates.push_back(Crate{{0.25, 0.0, 0.20}, {0.244, 0.244, 0.20}, {}});
  return a;
}
}  // namespace

TEST(Foothold, ASoleInsideOneCrateNeedsNoShift) {
  const Arena a = two_crates();
  EXPECT_TRUE(foothold_ok(a, V(-0.25, 0.0), 0.0));
  const auto f = find_foothold(a, V(-0.25, 0.0), 0.0, 0.0);
  EXPECT_TRUE(f.found);
  EXPECT_EQ(f.shift, V::Zero());
}

TEST(Foothold, AnOverhangOverALowerCrateIsFineOverAHigherOneIsNot) {
  const Arena a = two_crates();
  // Toes along +X on the high crate, heel 2 cm out over the low one: flat on the high crate.
  EXPECT_TRUE(foothold_ok(a, V(0.06, 0.0), 0.0));
  // Toes along -X on the low crate, heel resting on the high crate's edge: the foot would tilt over that edge.
  EXPECT_FALSE(foothold_ok(a, V(-0.06, 0.0), M_PI));
}

TEST(Foothold, AStraddlingSoleMovesTheLeastGridStepThatLandsItFlat) {
  const Arena a = two_crates();
  const V ankle(-0.10, 0.0);  // sole x in [-0.18, 0.08]: toe on the high crate, core mostly on the low one
  ASSERT_FALSE(foothold_ok(a, ankle, 0.0));
  const boxing::FootholdParams p;
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
      if (s.x() * s.x() + p.lateral_cost * s.y() * s.y() < cost - 1e-12) EXPECT_FALSE(foothold_ok(a, ankle + s, 0.0)) << s.transpose();
    }
}

TEST(Foothold, NothingWithinTheSearchRadiusLeavesTheSpotAndSaysSo) {
  Arena a;  // a 10 cm post: no sole fits on it; the floor around it is clear of it only 14 cm away
  a.crates.push_back(Crate{{0.0, 0.0, 0.2}, {0.05, 0.05, 0.2}, {}});
  boxing::FootholdParams p;
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
