// The unassisted get-up (--getup unassisted, game/balance/unassisted_getup.h) in the match: no external force on any
// body, the root helped only by a torque within its limit, the get-up plan's phases followed; and the carried get-up
// (--getup assisted) stays the default.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "game/cli.h"
#include "game/match/referee.h"
#include "game/world.h"

namespace boxing {
namespace {

std::unique_ptr<World> match_world(uint64_t seed, const std::string& getup) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.scenario = "match";
  o.seed = seed;
  o.getup = getup;
  auto w = make_world(o);
  EXPECT_TRUE(w) << w.error();
  return w ? std::move(*w) : nullptr;
}

bool has_phase(const GetUpRecord& r, const std::string& name) {
  return std::any_of(r.phases.begin(), r.phases.end(), [&](const auto& p) { return p.first == name; });
}

TEST(UnassistedGetUp, IsNotTheDefault) {
  EXPECT_EQ(Options{}.getup, "assisted");
  auto o = parse_cli({"--getup", "unassisted"});
  ASSERT_TRUE(o.ok()) << o.error();
  EXPECT_EQ(o->getup, "unassisted");
  auto bad = parse_cli({"--getup", "levitate"});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("--getup"), std::string::npos) << bad.error();
  auto w = match_world(3, Options{}.getup);
  ASSERT_TRUE(w);
  for (const Boxer& b : w->boxers) EXPECT_FALSE(b.settings.tuning.stand_up.unassisted);
}

// Match seed 3: boxer 0 is knocked down at 2 s by the referee's own call, pushed toward where it faces, so it falls on
// its front whatever the fight does (knock_down, referee.h). Unassisted, nothing but the body's joints and the QP's root torque acts on it: the record's lift force is
// 0 to the bit (no force is ever applied: by construction, so no tolerance), its root torque at most the plan's limit
// (GetUpPlanTuning::max_root_torque; the QP clamps it, 1e-9 N m for the clamp's rounding), and the plan gets past
// its first phase (push_up -> hands_knees: the gate opened on a measured support). It does not get up in time today
// (0 of the 6 knockdowns of match seeds 1-5 at 180 s are up within 10 s: docs/decisions/unassisted-getup.md), so no
// up-rate is asserted.
TEST(UnassistedGetUp, PutsNoForceOnTheBodyAndFollowsThePlansPhases) {
  auto w = match_world(3, "unassisted");
  ASSERT_TRUE(w);
  for (int i = 0; i < 2 * 240; ++i) step_world(*w);
  const Eigen::Vector3d facing = w->data.x[w->boxers[1].bodies.body[0]].p - w->data.x[w->boxers[0].bodies.body[0]].p;
  knock_down(*w, 0, Eigen::Vector3d(facing.x(), facing.y(), 0.0).normalized(), "test");
  for (int i = 0; i < 9 * 240; ++i) step_world(*w);
  const GetUpRecord* r = nullptr;
  for (const GetUpRecord& g : w->getups.records)
    if (g.boxer == 0 && g.down_at >= 2.0) r = &g;
  ASSERT_NE(r, nullptr) << "no knockdown of boxer 0 after the call at 2 s";
  EXPECT_EQ(r->lying, "front");
  EXPECT_EQ(r->lift_force_peak, 0.0);
  EXPECT_EQ(r->lift_force_sq_dt, 0.0);
  EXPECT_LE(r->root_torque_peak, GetUpPlanTuning{}.max_root_torque + 1e-9);
  EXPECT_GT(r->root_torque_peak, 0.0);  // (the plan does use its root torque)
  EXPECT_TRUE(has_phase(*r, "push_up"));
  EXPECT_TRUE(has_phase(*r, "hands_knees"));
}

}  // namespace
}  // namespace boxing
