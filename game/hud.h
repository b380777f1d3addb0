#pragma once
// The game's UI windows, built with Dear ImGui between eng::ui::ui_begin and ui_end (engine/ui/ui.h).
#include <string>
#include <vector>

namespace boxing {

// What the stats panel shows: the frame time (ms and fps), the GPU, and the game's status lines.
struct HudStats {
  float frame_ms = 0;
  std::string device;
  std::vector<std::string> lines;
};

// The stats panel in the top-left corner: translucent, takes no input (clicks and drags go to the scene).
void draw_stats_panel(const HudStats& stats);

// The match's panel (top centre): the round and its clock, per boxer a consciousness bar, punches landed / thrown and
// knockdowns, and a banner (a knockdown's count, the result).
struct MatchHud {
  int round = 1;
  double clock_s = 0.0;  // left in the round (or the rest between rounds)
  bool resting = false;  // between rounds
  struct Side {
    float consciousness = 1.0f;
    int landed = 0, thrown = 0, knockdowns = 0;
    bool player = false;
    const char* state = "";
  } side[2];
  std::string banner;
};
void draw_match_panel(const MatchHud& hud);
// The panel's top line: the round and the time left in it, whole seconds as m:ss ("ROUND 1   2:59").
std::string match_clock_text(const MatchHud& hud);

}  // namespace boxing
