// The arena layout: seeded, uneven by construction (the leg fitting onto it: tests/control/biped/leg_ik_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "game/arena.h"

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

TEST(Arena, FlatIsOneLevelPlatform) {
  const boxing::Arena a = boxing::make_arena(5, 0.10, 1.20, true);
  for (const auto& c : a.crates) EXPECT_NEAR(c.center.z() + c.half_extents.z(), 0.30, 1e-12);
  for (const auto& s : a.stances) EXPECT_NEAR(s.lead_top - s.rear_top, 0.0, 1e-12);
}

// The match's ring (make_ring): 5 m inside, walkable steps between neighbours, the marks out of reach of each other
// with the arena's step between the feet, four corners on the ropes' square.
TEST(Arena, RingIsFiveMetresInsideWithWalkableStepsAndMarksApart) {
  for (uint64_t seed = 1; seed <= 50; ++seed) {
    const Arena a = make_ring(seed);
    const Ring& r = a.ring;
    ASSERT_TRUE(r.present);
    EXPECT_NEAR(2.0 * r.half_inside, 5.0, 1e-12);
    EXPECT_NEAR(r.top_mean, 0.30, 0.02) << "seed " << seed;
    // Every cell centre's top (the apron's too) within 8 cm of its neighbours'.
    for (double x = -2.75; x <= 2.76; x += 0.5)
      for (double y = -2.75; y <= 2.76; y += 0.5) {
        const double h = a.top_at(x, y);
        EXPECT_GT(h, kFloorTop);
        if (std::abs(x) < 2.5 && std::abs(y) < 2.5) {
          EXPECT_NEAR(h, 0.30, 0.04 + 1e-9) << "seed " << seed;
        }
        if (x + 0.5 < 2.76) {
          EXPECT_LE(std::abs(a.top_at(x + 0.5, y) - h), 0.08 + 1e-9) << x << "," << y;
        }
        if (y + 0.5 < 2.76) {
          EXPECT_LE(std::abs(a.top_at(x, y + 0.5) - h), 0.08 + 1e-9) << x << "," << y;
        }
      }
    EXPECT_GE((a.stances[0].position - a.stances[1].position).norm(), 2.5);
    for (const Stance& s : a.stances) {
      EXPECT_GE(std::abs(s.lead_top - s.rear_top), kRingMinStep - 1e-12) << "seed " << seed;
      EXPECT_TRUE(r.inside(s.position, 1.0));
    }
    for (const Eigen::Vector2d& c : r.corners) EXPECT_NEAR(c.cwiseAbs().minCoeff(), r.half_inside, 1e-12);
    EXPECT_NEAR((r.corners[Ring::kRed] + r.corners[Ring::kBlue]).norm(), 0.0, 1e-12);  // opposite corners
  }
  EXPECT_FALSE(make_arena(1).ring.present);
}

TEST(Arena, TheCrateIndexGivesTheSameTopsAsScanningEveryCrate) {
  // Random points over the platform and past it, and points on the crates' edges and corners: the indexed query
  // against a copy whose index is dropped (top_at then scans every crate).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-3.6, 3.6);
  for (const Arena& a : {make_ring(4, 0.10, 2.8), make_arena(4)}) {
    Arena scan = a;
    scan.index = CrateIndex{};
    ASSERT_EQ(a.index.indexed, a.crates.size());
    int on_crates = 0;
    for (int i = 0; i < 4000; ++i) {
      const double x = u(rng), y = u(rng);
      EXPECT_EQ(a.top_at(x, y), scan.top_at(x, y)) << x << ", " << y;
      on_crates += a.top_at(x, y) > 0.0;
    }
    for (const Crate& c : a.crates)
      for (int sx : {-1, 1})
        for (int sy : {-1, 1}) {
          const double x = c.center.x() + sx * c.half_extents.x(), y = c.center.y() + sy * c.half_extents.y();
          EXPECT_EQ(a.top_at(x, y), scan.top_at(x, y)) << x << ", " << y;
        }
    EXPECT_GT(on_crates, 400);  // the points do fall on crates (and off them)
    EXPECT_LT(on_crates, 3900);
  }
}
