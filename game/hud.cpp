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

std::string match_clock_text(const MatchHud& h) {
  char line[64];
  const int secs = static_cast<int>(h.clock_s);
  if (h.resting) std::snprintf(line, sizeof line, "REST   %d:%02d", secs / 60, secs % 60);
  else std::snprintf(line, sizeof line, "ROUND %d   %d:%02d", h.round, secs / 60, secs % 60);
  return line;
}

void draw_match_panel(const MatchHud& h) {
  const ImGuiIO& io = ImGui::GetIO();
  const float w = 460.0f;
  ImGui::SetNextWindowPos(ImVec2(0.5f * (io.DisplaySize.x - w), 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w, h.banner.empty() ? 96.0f : 124.0f), ImGuiCond_Always);  // fixed: see above
  ImGui::SetNextWindowBgAlpha(0.55f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##match", nullptr, flags)) {
    char line[128];
    const std::string clock = match_clock_text(h);
    ImGui::SetCursorPosX(0.5f * (w - ImGui::CalcTextSize(clock.c_str()).x));
    ImGui::TextUnformatted(clock.c_str());
    const ImVec4 colour[2] = {ImVec4(0.85f, 0.15f, 0.12f, 1.0f), ImVec4(0.15f, 0.3f, 0.9f, 1.0f)};
    ImGui::Columns(2, nullptr, false);
    for (int k = 0; k < 2; ++k) {
      const MatchHud::Side& s = h.side[k];
      ImGui::PushStyleColor(ImGuiCol_PlotHistogram, colour[k]);
      ImGui::ProgressBar(s.consciousness, ImVec2(-1, 14), "");
      ImGui::PopStyleColor();
      std::snprintf(line, sizeof line, "%s%s  landed %d/%d  down %d", k == 0 ? "RED" : "BLUE", s.player ? " (you)" : "",
                    s.landed, s.thrown, s.knockdowns);
      ImGui::TextUnformatted(line);
      ImGui::TextUnformatted(s.state);
      ImGui::NextColumn();
    }
    ImGui::Columns(1);
    if (!h.banner.empty()) {
      ImGui::SetCursorPosX(0.5f * (w - ImGui::CalcTextSize(h.banner.c_str()).x));
      ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.2f, 1.0f), "%s", h.banner.c_str());
    }
  }
  ImGui::End();
}

}  // namespace boxing
