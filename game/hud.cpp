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
  ImGui::SetNextWindowPos(ImVec2(10, s.top), ImGuiCond_Always);
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

namespace {

ImU32 rgba(const float c[3], float a = 1.0f) { return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], a)); }

// A team colour made readable as text on a dark ground (the renderer's colours are dark, linear RGB).
ImU32 bright(const float c[3]) {
  const float l[3] = {0.3f + 0.9f * c[0], 0.3f + 0.9f * c[1], 0.3f + 0.9f * c[2]};
  return rgba(l);
}

}  // namespace

float hud_text_width(ImFont* font, const char* text) {
  ImFont* f = font ? font : ImGui::GetFont();
  return f->CalcTextSizeA(f->FontSize, 1e9f, 0.0f, text).x;
}

void hud_text(ImDrawList* dl, ImFont* font, float x, float y, float align_x, ImU32 colour, const char* text) {
  ImFont* f = font ? font : ImGui::GetFont();
  x -= align_x * hud_text_width(f, text);
  const float shadow = std::max(1.0f, f->FontSize / 14.0f);  // a drop shadow keeps the type legible on the lit ring
  dl->AddText(f, f->FontSize, ImVec2(x + shadow, y + shadow), IM_COL32(0, 0, 0, 200), text);
  dl->AddText(f, f->FontSize, ImVec2(x, y), colour, text);
}

