// Stamina (game/match/stamina.h, issue 65 item 3): the rule as written, and in the fight: each punch's start costs
// what the rule says, a masher's level falls until its punch keys are refused "tired", and with no punch playing it
// recovers at recover_rate.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "game/match/match.h"
#include "game/match/stamina.h"
#include "game/world.h"
#include "test_paths.h"

namespace boxing {
namespace {

// The rule's numbers, from its tuning (the asserts follow it if it is retuned).
TEST(Stamina, PunchesCostMoreInAFlurryDefencesAndStepsLessAndTheLevelRecoversWhileNoPunchPlays) {
  const StaminaTuning t;
  Stamina s;
  stamina_spend(s, t, stamina_clip_cost(s, t, true, 1, false, 0.0), true, 0.0);
  EXPECT_DOUBLE_EQ(s.level, 1.0 - t.punch_cost);
  // 0.5 s later: inside the flurry window, flurry_factor times the cost.
  stamina_spend(s, t, stamina_clip_cost(s, t, true, 1, false, 0.5), true, 0.5);
  EXPECT_DOUBLE_EQ(s.level, 1.0 - t.punch_cost - t.flurry_factor * t.punch_cost);
  const double after_punches = s.level;
  // Slips and steps cost less than a punch.
  EXPECT_LT(stamina_clip_cost(s, t, false, 0, true, 9.0), t.punch_cost);
  EXPECT_LT(t.move_cost, t.punch_cost);
  EXPECT_DOUBLE_EQ(stamina_clip_cost(s, t, true, 2, false, 9.0), 2.0 * t.punch_cost);  // a combination: two punches
  // Recovery: none while a punch plays, recover_rate per second otherwise (not spent here).
  stamina_recover(s, t, true, 1.0);
  EXPECT_DOUBLE_EQ(s.level, after_punches);
  for (int i = 0; i < 240; ++i) stamina_recover(s, t, false, 1.0 / 240.0);
  EXPECT_NEAR(s.level, after_punches + t.recover_rate, 1e-12);  // 1e-12: 240 additions' rounding
  // No effect in the band (exactly 1: the fight is the same as without stamina); linear below to the minimum at 0.
  for (const double level : {t.effect_below, 0.75, 1.0}) {
    s.level = level;
    EXPECT_EQ(stamina_speed(s, t), 1.0);
    EXPECT_EQ(stamina_power(s, t), 1.0);
  }
  s.level = 0.0;
  EXPECT_DOUBLE_EQ(stamina_speed(s, t), t.min_speed);
  EXPECT_DOUBLE_EQ(stamina_power(s, t), t.min_power);
  s.level = 0.5 * t.effect_below;
  EXPECT_DOUBLE_EQ(stamina_power(s, t), 0.5 * (1.0 + t.min_power));
  // Spent: below a punch's cost the boxer is gassed, recovering at spent_recover_rate, until rested_at.
  Stamina g;
  g.level = t.punch_cost + 0.01;
  stamina_spend(g, t, t.punch_cost, true, 0.0);
  EXPECT_FALSE(stamina_can_punch(g));
  double secs = 0.0;
  while (!stamina_can_punch(g) && secs < 100.0) stamina_recover(g, t, false, 0.01), secs += 0.01;
  EXPECT_NEAR(secs, (t.rested_at - 0.01) / t.spent_recover_rate, 0.011);  // 0.011 s: one 0.01 s step and rounding
}

// Red mashes jabs (one every 0.15 s from 2 s to 8 s) at an idle blue (handed to a player who presses nothing): each
// punch's start takes exactly its cost (punch_cost, flurry_factor times it within flurry_window of the last); the level
// falls until presses are refused "tired"; after the last punch it recovers by the rule (spent, then rested).
TEST(Stamina, DropsWithEachPunchThenTiredThenRecoversByTheRule) {
  const std::string input = std::string(BOXING_BINARY_DIR) + "/stamina_masher.json";
  {
    std::ofstream out(input);
    out << "{\"events\": [{\"t\": 0, \"set\": {\"boxer\": 1, \"control\": \"player\"}}";
    for (int i = 0; i <= 40; ++i) out << ", {\"t\": " << 2.0 + 0.15 * i << ", \"key\": {\"action\": \"jab\", \"boxer\": 0}}";
    out << "]}\n";
  }
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.scenario = "match";
  o.seed = 4;
  o.player = 0;
  o.start_apart = 1.0;
  o.input = input;
  auto made = make_world(o);
  ASSERT_TRUE(made) << made.error();
  World& w = **made;
  const Match& mt = *w.match;
  const StaminaTuning& t = mt.tuning.stamina;
  const Stamina& s = mt.fighter[0].stamina;
  size_t seen = 0;
  double last_start = -1e9;
  int punches = 0;
  while (w.data.time < 10.0) {
    const double before = s.level;
    step_world(w);
    for (; seen < mt.events.size(); ++seen) {
      const PunchEvent& e = mt.events[seen];
      if (e.boxer != 0) continue;
      const double cost = t.punch_cost * (e.t - last_start < t.flurry_window ? t.flurry_factor : 1.0);
      EXPECT_NEAR(s.level, std::max(0.0, before - cost), 1e-12) << "punch at " << e.t;
      last_start = e.t;
      ++punches;
    }
  }
  EXPECT_GE(punches, 4);
  EXPECT_LT(s.lowest, t.punch_cost);  // it ran out
  int tired = 0;
  for (const PlayerPress& p : mt.presses) tired += p.refused && std::string(p.refused) == "tired";
  EXPECT_GT(tired, 0);
  // No punch plays from here (the last press was at 8 s, refused or long over). Spent (it ran dry at about 4 s), it
  // recovers at spent_recover_rate; rested (at rested_at, 15 s later), at recover_rate. 1e-9: 480 ticks' sum.
  EXPECT_FALSE(stamina_can_punch(s));
  const double at10 = s.level;
  for (int i = 0; i < 480; ++i) step_world(w);  // 2 s
  EXPECT_NEAR(s.level, at10 + 480 * kPhysicsDt * t.spent_recover_rate, 1e-9);
  while (!stamina_can_punch(s)) step_world(w);
  EXPECT_NEAR(s.level, t.rested_at, t.spent_recover_rate * kPhysicsDt + 1e-12);  // crossed within one tick
  const double rested = s.level;
  for (int i = 0; i < 480; ++i) step_world(w);  // 2 s
  EXPECT_NEAR(s.level, rested + 480 * kPhysicsDt * t.recover_rate, 1e-9);
  EXPECT_EQ(mt.fighter[0].thrown, punches);  // no punch since
}

}  // namespace
}  // namespace boxing
