// The front end as a person uses it: the window build under the X server (scripts/test runs the suite in Xvfb),
// xdotool's keys and clicks, each test on an X server of its own (xvfb-run). What each key and menu did comes back in the report's front_end block (its log, in
// order, and the state at the close); the window's title names the screen, so the script waits on it rather than
// on the clock (game/app.cpp window_title).
//
// 1. The keys after the panel was clicked (issue 64): Tab, H, P, '.', '[' and Esc each take effect with the physics
//    panel clicked (a slider, a checkbox), and a text field the player clicked (the seed) takes the keys only while
//    it is being edited.
// 2. A newcomer's path: the title, the AI level set to easy with the arrows, Play vs AI, three short rounds fought
//    with the fight keys, the result screen, back to the title, quit. Screenshots of the title, the HUD and the result
//    are left in <build>/front_end_window_test/ to look at.
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

// Each test runs its session on an X server of its own (run_script): xvfb-run must be there (scripts/deps: xvfb).
#define REQUIRE_XVFB_RUN()                                                                         \
  do {                                                                                             \
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0)                                   \
      BOXING_SKIP_OR_FAIL("xvfb-run missing: scripts/deps installs it (apt-get install xvfb)");    \
  } while (0)

std::string fresh_dir(const std::string& name) {
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/" + name;
  std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str());
  return dir;
}

// Runs a bash script (as a file: through std::system's sh -c, $(...) and $win would be expanded too early) on an X
// server of its own: the other window tests' real pointer clicks (ctest runs them side by side on the suite's Xvfb)
// landed on this game's menus, and ours on theirs.
int run_script(const std::string& dir, const std::string& body) {
  const std::string script = dir + "/session.sh";
  std::ofstream(script) << "set -u\n" << body << "\n";
  return std::system(("xvfb-run -a -s '-screen 0 1280x720x24' bash " + script).c_str());
}

// Shell helpers for the scripts: a click (press and release a frame apart or more: ImGui 1.86 reads the button's
// state once a frame), a key held long enough for ImGui's own key snapshot, and a wait for the window's title.
const char* kHelpers = R"sh(
click() { xdotool mousemove --window $win $1 $2 && sleep 0.3 && xdotool mousedown 1 && sleep 0.3 && xdotool mouseup 1 && sleep 0.4; }
key() { xdotool key --window $win "$@" && sleep 0.5; }
hold() { xdotool keydown --window $win $1 && sleep 0.3 && xdotool keyup --window $win $1 && sleep 0.4; }
wait_title() { for i in $(seq 1 $2); do [ "$(xdotool getwindowname $win)" = "$1" ] && return 0; sleep 0.3; done; return 1; }
)sh";

}  // namespace

TEST(FrontEndWindow, TabHPAndEscWorkAfterThePanelWasClickedAndATextFieldTakesKeysOnlyWhileEdited) {
  BOXING_REQUIRE_DISPLAY_AND_XDOTOOL();
  REQUIRE_XVFB_RUN();
  boxing_test::pin_lavapipe_env();
  const std::string dir = fresh_dir("front_end_keys_test");
  const std::string report = dir + "/report.json";
  // The sandbox (two boxers in guard), 1280 x 720: the panel's widgets at fixed places (340 px wide, 10 px from the
  // top-right corner; the layout of tests/game/interaction/hands_window_test.cpp): boxer 0's gain slider at
  // (1013, 87), the ghost checkbox at (947, 272), the seed field at (960, 391).
  const std::string body = std::string(kHelpers) +
      "(timeout 120 " + BOXING_BINARY_DIR + "/boxing --mode sandbox --seed 7 --no-vsync --width 1280 --height 720 "
      "--report " + report + " >" + dir + "/game.log 2>&1 &)\n"
      "win=$(timeout 60 xdotool search --sync --onlyvisible --name 'Boxing - sandbox \\(seed 7\\)' | head -1)\n"
      "timeout 10 xdotool windowfocus $win; sleep 2\n"
      "key Tab\n"                        // the panel opens
      "click 1013 87\n"                  // the panel clicked: boxer 0's gain slider
      "key Tab\n"                        // closes it
      "key Tab\n"                        // opens it again
      "click 947 272\n"                  // clicked again: the ghost checkbox
      "key h; key p; key period; key bracketleft\n"
      "key Escape\n"                     // the pause menu
      "wait_title 'Boxing - sandbox (seed 7) - paused' 20 && key Escape\n"  // resumed
      "click 960 391\n"                  // the seed's text field: now it has the keys
      "key p\n"                          // typed into the field (an integer field drops the letter): no pause toggle
      "hold Return\n"                    // the edit ends: the keys are the game's again
      "key p\n"                          // the physics runs again
      "key Escape; key Down; key Down; key Return\n"  // the menu's "quit to title"
      "wait_title 'Boxing - title (seed 7)' 20 && key Escape\n"  // quits
      "for i in $(seq 1 100); do [ -s " + report + " ] && break; sleep 0.3; done";
  ASSERT_EQ(run_script(dir, body), 0);
  const nlohmann::json r = read_json(report);
  ASSERT_TRUE(r.is_object()) << "the game wrote no report";
  const nlohmann::json& fe = r["front_end"];
  const std::vector<std::string> expected = {
      "panel open",  "panel closed", "panel open", "debug overlay on", "physics paused", "one frame", "time 1/2",
      "paused",      "playing",      "physics running", "paused", "title", "quit"};
  EXPECT_EQ(fe["log"].get<std::vector<std::string>>(), expected) << fe.dump();
  EXPECT_EQ(fe["screen"], "title");
  EXPECT_TRUE(fe["panel_open"].get<bool>());
  EXPECT_TRUE(fe["debug_overlay"].get<bool>());
  EXPECT_FALSE(fe["physics_paused"].get<bool>());
  EXPECT_EQ(fe["time_scale"], "1/2");
}

