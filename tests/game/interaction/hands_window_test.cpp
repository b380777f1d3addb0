// The player's hands as a person uses them: the window build under the X server (scripts/test runs the suite in
// Xvfb), xdotool's mouse and keys. A left-drag from boxer 0's head pulls the head toward the cursor (the physics
// state in the report, not pixels) and the boxer recovers after the release; T throws a beach ball at the cursor that
// hits boxer 1; Tab opens the panel and clicks on it switch boxer 0's servo to person space (its combo) and boxer 1 to the PD balance
// (a radio button), and F2 steps boxer 1's servo. The session's recording (--record) played back headless gives the same run, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "game/cli.h"
#include "game/interaction/mouse_hands.h"
#include "game/scene_view.h"
#include "game/world.h"
#include "support/vulkan_test_env.h"
#include "support/window_test_env.h"
#include "test_paths.h"

namespace {
nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return in.good() ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
}
// The pixel (1280 x 720, side camera) of a boxer's bone after `t` seconds of the stand scenario, seed 1.
void pixel_of(int boxer, const char* bone, double t, int& px, int& py) {
  auto o = boxing::parse_cli({"--scenario", "stand", "--seed", "1"});
  auto w = boxing::make_world(*o);
  while ((*w)->data.time < t) boxing::step_world(**w);
  const int body = (*w)->boxers[boxer].bodies.body[(*w)->boxer_desc.skeleton.find(bone)];
  double x, y;
  boxing::world_to_pixel(boxing::camera_preset("side", **w), (*w)->data.com_world[body], 1280, 720, x, y);
  px = int(std::lround(x)), py = int(std::lround(y));
}
}  // namespace

TEST(HandsWindow, DragThrowAndPanelClickAsAPersonAndTheRecordingReplaysBitForBit) {
  BOXING_REQUIRE_DISPLAY_AND_XDOTOOL();
  boxing_test::pin_lavapipe_env();
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/hands_window_test";
  const std::string report = dir + "/window.json", record = dir + "/session.json", replay = dir + "/replay.json";
  std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str());
  int hx, hy, cx, cy;
  pixel_of(0, "head", 1.0, hx, hy);
  pixel_of(1, "chest", 1.0, cx, cy);
  const std::string exe = std::string(BOXING_BINARY_DIR) + "/boxing";
  const std::string W = "--window $win ";
  std::string cmd =
      "(timeout 150 " + exe + " --scenario stand --seed 1 --seconds 20 --no-vsync --camera side --width 1280 "
      "--height 720 --report " + report + " --record " + record + " >/dev/null 2>&1 &) ; "
      "win=$(timeout 60 xdotool search --sync --onlyvisible --name 'Boxing - stand' | head -1) && "
      "timeout 10 xdotool windowfocus $win && sleep 2 && "
      // the drag: press on the head, move 70 px right (0.34 m at the head) in steps, hold, release
      "xdotool mousemove " + W + std::to_string(hx) + " " + std::to_string(hy) + " && sleep 0.4 && xdotool mousedown 1 && ";
  for (int i = 1; i <= 14; ++i)
    cmd += "sleep 0.07 && xdotool mousemove " + W + std::to_string(hx + 5 * i) + " " + std::to_string(hy) + " && ";
  cmd += "sleep 1.2 && xdotool mouseup 1 && sleep 1 && "
         // the throw: the cursor on boxer 1's chest, T
         "xdotool mousemove " + W + std::to_string(cx) + " " + std::to_string(cy) + " && sleep 0.4 && "
         "xdotool key " + W + "t && sleep 1.5 && "
         // the panel (its top-right corner is fixed: 340 px wide, 10 px from the edges), opened with Tab (hidden at the
         // start): boxer 0's servo combo opened, "person" chosen in its list; boxer 1's PD radio
         "xdotool key " + W + "Tab && sleep 0.6 && xdotool mousemove " + W + "980 63 && sleep 0.4 && xdotool mousedown 1 && sleep 0.4 && xdotool mouseup 1 && "
         "sleep 0.6 && xdotool mousemove " + W + "962 105 && sleep 0.4 && xdotool mousedown 1 && sleep 0.4 && "
         "xdotool mouseup 1 && sleep 0.6 && "
         "xdotool mousemove " + W + "1140 176 && sleep 0.4 && xdotool mousedown 1 && sleep 0.4 && xdotool mouseup 1 && "
         "sleep 0.4 && xdotool mousemove " + W + "640 650 && sleep 0.3 && xdotool key " + W + "F2; "
         "for i in $(seq 1 240); do [ -s " + report + " ] && break; sleep 0.5; done";
  const std::string script = dir + "/session.sh";  // $(...) and $win must reach bash, not std::system's sh -c
  std::ofstream(script) << cmd << "\n";
  ASSERT_EQ(std::system(("bash " + script).c_str()), 0);
  const nlohmann::json r = read_json(report);
  ASSERT_TRUE(r.is_object()) << "the game wrote no report";
  const auto& in = r["interaction"];
  // The drag: boxer 0's head, pulled at least 0.15 m toward the cursor, released; the boxer is up at the end.
  ASSERT_GE(in["drags"].size(), 1u) << in.dump();
  const auto& drag = in["drags"][0];
  EXPECT_EQ(drag["boxer"], 0);
  EXPECT_EQ(drag["bone"], "head");
  EXPECT_GE(drag["max_displacement_m"].get<double>(), 0.15) << drag.dump();
  EXPECT_GT(drag["released_at"].get<double>(), drag["t"].get<double>());
  EXPECT_FALSE(r["boxers"][0]["fell"].get<bool>());
  // The throw hit boxer 1.
  EXPECT_EQ(in["objects_thrown"], 1);
  bool ball_on_1 = false;
  for (const auto& h : in["object_hits"]) ball_on_1 = ball_on_1 || (h["boxer"] == 1 && h["object"] == "ball");
  EXPECT_TRUE(ball_on_1) << in["object_hits"].dump();
  // The panel's clicks and the key: boxer 0 in person space (the combo), boxer 1 on the PD balance (the radio) and,
  // F2, its servo stepped from world to person space.
  EXPECT_EQ(r["boxers"][0]["servo"], "person");
  EXPECT_EQ(r["boxers"][0]["balance"], "qp");
  EXPECT_EQ(r["boxers"][1]["balance"], "pd");
  EXPECT_EQ(r["boxers"][1]["servo"], "person");

  // The recording, played headless for the same time: the same run (every measurement of both boxers, the hands').
  const nlohmann::json rec = read_json(record);
  ASSERT_TRUE(rec.is_object());
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.6f", r["seconds"].get<double>());
  ASSERT_EQ(std::system((exe + " --headless --no-validation --scenario stand --seed 1 --seconds " + seconds +
                         " --input " + record + " --report " + replay + " >/dev/null 2>&1")
                            .c_str()),
            0);
  nlohmann::json h = read_json(replay);
  ASSERT_TRUE(h.is_object());
  EXPECT_EQ(h["physics_steps"], r["physics_steps"]);
  EXPECT_EQ(h["interaction"].dump(), r["interaction"].dump());
  for (int k = 0; k < 2; ++k) {
    nlohmann::json a = r["boxers"][k], b = h["boxers"][k];
    a.erase("qp"), b.erase("qp");  // its wall-clock solve times
    EXPECT_EQ(a.dump(), b.dump()) << "boxer " << k;
  }
}
