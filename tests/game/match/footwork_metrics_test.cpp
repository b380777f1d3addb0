// The match's footwork as measured (game/match/footwork_metrics.h): present and sane in the report of a short match.
#include <gtest/gtest.h>

#include "game/match/match.h"
#include "game/world.h"

using namespace boxing;

TEST(MatchFootwork, ReportHasTheFootworkFieldsAndTheyAreSane) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.scenario = "match";
  o.seed = 3;
  auto made = make_world(o);
  ASSERT_TRUE(made) << made.error();
  World& w = **made;
  const double seconds = 20.0;
  for (int i = 0; i < static_cast<int>(seconds * 240); ++i) step_world(w);
  const nlohmann::json m = match_report(w);
  ASSERT_TRUE(m.contains("teleports"));
  EXPECT_GE(m["teleports"].get<int>(), 0);
  EXPECT_EQ(m["teleports"].get<int>(), 0);  // nobody is set anywhere (the referee's marks are gone)
  ASSERT_EQ(m["fighters"].size(), 2u);
  for (const auto& f : m["fighters"]) {
    EXPECT_GE(f["steps"].get<int>(), 0);
    EXPECT_GT(f["path_m"].get<double>(), 0.0);
    EXPECT_LT(f["path_m"].get<double>(), 3.0 * seconds);  // no faster than a run on average
    EXPECT_GE(f["standing_s"].get<double>(), 0.0);
    EXPECT_LE(f["standing_s"].get<double>(), seconds + 1e-6);
    EXPECT_LE(f["time_in_range_s"].get<double>(), f["standing_s"].get<double>() + 1e-9);
    EXPECT_LE(f["legs_through_s"].get<double>(), f["standing_s"].get<double>() + 1e-9);
    EXPECT_GE(f["steps_per_minute_standing"].get<double>(), 0.0);
    EXPECT_GE(f["ring_exits"].get<int>(), f["ring_exits_after_hit"].get<int>());
    EXPECT_GE(f["rope_contacts_s"].get<double>(), 0.0);
  }
  for (const auto& g : m["getups"])
    if (!g["count_distance_min_m"].is_null()) {
      EXPECT_GE(g["count_distance_min_m"].get<double>(), 0.0);
    }
}

// The teleport detector sees a pose set directly: a boxer moved 1 m by set_character_pose mid-match counts once (a
// pelvis jump no velocity explains, footwork_metrics.h), and its path is not carried across the jump.
TEST(MatchFootwork, APoseSetDirectlyCountsAsATeleport) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.seed = 3;
  auto made = make_world(o);
  ASSERT_TRUE(made) << made.error();
  World& w = **made;
  for (int i = 0; i < 240; ++i) step_world(w);
  EXPECT_EQ(w.match->teleports, 0);
  const double path_before = w.match->footwork[1].path_m;
  double* q = w.data.q.data() + w.model.bodies[w.boxers[1].bodies.body[0]].q_index;  // the free root's x y z
  q[1] += 1.0;  // 1 m sideways, set directly
  step_world(w);
  EXPECT_EQ(w.match->teleports, 1);
  EXPECT_EQ(w.match->footwork[1].teleports, 1);
  EXPECT_LT(w.match->footwork[1].path_m - path_before, 0.5);  // the 1 m jump is not in the path
}

// The clinch's clock (game/match/clinch.h): boxers started at their marks (2.8 m apart) are not locked in the first
// second; boxers started chest to chest (0.4 m) are, every tick they both stand in it, and the longest lock is no
// longer than the time locked in all.
TEST(MatchFootwork, TheClinchClockRunsOnlyWhileTheBoxersStandLocked) {
  for (const double apart : {2.8, 0.4}) {
    Options o;
    o.headless = true;
    o.scenario_id = Scenario::Match;
    o.seed = 3;
    o.start_apart = apart;
    auto made = make_world(o);
    ASSERT_TRUE(made) << made.error();
    World& w = **made;
    for (int i = 0; i < 120; ++i) step_world(w);  // 0.5 s: before either boxer's first punch or step (1 s in)
    const ClinchMetrics& c = w.match->clinch;
    EXPECT_LE(c.longest_s, c.locked_s + 1e-12);
    if (apart > 2.0) {
      EXPECT_EQ(c.locked_s, 0.0);
    } else {
      EXPECT_NEAR(c.locked_s, 0.5, kPhysicsDt + 1e-9);  // every tick of the half second (both stand from the start)
      EXPECT_NEAR(c.longest_s, c.locked_s, 1e-12);
    }
    EXPECT_GE(match_report(w)["clinch"]["locked_s"].get<double>(), 0.0);
  }
}
