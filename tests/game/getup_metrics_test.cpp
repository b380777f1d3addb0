// The report's `getups` (game/getup_metrics.h) against what the scene does: a boxer floored in `stand`, where no
// stand-up (and so no root assist) acts. Against the match's own bookkeeping of a get-up: match/match_test.cpp
// (GetUpMetrics.AMatchGetUpIsRecordedAsTheMatchCountsIt).
#include <gtest/gtest.h>

#include "game/interaction/interaction.h"
#include "game/world.h"

namespace boxing {
namespace {

constexpr int kTicksPerSecond = 240;

std::unique_ptr<World> world_of(Scenario id, const char* name) {
  Options o;
  o.headless = true;
  o.scenario_id = id;
  o.scenario = name;
  o.seed = 1;
  auto w = make_world(o);
  EXPECT_TRUE(w) << w.error();
  return w ? std::move(*w) : nullptr;
}

void submit_push(World& w, int k, const Eigen::Vector3d& force, double duration) {
  InputEvent push;
  push.kind = InputKind::Push;
  push.boxer = k;
  push.bone = "chest";
  push.vec = force;
  push.duration = duration;
  interaction_submit(w, push);
}

// Floored in `stand` by a push (2500 N for 0.3 s), the boxer lies: nothing lifts it, so the record's lift force is 0
// to the bit and it stays open (not up), its one phase "down".
TEST(GetUpMetrics, AFallWithNoStandUpMeasuresNoLiftForce) {
  auto w = world_of(Scenario::Stand, "stand");
  ASSERT_TRUE(w);
  World& world = *w;
  for (int i = 0; i < kTicksPerSecond; ++i) step_world(world);
  submit_push(world, 0, Eigen::Vector3d(2500.0, 0.0, 0.0), 0.3);
  for (int i = 0; i < 6 * kTicksPerSecond; ++i) step_world(world);
  ASSERT_FALSE(world.getups.records.empty()) << "the push did not floor the boxer";
  const GetUpRecord& r = world.getups.records[0];
  EXPECT_LT(r.up_at, 0.0);
  EXPECT_EQ(r.lift_force_peak, 0.0);
  EXPECT_EQ(r.lift_force_sq_dt, 0.0);
  ASSERT_EQ(r.phases.size(), 1u);
  EXPECT_EQ(r.phases[0].first, "down");
  EXPECT_GT(r.time, 4.0);
}

}  // namespace
}  // namespace boxing
