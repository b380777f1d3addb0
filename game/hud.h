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

}  // namespace boxing
