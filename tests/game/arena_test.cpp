// The arena layout: seeded, uneven by construction (the leg fitting onto it: tests/control/biped/leg_ik_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

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
