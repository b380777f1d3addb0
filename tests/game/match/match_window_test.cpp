// The match as a person plays it: the window build under the X server (scripts/test runs the suite in Xvfb), the red
// boxer the player's (--player 0: the AI never punches for it), fight keys pressed with xdotool (J jab, K cross): the
// player's punches are thrown.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/platform/window.h"
#include "support/vulkan_test_env.h"
#include "test_paths.h"

TEST(MatchWindow, FightKeysThrowThePlayersPunches) {
  if (!eng::platform::display_available()) GTEST_SKIP() << "no display (run under xvfb-run to exercise this)";
  if (std::system("command -v xdotool >/dev/null 2>&1") != 0) GTEST_SKIP() << "xdotool missing (scripts/deps installs it)";
  boxing_test::pin_lavapipe_env();
  const std::string report = std::string(BOXING_BINARY_DIR) + "/match_window_test.json";
  std::remove(report.c_str());
  // The game in the background; once its window is mapped, focus it and press the keys a second apart.
  const std::string cmd =
      "(timeout 120 " + std::string(BOXING_BINARY_DIR) + "/boxing --scenario match --player 0 --seed 3 --seconds 8 --no-vsync " +
      "--width 640 --height 360 --report " + report + " >/dev/null 2>&1 &) ; "
      "win=$(timeout 60 xdotool search --sync --onlyvisible --name 'Boxing - match' | head -1) && "
      "timeout 10 xdotool windowfocus $win && sleep 1.5 && "
      "xdotool key --window $win j && sleep 1.2 && xdotool key --window $win k && sleep 1.2 && "
      "xdotool key --window $win j; "
      "for i in $(seq 1 240); do [ -s " + report + " ] && break; sleep 0.5; done";
  // As a script file: through std::system's sh -c, $(...) and $win would be expanded before the game starts.
  const std::string script = std::string(BOXING_BINARY_DIR) + "/match_window_test.sh";
  std::ofstream(script) << cmd << "\n";
  ASSERT_EQ(std::system(("bash " + script).c_str()), 0);
  std::ifstream in(report);
  ASSERT_TRUE(in.good()) << "the game wrote no report";
  const nlohmann::json r = nlohmann::json::parse(in);
  const auto& m = r["match"];
  EXPECT_TRUE(m["players"][0].get<bool>());
  EXPECT_FALSE(m["players"][1].get<bool>());  // blue stays with the AI
  EXPECT_GE(m["player_commands_taken"][0].get<int>(), 2);
  int jabs = 0, crosses = 0;
  for (const auto& e : m["events"])
    if (e["boxer"] == 0) (e["punch"] == "jab" ? jabs : crosses) += e["punch"] == "jab" || e["punch"] == "cross";
  // Of the three keyed punches at least two are thrown (a hit on the player's boxer between the key and the punch's
  // start forces a reaction clip instead: the timing depends on the machine's load, the window's frames). Seed 3: the
  // AI lands nothing on an idle player's boxer in the first 8 s (seed 1's jab at 1.7 s ate the first key under load).
  EXPECT_GE(jabs, 1) << m["events"].dump();
  EXPECT_GE(jabs + crosses, 2) << m["events"].dump();
}
