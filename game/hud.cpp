#include "game/hud.h"

#include <algorithm>
#include <cstdio>

#include "imgui.h"

namespace boxing {

void draw_stats_panel(const HudStats& s) {
  char stats[96];
  std::snprintf(stats, sizeof(stats), "%.2f ms  (%.0f fps)", s.frame_ms, s.frame_ms > 0 ? 1000.0f / s.frame_ms : 0.0f);
  // Size the panel from its text up front: an auto-resizing ImGui window is hidden on its first frame and lags
  // one frame behind its content, which would make a single headless frame miss the panel and break
  // frame-to-frame determinism.
  const ImGuiStyle& style = ImGui::GetStyle();
  float w = std::max(ImGui::CalcTextSize(stats).x, ImGui::CalcTextSize(s.device.c_str()).x);
  for (const std::string& line : s.lines) w = std::max(w, ImGui::CalcTextSize(line.c_str()).x);
  const int rows = 2 + static_cast<int>(s.lines.size());
  const float sep = s.lines.empty() ? 0.0f : style.ItemSpacing.y + 1.0f;
  const float h = rows * ImGui::GetTextLineHeightWithSpacing() - style.ItemSpacing.y + sep + 2.0f * style.WindowPadding.y;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w + 2.0f * style.WindowPadding.x, h), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.55f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##stats", nullptr, flags)) {
    ImGui::TextUnformatted(stats);
    ImGui::TextUnformatted(s.device.c_str());
    if (!s.lines.empty()) ImGui::Separator();
    for (const std::string& line : s.lines) ImGui::TextUnformatted(line.c_str());
  }
  ImGui::End();
}

}  // namespace boxing
