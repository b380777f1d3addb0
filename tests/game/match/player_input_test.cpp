// Every press accounted for (game/match/player_input.h, issue 65 item 1), headless through --input files: a fight key
// pressed while the boxer is free starts its motion on the physics tick after the press; pressed during a punch it is
// buffered or refused with a reason; none is ever dropped unseen (the report's match.player_inputs).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "engine/anim/motion_graph.h"
#include "game/interaction/input_events.h"
#include "game/match/match.h"
#include "game/match/match_report.h"
#include "game/world.h"
#include "test_paths.h"

namespace boxing {
namespace {

// An --input file of fight keys for boxer 0 (t, action), plus extra raw events (e.g. blue handed to an idle player).
std::string write_keys(const std::string& name, const std::vector<std::pair<double, std::string>>& keys,
                       const std::string& extra = "") {
  const std::string path = std::string(BOXING_BINARY_DIR) + "/" + name + ".json";
  std::ofstream out(path);
  out << "{\"events\": [" << extra;
  bool first = extra.empty();
  for (const auto& [t, action] : keys) {
    out << (first ? "" : ",") << "{\"t\": " << t << ", \"key\": {\"action\": \"" << action << "\", \"boxer\": 0}}";
    first = false;
  }
  out << "]}\n";
  return path;
}

std::unique_ptr<World> world_with_input(uint64_t seed, const std::string& input) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.scenario = "match";
  o.seed = seed;
  o.player = 0;
  o.start_apart = 1.0;  // m: at punching range (the walk in from the marks is not what these tests are about)
  o.input = input;
  auto w = make_world(o);
  return w ? std::move(*w) : nullptr;
}

void run_until(World& w, double t) {
  while (w.data.time < t - 1e-9) step_world(w);
}

bool is_punch_action(FightCommand c) { return c >= FightCommand::Jab && c <= FightCommand::RearUppercut; }

// Red presses five different punches, each when in guard with nothing under way (2 s apart: a punch and its return to
// guard take under 1 s); blue is handed to an idle player (no hit can make red "hurt"). Each starts on the tick after
// its press: the press's tick's control drives the punch's clip (forced from guard) and the punch's event opens at the
// end of that tick, 1/240 s after the press. Before, a request waited for the graph's next transition point (~0.3 s).
TEST(PlayerInput, APressWhenFreeStartsItsPunchOnTheNextTick) {
  const std::vector<std::pair<double, std::string>> keys = {
      {2.0, "jab"}, {4.0, "cross"}, {6.0, "lead_hook"}, {8.0, "rear_uppercut"}, {10.0, "rear_hook"}};
  auto w = world_with_input(3, write_keys("player_input_free", keys,
                                          "{\"t\": 0, \"set\": {\"boxer\": 1, \"control\": \"player\"}}"));
  ASSERT_TRUE(w);
  World& world = *w;
  run_until(world, 11.5);
  const Match& mt = *world.match;
  ASSERT_EQ(mt.presses.size(), keys.size());
  std::vector<const PunchEvent*> red;
  for (const PunchEvent& e : mt.events)
    if (e.boxer == 0) red.push_back(&e);
  ASSERT_EQ(red.size(), keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    const PlayerPress& p = mt.presses[i];
    SCOPED_TRACE(keys[i].second);
    EXPECT_EQ(p.waited, PressWait::Free);
    EXPECT_EQ(p.refused, nullptr);
    // The event's time is the press's tick (events are applied at the first tick at or after their t).
    EXPECT_NEAR(p.t_pressed, keys[i].first, kPhysicsDt);
    // One tick exactly (a tick is 1/240 s; 1e-9 s: the clock's sum of 1/240 steps).
    EXPECT_NEAR(p.t_started - p.t_pressed, kPhysicsDt, 1e-9);
    EXPECT_EQ(red[i]->punch, keys[i].second);
    EXPECT_NEAR(red[i]->t, p.t_started, 1e-9);  // the fight saw the punch start then
  }
  const nlohmann::json r = match_report(world);
  ASSERT_EQ(r["player_inputs"].size(), keys.size());
  EXPECT_EQ(r["player_inputs"][0]["action"], "jab");
  EXPECT_EQ(r["player_inputs"][0]["waited"], "free");
  EXPECT_TRUE(r["player_inputs"][0].contains("t_started"));
}

// A scripted session: three keys a second for 180 s (540 presses), every key in turn (punches, defences, steps), against
// the normal AI. Every press is in the log: started (its motion under way, a punch's event opened at that moment), or
// refused with one of the reasons the HUD shows; only a press in the run's last second may still be waiting. The
// report's player_inputs holds them all.
TEST(PlayerInput, ThreeKeysASecondFor180SecondsLoseNoPressSilently) {
  std::vector<std::pair<double, std::string>> keys;
  for (int i = 0; i < 540; ++i) keys.push_back({0.5 + i / 3.0, kKeyActions[i % kKeyActionCount]});
  auto w = world_with_input(2, write_keys("player_input_session", keys));
  ASSERT_TRUE(w);
  World& world = *w;
  run_until(world, 180.5);
  const Match& mt = *world.match;
  ASSERT_EQ(mt.presses.size(), keys.size());  // every key event reached the match
  const std::set<std::string> reasons = {"tired", "hurt", "down", "busy", "rest", "over", "neutral corner",
                                         "off balance"};
  int started = 0, refused = 0, pending = 0, free_started = 0;
  std::multiset<double> red_punches;
  for (const PunchEvent& e : mt.events)
    if (e.boxer == 0) red_punches.insert(e.t);
  int punch_starts = 0;
  for (const PlayerPress& p : mt.presses) {
    if (p.t_started >= 0.0) {
      ++started;
      EXPECT_GE(p.t_started, p.t_pressed + kPhysicsDt - 1e-9);
      if (p.waited == PressWait::Free) {
        ++free_started;
        EXPECT_NEAR(p.t_started - p.t_pressed, kPhysicsDt, 1e-9);
      }
      if (is_punch_action(p.action)) {
        ++punch_starts;
        // Its punch opened an event at its start (1e-9 s: the clock's sum).
        const auto it = red_punches.lower_bound(p.t_started - 1e-9);
        EXPECT_TRUE(it != red_punches.end() && *it < p.t_started + 1e-9) << "a started punch the fight did not see";
      }
    } else if (p.refused) {
      ++refused;
      EXPECT_TRUE(reasons.count(p.refused)) << p.refused;
    } else {
      ++pending;
      EXPECT_GT(p.t_pressed, world.data.time - 1.0) << "a press left waiting";
    }
  }
  EXPECT_EQ(started + refused + pending, 540);
  EXPECT_EQ(punch_starts, static_cast<int>(red_punches.size()));  // no punch of red's but the keys'
  EXPECT_GT(free_started, 0);
  EXPECT_GT(started, 100);  // the session did fight: a third of the keys or more (measured: see docs/guide/controls.md)
  const nlohmann::json r = match_report(world);
  ASSERT_EQ(r["player_inputs"].size(), 540u);
  for (const auto& p : r["player_inputs"])
    EXPECT_EQ(p.contains("t_started") + p.contains("refused") + p.contains("pending"), 1) << p.dump();
  std::printf("presses 540: started %d (free %d), refused %d, pending %d\n", started, free_started, refused, pending);
}

// A press while a punch plays is buffered (two at most) and starts once the boxer is back in guard, in order; a third
// during the same punch is refused "busy", and the HUD shows the reason for a second.
TEST(PlayerInput, PressesDuringAPunchAreBufferedTwoDeepThenRefusedBusy) {
  auto w = world_with_input(3, write_keys("player_input_buffer", {}, "{\"t\": 0, \"set\": {\"boxer\": 1, \"control\": \"player\"}}"));
  ASSERT_TRUE(w);
  World& world = *w;
  run_until(world, 2.0);
  match_command(world, 0, FightCommand::Jab);
  step_world(world);
  step_world(world);  // the jab plays
  for (FightCommand c : {FightCommand::Cross, FightCommand::LeadHook, FightCommand::Jab}) match_command(world, 0, c);
  const Match& mt = *world.match;
  ASSERT_EQ(mt.presses.size(), 4u);
  EXPECT_EQ(mt.presses[0].waited, PressWait::Free);
  EXPECT_EQ(mt.presses[1].waited, PressWait::Buffered);
  EXPECT_EQ(mt.presses[2].waited, PressWait::Buffered);
  ASSERT_NE(mt.presses[3].refused, nullptr);
  EXPECT_STREQ(mt.presses[3].refused, "busy");
  EXPECT_STREQ(player_notice(world, 0), "busy");
  EXPECT_EQ(match_hud(world).side[0].notice, "busy");
  run_until(world, 6.0);
  EXPECT_STREQ(player_notice(world, 0), "");  // shown for notice_seconds (1 s)
  EXPECT_GT(mt.presses[1].t_started, mt.presses[0].t_started);
  EXPECT_GT(mt.presses[2].t_started, mt.presses[1].t_started);
  std::vector<std::string> red;
  for (const PunchEvent& e : mt.events)
    if (e.boxer == 0) red.push_back(e.punch);
  EXPECT_EQ(red, (std::vector<std::string>{"jab", "cross", "lead_hook"}));
}

}  // namespace
}  // namespace boxing
