// The match as a person plays it: the window build under the X server (scripts/test runs the suite in Xvfb), the red
// boxer the player's (--player 0: the AI never punches for it), fight keys pressed with xdotool (J jab, K cross): each
// key is taken and throws its own punch. The blue boxer is handed to the player too (an input file's set event at
// t = 0) and so stands in guard throwing nothing: no hit on red can force a reaction clip over a keyed punch, so every
// key's effect is certain whatever the machine's load (with blue's AI on, a hit between the key and the punch's start
// ate a keyed punch now and then, and the test could only ask for "two of three").
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/vulkan_test_env.h"
#include "support/window_test_env.h"
#include "test_paths.h"

namespace {

struct WindowSession {
  nlohmann::json report, recording;
};

// The game in the background in `dir` (a match, red the player's: `args` adds to it); once its window is mapped, it
// is focused and `keys` (xdotool commands on $win) run; then the run's report and its --record recording are read.
WindowSession play_window_session(const std::string& dir, const std::string& args, const std::string& keys) {
  const std::string report = dir + "/report.json", record = dir + "/keys.json";
  const std::string cmd =
      "(timeout 120 " + std::string(BOXING_BINARY_DIR) + "/boxing --scenario match --player 0 --seed 3 --no-vsync " +
      "--width 640 --height 360 " + args + " --record " + record + " --report " + report + " >/dev/null 2>&1 &) ; "
      "win=$(timeout 60 xdotool search --sync --onlyvisible --name 'Boxing - match' | head -1) && "
      "timeout 10 xdotool windowfocus $win && sleep 1.5 && " + keys + "; "
      "for i in $(seq 1 240); do [ -s " + report + " ] && break; sleep 0.5; done";
  // As a script file: through std::system's sh -c, $(...) and $win would be expanded before the game starts.
  const std::string script = dir + "/session.sh";
  std::ofstream(script) << cmd << "\n";
  WindowSession out;
  EXPECT_EQ(std::system(("bash " + script).c_str()), 0);
  std::ifstream in(report);
  EXPECT_TRUE(in.good()) << "the game wrote no report";
  if (in.good()) out.report = nlohmann::json::parse(in, nullptr, false);
  std::ifstream rin(record);
  EXPECT_TRUE(rin.good()) << "the game wrote no recording";
  if (rin.good()) out.recording = nlohmann::json::parse(rin, nullptr, false);
  return out;
}

}  // namespace

TEST(MatchWindow, FightKeysThrowThePlayersPunches) {
  BOXING_REQUIRE_DISPLAY_AND_XDOTOOL();
  boxing_test::pin_lavapipe_env();
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/match_window_test";
  const std::string input = dir + "/blue_idle.json";
  std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str());
  std::ofstream(input) << R"({"events": [{"t": 0, "set": {"boxer": 1, "control": "player"}}]})" << "\n";
  // Keys a second apart.
  const WindowSession session = play_window_session(dir, "--seconds 8 --input " + input,
      "xdotool key --window $win j && sleep 1.2 && xdotool key --window $win k && sleep 1.2 && "
      "xdotool key --window $win j");
  ASSERT_FALSE(session.report.is_discarded() || session.report.is_null());
  ASSERT_FALSE(session.recording.is_discarded() || session.recording.is_null());
  const nlohmann::json& r = session.report;
  const auto& m = r["match"];
  EXPECT_TRUE(m["players"][0].get<bool>());
  EXPECT_TRUE(m["players"][1].get<bool>());  // blue handed to the (idle) player by the input file
  // Each key became its own fight-key event, in the order pressed (the recording holds every input event applied).
  const nlohmann::json& rec = session.recording;
  std::vector<std::string> keys;
  for (const auto& e : rec["events"])
    if (e.contains("key")) {
      EXPECT_EQ(e["key"]["boxer"], 0) << e.dump();
      keys.push_back(e["key"]["action"].get<std::string>());
    }
  EXPECT_EQ(keys, (std::vector<std::string>{"jab", "cross", "jab"})) << rec.dump();
  // ... each was taken by red's motion graph and threw that punch: J twice a jab, K once a cross, nothing else.
  EXPECT_EQ(m["player_commands_taken"][0].get<int>(), 3);
  EXPECT_EQ(m["player_commands_taken"][1].get<int>(), 0);
  std::vector<std::string> red, blue;
  for (const auto& e : m["events"]) (e["boxer"] == 0 ? red : blue).push_back(e["punch"].get<std::string>());
  EXPECT_EQ(red, (std::vector<std::string>{"jab", "cross", "jab"})) << m["events"].dump();
  EXPECT_TRUE(blue.empty()) << m["events"].dump();
}

// Every press accounted for in the window (player_input.h): the player mashes J and K (ten keys 0.15 s apart, faster
// than punches play), then presses four keys 0.4 s apart, against blue's AI. Every key xdotool pressed reached the
// match (the recording's key events) and each is in the report's player_inputs: started, or refused with its reason
// (busy, hurt, tired, ...); none is left waiting or missing, and a press taken while free started on the next tick.
TEST(MatchWindow, EveryKeyPressIsStartedOrRefusedWithAReason) {
  BOXING_REQUIRE_DISPLAY_AND_XDOTOOL();
  boxing_test::pin_lavapipe_env();
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/match_window_presses_test";
  std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str());
  const WindowSession session = play_window_session(dir, "--seconds 14 --start-apart 1.0",
      "xdotool key --window $win --delay 150 j j k j k j j k j j && sleep 1.0 && "
      "xdotool key --window $win --delay 400 j k u i");
  ASSERT_FALSE(session.report.is_discarded() || session.report.is_null());
  ASSERT_FALSE(session.recording.is_discarded() || session.recording.is_null());
  const nlohmann::json m = session.report["match"];
  const nlohmann::json& rec = session.recording;
  std::vector<std::string> keys, logged;
  for (const auto& e : rec["events"])
    if (e.contains("key")) keys.push_back(e["key"]["action"].get<std::string>());
  EXPECT_EQ(keys.size(), 14u) << rec.dump();  // every xdotool press became a key event
  int started = 0, refused = 0;
  for (const auto& p : m["player_inputs"]) {
    logged.push_back(p["action"].get<std::string>());
    EXPECT_TRUE(p.contains("t_started") != p.contains("refused")) << p.dump();  // one or the other, never neither
    if (p.contains("t_started")) {
      ++started;
      if (p["waited"] == "free") {
        EXPECT_NEAR(p["t_started"].get<double>() - p["t_pressed"].get<double>(), 1.0 / 240.0, 1e-9) << p.dump();
      }
    } else {
      ++refused;
      EXPECT_FALSE(p["refused"].get<std::string>().empty());
    }
  }
  EXPECT_EQ(logged, keys);  // the same presses, in the same order
  EXPECT_GE(started, 1);
  std::printf("window: %zu presses, %d started, %d refused\n", keys.size(), started, refused);
}