// Per side a plate along the top (red left, blue right, mirrored): the name in the boxer's colour, its tag, the
// consciousness bar, punches and knockdowns; the round and clock between them; below, the count, the cards or the
// result. On ImGui's background list: under every panel, taking no input.
void draw_broadcast_hud(const MatchHud& h, const HudFonts& fonts) {
  const ImGuiIO& io = ImGui::GetIO();
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float W = io.DisplaySize.x, H = io.DisplaySize.y;
  const float margin = 20.0f, plate_w = std::min(0.34f * W, 420.0f), top = 14.0f;
  const ImU32 white = IM_COL32(245, 245, 240, 255), dim = IM_COL32(210, 210, 200, 230);
  const float large = fonts.large ? fonts.large->FontSize : ImGui::GetFontSize();
  char line[128];
  for (int k = 0; k < 2; ++k) {
    const MatchHud::Side& s = h.side[k];
    const float x0 = k == 0 ? margin : W - margin - plate_w, x1 = x0 + plate_w;
    const float ax = k == 0 ? 0.0f : 1.0f, xt = k == 0 ? x0 + 10.0f : x1 - 10.0f;
    // The UI blends in linear space over the sRGB scene: a ground needs a high alpha to read dark.
    const float plate_h = large + 68.0f;  // the name, the consciousness and stamina bars, the punches
    dl->AddRectFilled(ImVec2(x0, top), ImVec2(x1, top + plate_h), IM_COL32(6, 8, 12, 225), 6.0f);
    dl->AddRectFilled(k == 0 ? ImVec2(x0, top) : ImVec2(x1 - 6.0f, top), k == 0 ? ImVec2(x0 + 6.0f, top + plate_h)
                                                                            : ImVec2(x1, top + plate_h),
                      rgba(s.colour), 3.0f);
    hud_text(dl, fonts.large, xt, top + 4.0f, ax, bright(s.colour), s.name.c_str());
    if (!s.tag.empty()) {
      const float name_w = hud_text_width(fonts.large, s.name.c_str());
      hud_text(dl, fonts.medium, k == 0 ? xt + name_w + 14.0f : xt - name_w - 14.0f, top + 12.0f, ax, white,
               s.tag.c_str());
    }
    // Consciousness: the bar drains toward the middle of the screen, as a broadcast's health bars do.
    const float by = top + large + 12.0f, bw = plate_w - 20.0f, bx0 = x0 + 10.0f;
    dl->AddRectFilled(ImVec2(bx0, by), ImVec2(bx0 + bw, by + 14.0f), IM_COL32(40, 40, 46, 220), 3.0f);
    const float fill = std::clamp(s.consciousness, 0.0f, 1.0f) * bw;
    const float f0 = k == 0 ? bx0 : bx0 + bw - fill;
    if (fill > 0.0f) dl->AddRectFilled(ImVec2(f0, by), ImVec2(f0 + fill, by + 14.0f), bright(s.colour), 3.0f);
    // Stamina: a thin bar under it, the same way; amber, red once below the band where it slows the punches (0.3).
    const float sy = by + 18.0f;
    dl->AddRectFilled(ImVec2(bx0, sy), ImVec2(bx0 + bw, sy + 6.0f), IM_COL32(40, 40, 46, 220), 2.0f);
    const float sfill = std::clamp(s.stamina, 0.0f, 1.0f) * bw;
    const float s0 = k == 0 ? bx0 : bx0 + bw - sfill;
    const ImU32 scol = s.stamina < 0.3f ? IM_COL32(230, 70, 50, 255) : IM_COL32(235, 185, 60, 255);
    if (sfill > 0.0f) dl->AddRectFilled(ImVec2(s0, sy), ImVec2(s0 + sfill, sy + 6.0f), scol, 2.0f);
    std::snprintf(line, sizeof line, "landed %d / %d   down %d", s.landed, s.thrown, s.knockdowns);
    hud_text(dl, fonts.medium, xt, sy + 12.0f, ax, dim, line);
    // A refused press: why, just under the plate (player_input.h), in large type for the second it lasts.
    if (!s.notice.empty()) {
      std::string why = s.notice;
      for (char& ch : why) ch = static_cast<char>(ch >= 'a' && ch <= 'z' ? ch - 'a' + 'A' : ch);
      hud_text(dl, fonts.large, xt, top + plate_h + 6.0f, ax, IM_COL32(255, 120, 80, 255), why.c_str());
    }
  }
  // The round and the clock.
  const int secs = static_cast<int>(h.clock_s);
  std::snprintf(line, sizeof line, "%d:%02d", secs / 60, secs % 60);
  const float cw = std::max(120.0f, hud_text_width(fonts.large, line) + 40.0f);
  dl->AddRectFilled(ImVec2(0.5f * (W - cw), top), ImVec2(0.5f * (W + cw), top + large + 40.0f), IM_COL32(6, 8, 12, 225),
                    6.0f);
  const std::string head = h.resting ? std::string("REST") : "ROUND " + std::to_string(h.round);
  hud_text(dl, fonts.medium, 0.5f * W, top + 6.0f, 0.5f, dim, head.c_str());
  hud_text(dl, fonts.large, 0.5f * W, top + 28.0f, 0.5f, white, line);
  // A knockdown: who is down and the count, in the largest type.
  const float mid = 0.30f * H;
  if (h.down >= 0 && h.result.empty()) {
    const MatchHud::Side& s = h.side[h.down];
    const std::string down = s.name + " DOWN";
    hud_text(dl, fonts.large, 0.5f * W, mid, 0.5f, bright(s.colour), down.c_str());
    if (h.count > 0) {
      const std::string n = std::to_string(h.count);
      hud_text(dl, fonts.huge, 0.5f * W, mid + large + 4.0f, 0.5f, white, n.c_str());
    }
    if (h.count_stopped)
      hud_text(dl, fonts.medium, 0.5f * W, mid + large + (fonts.huge ? fonts.huge->FontSize : 2.0f * large) + 10.0f, 0.5f,
               dim, "count stopped: to the neutral corner");
  }
  if (!h.cards.empty() && h.result.empty()) hud_text(dl, fonts.large, 0.5f * W, mid, 0.5f, white, h.cards.c_str());
  if (!h.result.empty()) hud_text(dl, fonts.large, 0.5f * W, mid, 0.5f, IM_COL32(255, 215, 60, 255), h.result.c_str());
}

void draw_key_hints(const std::string& text, ImFont* font) {
  const ImGuiIO& io = ImGui::GetIO();
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float size = font ? font->FontSize : ImGui::GetFontSize();
  hud_text(dl, font, 0.5f * io.DisplaySize.x, io.DisplaySize.y - size - 8.0f, 0.5f, IM_COL32(235, 235, 225, 215),
           text.c_str());
}

void draw_caption(const std::string& text, ImFont* font) {
  if (text.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const float size = font ? font->FontSize : ImGui::GetFontSize();
  const float w = hud_text_width(font, text.c_str()), x = 0.5f * io.DisplaySize.x;
  dl->AddRectFilled(ImVec2(x - 0.5f * w - 12.0f, 8.0f), ImVec2(x + 0.5f * w + 12.0f, 8.0f + size + 12.0f),
                    IM_COL32(30, 32, 38, 190), 6.0f);
  hud_text(dl, font, x, 14.0f, 0.5f, IM_COL32(245, 245, 235, 255), text.c_str());
}

}  // namespace boxing
