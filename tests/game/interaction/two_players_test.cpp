// Two players (issue 65): `--mode versus` makes both boxers players'. Headless, a scripted pad fights blue (one pad
// connected: the pad is blue's, the keyboard red's; gamepad.h pad_boxer) and scripted keys fight red, three short
// rounds to a result; --record writes the pad events back out. The window's keyboard halves: two_players_window_test.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/run_boxing.h"
#include "test_paths.h"

namespace {

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return in.good() ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
}

// Red's keys: a punch (or a step in) every 0.5 s. Blue's pad: a face button or bumper pressed every 0.5 s and let go
// 0.2 s later, and every 4 s the left stick held forward for 1 s (a step, then its repeat).
nlohmann::json script(double until) {
  const char* red[] = {"jab", "cross", "step_forward", "lead_hook", "jab", "rear_uppercut", "slip_left", "cross"};
  const char* blue[] = {"x", "y", "x", "a", "b", "left_bumper", "x", "right_bumper"};
  nlohmann::json ev = nlohmann::json::array();
  ev.push_back({{"t", 0.2}, {"pad", {{"pad", 0}}}});  // plugged in, at rest
  int i = 0;
  for (double t = 1.0; t < until; t += 0.5, ++i) {
    ev.push_back({{"t", t}, {"key", {{"action", red[i % 8]}, {"boxer", 0}}}});
    nlohmann::json pad = {{"pad", 0}, {"buttons", {{blue[i % 8], true}}}};
    if (i % 8 == 0) pad["axes"] = {{"left_y", -0.9}};
    ev.push_back({{"t", t + 0.1}, {"pad", pad}});
    nlohmann::json up = {{"pad", 0}};
    if (i % 8 == 0) up["axes"] = {{"left_y", -0.9}};  // the stick still held
    ev.push_back({{"t", t + 0.3}, {"pad", up}});
  }
  return {{"events", ev}};
}

}  // namespace

TEST(TwoPlayers, AScriptedPadAndScriptedKeysFightThreeRoundsToAResult) {
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/two_players_test";
  std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str());
  // Three 20 s rounds, 3 s rests: the last bell at 66 s.
  const double seconds = 68.0;
  std::ofstream(dir + "/input.json") << script(seconds).dump(1);
  const auto run = boxing_test::run_boxing("--headless --mode versus --seed 4 --rounds 3 --round-seconds 20 "
                                           "--rest-seconds 3 --seconds 68 --no-validation --input " + dir +
                                           "/input.json --record " + dir + "/record.json --report " + dir +
                                           "/report.json");
  ASSERT_EQ(run.code, 0) << run.output;
  const nlohmann::json r = read_json(dir + "/report.json");
  ASSERT_TRUE(r.is_object()) << run.output;
  const nlohmann::json& m = r["match"];
  EXPECT_EQ(m["players"], nlohmann::json::array({true, true})) << "versus: both boxers are players', no AI";
  EXPECT_TRUE(m["result"]["finished"].get<bool>()) << m["result"].dump();
  EXPECT_FALSE(m["result_text"].get<std::string>().empty());
  // Both threw punches, and only the players could have: neither boxer has an AI in versus. 8 punch keys and 7 punch
  // buttons in every 8 presses (0.5 s apart) over about 60 s of fighting ask for over 100 each; the floor of 15 is
  // what a motion graph taking one punch a second or so (a punch's clip and its return to guard) still throws when
  // some presses land on a boxer down or between rounds.
  EXPECT_GT(m["punches_thrown"][0].get<int>(), 15) << m["punches_thrown"];
  EXPECT_GT(m["punches_thrown"][1].get<int>(), 15) << m["punches_thrown"];
  // The pad was blue's (the one pad in versus), and it gave its actions: a press every 0.5 s.
  const nlohmann::json& pads = r["interaction"]["pads"];
  ASSERT_EQ(pads.size(), 1u) << r["interaction"].dump();
  EXPECT_EQ(pads[0]["boxer"], 1);
  EXPECT_GT(pads[0]["actions"].get<int>(), 100);
  // --record wrote every pad event back (the world applies and records each): the same count as the script's.
  const nlohmann::json rec = read_json(dir + "/record.json");
  ASSERT_TRUE(rec.is_object());
  int pad_in = 0, pad_out = 0;
  const nlohmann::json in = script(seconds);
  for (const auto& e : in["events"]) pad_in += e.contains("pad");
  for (const auto& e : rec["events"]) pad_out += e.contains("pad");
  EXPECT_EQ(pad_out, pad_in);
}
