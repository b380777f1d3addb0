// Two players on one keyboard, in the window (issue 65): `--mode versus` under an X server of its own, xdotool typing
// on both halves of the keyboard (game/interaction/fight_keys.h), the Shift combinations with the left and the right
// Shift. The recording (--record) says which boxer each key went to: the left half's to red, the right half's to blue,
// each in the order typed; both boxers threw punches (no AI in versus: only the keys could). The pause menu with its
// controls table is left in <build>/two_players_window_test/pause.png to look at.
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

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return in.good() ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
}

}  // namespace

TEST(TwoPlayersWindow, EachHalfOfTheKeyboardDrivesItsOwnBoxer) {
  BOXING_REQUIRE_DISPLAY_AND_XDOTOOL();
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)
    BOXING_SKIP_OR_FAIL("xvfb-run missing: scripts/deps installs it (apt-get install xvfb)");
  boxing_test::pin_lavapipe_env();
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/two_players_window_test";
  std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str());
  const std::string report = dir + "/report.json", record = dir + "/record.json";
  // The pairs 1 s apart (a punch's clip and its return to guard take about that: the next press would wait in the
  // buffer, which is not what this test is about). The window closes itself after 16 simulated seconds.
  const std::string body = std::string("set -u\n") +
      "(timeout 120 " + BOXING_BINARY_DIR + "/boxing --mode versus --seed 3 --seconds 16 --no-vsync --width 1280 "
      "--height 720 --record " + record + " --report " + report + " >" + dir + "/game.log 2>&1 &)\n"
      "win=$(timeout 60 xdotool search --sync --onlyvisible --name 'Boxing - versus \\(seed 3\\)' | head -1)\n"
      "timeout 10 xdotool windowfocus $win; sleep 2\n"
      "k() { xdotool key --window $win \"$@\"; sleep 1.0; }\n"
      "k r; k j; k f; k k\n"                       // P1 jab, P2 jab, P1 cross, P2 cross
      "k shift+a; k Shift_R+Left\n"               // P1 slip left, P2 slip left
      "k w; k Up\n"                               // P1 step in, P2 step in
      "k v; k i\n"                                // P1 lead hook, P2 rear hook
      "xdotool key --window $win Escape; sleep 1.5; import -window $win " + dir + "/pause.png\n"
      "xdotool key --window $win Escape; sleep 0.5\n"
      "for i in $(seq 1 150); do [ -s " + report + " ] && break; sleep 0.3; done";
  const std::string script = dir + "/session.sh";
  std::ofstream(script) << body << "\n";
  ASSERT_EQ(std::system(("xvfb-run -a -s '-screen 0 1280x720x24' bash " + script).c_str()), 0);
  const nlohmann::json r = read_json(report);
  ASSERT_TRUE(r.is_object()) << "the game wrote no report";
  const nlohmann::json rec = read_json(record);
  ASSERT_TRUE(rec.is_object()) << "the game wrote no recording";
  std::vector<std::string> red, blue;
  for (const auto& e : rec["events"])
    if (e.contains("key")) (e["key"]["boxer"] == 0 ? red : blue).push_back(e["key"]["action"]);
  const std::vector<std::string> p1 = {"jab", "cross", "slip_left", "step_forward", "lead_hook"};
  const std::vector<std::string> p2 = {"jab", "cross", "slip_left", "step_forward", "rear_hook"};
  EXPECT_EQ(red, p1) << rec.dump();
  EXPECT_EQ(blue, p2) << rec.dump();
  const nlohmann::json& m = r["match"];
  EXPECT_EQ(m["players"], nlohmann::json::array({true, true}));
  // The jabs, crosses and hooks: each boxer threw at least two of its three (one may land while the boxer is still
  // moving from the slip or the step, and wait or be refused; the AI throws nothing in versus).
  EXPECT_GE(m["punches_thrown"][0].get<int>(), 2) << m.dump();
  EXPECT_GE(m["punches_thrown"][1].get<int>(), 2) << m.dump();
  const auto log = r["front_end"]["log"].get<std::vector<std::string>>();
  EXPECT_NE(std::find(log.begin(), log.end(), "paused"), log.end()) << r["front_end"].dump();
}