TEST(FrontEndWindow, ANewcomerPlaysThreeRoundsFromTheTitleToTheResultAndBack) {
  BOXING_REQUIRE_DISPLAY_AND_XDOTOOL();
  REQUIRE_XVFB_RUN();
  boxing_test::pin_lavapipe_env();
  const std::string dir = fresh_dir("front_end_window_test");
  const std::string report = dir + "/report.json";
  // Three 5 s rounds with 2 s rests: 19 s of fight, the result 3 s after the last bell.
  const std::string body = std::string(kHelpers) +
      "(timeout 150 " + BOXING_BINARY_DIR + "/boxing --seed 11 --rounds 3 --round-seconds 5 --rest-seconds 2 "
      "--no-vsync --width 960 --height 540 --report " + report + " >" + dir + "/game.log 2>&1 &)\n"
      "win=$(timeout 60 xdotool search --sync --onlyvisible --name 'Boxing - title \\(seed 11\\)' | head -1)\n"
      "timeout 10 xdotool windowfocus $win; sleep 2\n"
      "import -window $win " + dir + "/title.png\n"
      "key Down; key Down; key Down; key Left\n"  // PLAY VS AI -> TWO PLAYERS -> SANDBOX -> AI LEVEL: easy
      "key Up; key Up; key Up; key Return\n"      // back to PLAY VS AI, start
      "wait_title 'Boxing - play (seed 11)' 40\n"
      "n=0; while ! xdotool getwindowname $win | grep -qF ' - result'; do\n"
      "  n=$((n + 1)); [ $n -gt 120 ] && break\n"
      "  xdotool key --window $win j; sleep 0.35; xdotool key --window $win k; sleep 0.35\n"
      "  [ $n -eq 6 ] && import -window $win " + dir + "/hud.png\n"
      "done\n"
      "sleep 0.5; import -window $win " + dir + "/result.png\n"
      "key Return\n"
      "wait_title 'Boxing - title (seed 11)' 20 && key Escape\n"
      "for i in $(seq 1 100); do [ -s " + report + " ] && break; sleep 0.3; done";
  ASSERT_EQ(run_script(dir, body), 0);
  const nlohmann::json r = read_json(report);
  ASSERT_TRUE(r.is_object()) << "the game wrote no report";
  const nlohmann::json& fe = r["front_end"];
  EXPECT_EQ(fe["log"].get<std::vector<std::string>>(), (std::vector<std::string>{"start play", "result", "title", "quit"}))
      << fe.dump();
  const nlohmann::json& m = r["match"];
  EXPECT_EQ(r["seed"], 11);
  EXPECT_EQ(m["ai"], nlohmann::json::array({"easy", "easy"}));  // the title's AI level
  EXPECT_TRUE(m["players"][0].get<bool>());                   // red is the player's
  EXPECT_FALSE(m["players"][1].get<bool>());
  EXPECT_GT(m["player_commands_taken"][0].get<int>(), 3) << "the fight keys threw red's punches";
  EXPECT_TRUE(m["result"]["finished"].get<bool>()) << m["result"].dump();
  // Three rounds fought to the last bell, or fewer if one ended in a knockout.
  const std::string method = m["result"]["method"];
  if (method == "decision" || method == "draw") EXPECT_EQ(m["rounds"].size(), 3u) << m["rounds"].dump();
  else EXPECT_TRUE(method == "ko" || method == "tko") << method;
}
