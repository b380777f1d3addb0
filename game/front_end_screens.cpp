#include "game/front_end_screens.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "game/interaction/fight_keys.h"
#include "imgui.h"

namespace boxing {

namespace {

constexpr ImU32 kWhite = IM_COL32(245, 245, 240, 255);
constexpr ImU32 kDim = IM_COL32(190, 190, 180, 230);
constexpr ImU32 kGold = IM_COL32(255, 205, 60, 255);

float size_of(ImFont* f) { return f ? f->FontSize : ImGui::GetFontSize(); }

ImU32 bright(const float c[3]) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(0.3f + 0.9f * c[0], 0.3f + 0.9f * c[1], 0.3f + 0.9f * c[2], 1.0f));
}

// A screen: one full-screen window, no decoration, over the scene dimmed by `dim` (0-255 alpha); its draw list.
ImDrawList* begin_screen(const char* id, int dim) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(io.DisplaySize, ImGuiCond_Always);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoNav |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoScrollWithMouse;
  ImGui::Begin(id, nullptr, flags);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(ImVec2(0, 0), io.DisplaySize, IM_COL32(6, 8, 14, dim));
  return dl;
}

// A dark rounded ground under a screen's text, centred on cx (the UI blends in linear space over the sRGB scene: a
// ground needs a high alpha to read dark).
void ground(ImDrawList* dl, float cx, float y, float width, float height) {
  dl->AddRectFilled(ImVec2(cx - 0.5f * width, y), ImVec2(cx + 0.5f * width, y + height), IM_COL32(6, 8, 12, 215), 10.0f);
}

// A menu row centred at y, `width` wide: hovered, it takes the cursor; clicked, it returns true. `dir` says which
// third was clicked (-1 left, +1 right, 0 middle): the options' arrows.
bool menu_row(const char* id, float y, float width, float height, int row, int& cursor, int* dir = nullptr) {
  const ImGuiIO& io = ImGui::GetIO();
  const float x = 0.5f * (io.DisplaySize.x - width);
  ImGui::SetCursorScreenPos(ImVec2(x, y));
  const bool clicked = ImGui::InvisibleButton(id, ImVec2(width, height));
  if (ImGui::IsItemHovered() && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || clicked)) cursor = row;
  if (clicked && dir) {
    const float u = (io.MousePos.x - x) / width;
    *dir = u < 1.0f / 3.0f ? -1 : u > 2.0f / 3.0f ? +1 : 0;
  }
  return clicked;
}

// A row's label, highlighted when it has the cursor.
void row_label(ImDrawList* dl, const HudFonts& f, float y, float width, float h, bool selected, const std::string& text) {
  const ImGuiIO& io = ImGui::GetIO();
  const float cx = 0.5f * io.DisplaySize.x;
  if (selected) {
    dl->AddRectFilled(ImVec2(cx - 0.5f * width, y), ImVec2(cx + 0.5f * width, y + h), IM_COL32(200, 40, 30, 150), 6.0f);
    dl->AddRect(ImVec2(cx - 0.5f * width, y), ImVec2(cx + 0.5f * width, y + h), kGold, 6.0f, 0, 2.0f);
  }
  hud_text(dl, f.large, cx, y + 0.5f * (h - size_of(f.large)), 0.5f, selected ? kGold : kWhite, text.c_str());
}

const char* level_word(int level) { return level == 0 ? "EASY" : level == 2 ? "HARD" : "NORMAL"; }

std::string clock_of(double s) {
  char t[16];
  const int secs = static_cast<int>(s);
  std::snprintf(t, sizeof t, "%d:%02d", secs / 60, secs % 60);
  return t;
}

}  // namespace

FrontAction draw_title(FrontEnd& fe, const HudFonts& f) {
  const ImGuiIO& io = ImGui::GetIO();
  const float W = io.DisplaySize.x, H = io.DisplaySize.y, cx = 0.5f * W;
  ImDrawList* dl = begin_screen("##title", 120);
  const float huge = size_of(f.huge), large = size_of(f.large);
  const bool roomy = H >= 680.0f;  // 1280x720 and up; smaller windows (960x540) get a tighter menu
  const float top = roomy ? 0.08f * H : 0.03f * H;
  hud_text(dl, f.huge, cx, top, 0.5f, kWhite, "BOXING");
  dl->AddRectFilled(ImVec2(cx - 160.0f, top + huge + 4.0f), ImVec2(cx - 4.0f, top + huge + 10.0f),
                    IM_COL32(200, 35, 28, 255));
  dl->AddRectFilled(ImVec2(cx + 4.0f, top + huge + 4.0f), ImVec2(cx + 160.0f, top + huge + 10.0f),
                    IM_COL32(35, 70, 210, 255));
  hud_text(dl, f.medium, cx, top + huge + 18.0f, 0.5f, kDim, "two physically simulated boxers, three judges, one ring");
  // The menu: the modes, then the options (< value >), then quit.
  const FrontEndSettings& s = fe.settings;
  const std::string rows[] = {"WATCH  (AI VS AI)",
                              "PLAY VS AI",
                              "TWO PLAYERS",
                              "SANDBOX  (THE HANDS-ON LAB)",
                              std::string("AI LEVEL   <  ") + level_word(s.ai_level) + "  >",
                              "ROUNDS   <  " + std::to_string(s.rounds) + "  >",
                              "SEED   <  " + std::to_string(s.seed) + "  >",
                              "QUIT"};
  const float row_h = large + (roomy ? 10.0f : 4.0f), gap = roomy ? 6.0f : 0.0f;
  float y = top + huge + (roomy ? 56.0f : 52.0f);
  const float width = std::min(560.0f, W - 40.0f);
  const float menu_h = 9.0f * row_h + 8.0f * gap;  // eight rows and two half-row gaps
  ground(dl, cx, y - 12.0f, width + 60.0f, menu_h + 24.0f);
  FrontAction chosen = FrontAction::None;
  for (int r = 0; r < static_cast<int>(TitleItem::Count); ++r) {
    if (r == static_cast<int>(TitleItem::AiLevel) || r == static_cast<int>(TitleItem::Quit)) y += 0.5f * row_h;
    int dir = 0;
    if (menu_row(rows[r].c_str(), y, width, row_h, r, fe.title_cursor, &dir)) {
      const TitleItem item = static_cast<TitleItem>(r);
      const bool option = item == TitleItem::AiLevel || item == TitleItem::Rounds || item == TitleItem::Seed;
      if (option) title_step(fe, item, dir < 0 ? -1 : +1);
      else chosen = title_choose(fe, item);
    }
    row_label(dl, f, y, width, row_h, fe.title_cursor == r, rows[r]);
    y += row_h + gap;
  }
  // What the row under the cursor does, and the keys.
  static const char* const kHelp[] = {
      "Two AI boxers fight the bout; you watch (Esc for the menu).",
      "You are RED: J jab, K cross, U/I hooks, N/M uppercuts, B block, A/D slip, S duck, W/X step.",
      "Player 1 is RED on the fight keys; player 2's keys are not built yet: BLUE stays the AI.",
      "Two boxers in guard: drag them with the mouse, throw balls (T) and crates (Y); Tab opens the panel.",
      "How hard the AI fights: aggression, defence and reaction time.",
      "The bout's rounds; a minute's rest between them.",
      "The seed: the ring's crates and all the AI's choices. The same seed, the same fight.",
      "Leave the game."};
  hud_text(dl, f.medium, cx, y + 10.0f, 0.5f, kWhite, kHelp[fe.title_cursor]);
  hud_text(dl, f.medium, cx, H - 30.0f, 0.5f, kWhite,
           "Up / Down choose    Left / Right change    Enter start    Esc quit    (or the mouse)");
  ImGui::End();
  return chosen;
}

FrontAction draw_pause_menu(FrontEnd& fe, const HudFonts& f, const std::vector<std::string>& who) {
  const ImGuiIO& io = ImGui::GetIO();
  const float W = io.DisplaySize.x, H = io.DisplaySize.y, cx = 0.5f * W;
  ImDrawList* dl = begin_screen("##pause", 160);
  const float large = size_of(f.large), medium = size_of(f.medium);
  float y = 0.15f * H;  // below the HUD's name plates and clock
  hud_text(dl, f.huge, cx, y, 0.5f, kWhite, "PAUSED");
  y += size_of(f.huge) + 20.0f;
  ground(dl, cx, y - 10.0f, 480.0f, 3.0f * (large + 14.0f) + 6.0f);
  const char* rows[] = {"RESUME", "RESTART", "QUIT TO TITLE"};
  FrontAction chosen = FrontAction::None;
  for (int r = 0; r < static_cast<int>(PauseItem::Count); ++r) {
    if (menu_row(rows[r], y, 420.0f, large + 8.0f, r, fe.pause_cursor))
      chosen = pause_choose(fe, static_cast<PauseItem>(r));
    row_label(dl, f, y, 420.0f, large + 8.0f, fe.pause_cursor == r, rows[r]);
    y += large + 14.0f;
  }
  // The controls (fight_keys.h, gamepad.h): one row per action, a column per half of the keyboard and the pad; under
  // it who has which controls now (two players: which half, which pad).
  const std::vector<ControlsRow>& table = controls_table();
  const float line = medium + 6.0f, width = std::min(W - 40.0f, 1180.0f), left = cx - 0.5f * width;
  y += 14.0f;
  ground(dl, cx, y - 8.0f, width, line * static_cast<float>(table.size() + who.size()) + 22.0f);
  const float col[4] = {left + 16.0f, left + 0.30f * width, left + 0.52f * width, left + 0.75f * width};
  for (size_t r = 0; r < table.size(); ++r) {
    const ImU32 c = r == 0 ? kGold : kWhite;
    hud_text(dl, f.medium, col[0], y, 0.0f, r == 0 ? kGold : kDim, table[r].action);
    hud_text(dl, f.medium, col[1], y, 0.0f, c, table[r].left);
    hud_text(dl, f.medium, col[2], y, 0.0f, c, table[r].right);
    hud_text(dl, f.medium, col[3], y, 0.0f, c, table[r].pad);
    y += line;
  }
  y += 6.0f;
  for (const std::string& w : who) {
    hud_text(dl, f.medium, col[0], y, 0.0f, kGold, w.c_str());
    y += line;
  }
  hud_text(dl, f.medium, cx, H - 30.0f, 0.5f, kWhite, "Up / Down choose    Enter    Esc resume    (pad: d-pad, A, Start)");
  ImGui::End();
  return chosen;
}

std::string result_headline(const BoutSummary& r) {
  return r.winner < 0 ? "DRAW" : r.name[r.winner] + " WINS";
}

std::string result_method_line(const BoutSummary& r) {
  const std::string at = " IN ROUND " + std::to_string(r.round) + " AT " + clock_of(r.time_s);
  if (r.method == "ko") return "BY KNOCKOUT" + at;
  if (r.method == "tko") return "BY TECHNICAL KNOCKOUT" + at + " (THREE KNOCKDOWNS)";
  const int red = r.judges_for[0], blue = r.judges_for[1], even = 3 - red - blue;
  const std::string rounds = " AFTER " + std::to_string(r.round) + (r.round == 1 ? " ROUND" : " ROUNDS");
  if (r.method == "decision") {
    const int a = std::max(red, blue), b = std::min(red, blue);
    const std::string kind = a == 3 ? "UNANIMOUS" : b == 0 ? "MAJORITY" : "SPLIT";
    return kind + " DECISION" + rounds + " (" + std::to_string(a) + "-" + std::to_string(b) +
           (even ? ", " + std::to_string(even) + " EVEN)" : ")");
  }
  return "NO WINNER" + rounds + ": JUDGES " + std::to_string(red) + " RED, " + std::to_string(blue) + " BLUE, " +
         std::to_string(even) + " EVEN";
}

FrontAction draw_result(const BoutSummary& r, const HudFonts& f) {
  const ImGuiIO& io = ImGui::GetIO();
  const float W = io.DisplaySize.x, H = io.DisplaySize.y, cx = 0.5f * W;
  ImDrawList* dl = begin_screen("##result", 150);
  float y = std::max(12.0f, 0.05f * H);
  const std::string head = result_headline(r);
  hud_text(dl, f.huge, cx, y, 0.5f, r.winner < 0 ? kWhite : bright(r.colour[r.winner]), head.c_str());
  y += size_of(f.huge) + 6.0f;
  const std::string how = result_method_line(r);
  hud_text(dl, f.large, cx, y, 0.5f, kGold, how.c_str());
  y += size_of(f.large) + 22.0f;
  // The cards: per round the three judges (red-blue), then each boxer's punches landed / thrown and knockdowns.
  const float tw = std::min(980.0f, W - 40.0f), x0 = cx - 0.5f * tw;
  const float col[] = {0.0f, 0.13f, 0.25f, 0.37f, 0.52f, 0.76f};  // round, judges 1-3, red, blue (share of tw)
  const float line = size_of(f.medium) + 8.0f;
  ground(dl, cx, y - 12.0f, tw + 40.0f, (std::min<float>(r.rounds.size(), (H - y - 150.0f) / line) + 2.0f) * line + 24.0f);
  const char* heads[] = {"ROUND", "JUDGE 1", "JUDGE 2", "JUDGE 3", "RED landed / thrown", "BLUE landed / thrown"};
  const ImU32 head_colour[] = {kDim, kDim, kDim, kDim, bright(r.colour[0]), bright(r.colour[1])};
  for (int c = 0; c < 6; ++c) hud_text(dl, f.medium, x0 + col[c] * tw, y, 0.0f, head_colour[c], heads[c]);
  y += line;
  dl->AddLine(ImVec2(x0, y - 3.0f), ImVec2(x0 + tw, y - 3.0f), kDim);
  int total[3][2] = {}, landed[2] = {}, thrown[2] = {}, down[2] = {};
  char cell[64];
  const size_t shown = std::min<size_t>(r.rounds.size(), static_cast<size_t>(std::max(1.0f, (H - y - 150.0f) / line)));
  for (size_t i = 0; i < r.rounds.size(); ++i) {
    const BoutSummary::Round& rd = r.rounds[i];
    for (int j = 0; j < 3; ++j) total[j][0] += rd.judges[j][0], total[j][1] += rd.judges[j][1];
    for (int k = 0; k < 2; ++k) landed[k] += rd.landed[k], thrown[k] += rd.thrown[k], down[k] += rd.knockdowns[k];
    if (i >= shown) continue;  // more rounds than the screen holds: the totals still count them
    hud_text(dl, f.medium, x0 + col[0] * tw, y, 0.0f, kWhite, std::to_string(rd.round).c_str());
    for (int j = 0; j < 3; ++j) {
      std::snprintf(cell, sizeof cell, "%d - %d", rd.judges[j][0], rd.judges[j][1]);
      hud_text(dl, f.medium, x0 + col[1 + j] * tw, y, 0.0f, kWhite, cell);
    }
    for (int k = 0; k < 2; ++k) {
      if (rd.knockdowns[k] > 0) std::snprintf(cell, sizeof cell, "%d / %d   %d down", rd.landed[k], rd.thrown[k], rd.knockdowns[k]);
      else std::snprintf(cell, sizeof cell, "%d / %d", rd.landed[k], rd.thrown[k]);
      hud_text(dl, f.medium, x0 + col[4 + k] * tw, y, 0.0f, kWhite, cell);
    }
    y += line;
  }
  dl->AddLine(ImVec2(x0, y - 3.0f), ImVec2(x0 + tw, y - 3.0f), kDim);
  hud_text(dl, f.medium, x0 + col[0] * tw, y, 0.0f, kGold, "TOTAL");
  for (int j = 0; j < 3; ++j) {
    std::snprintf(cell, sizeof cell, "%d - %d", total[j][0], total[j][1]);
    hud_text(dl, f.medium, x0 + col[1 + j] * tw, y, 0.0f, kGold, cell);
  }
  for (int k = 0; k < 2; ++k) {
    std::snprintf(cell, sizeof cell, "%d / %d   %d down", landed[k], thrown[k], down[k]);
    hud_text(dl, f.medium, x0 + col[4 + k] * tw, y, 0.0f, kGold, cell);
  }
  y += line + 24.0f;
  int cursor = 0;
  FrontAction chosen = FrontAction::None;
  if (menu_row("##back", y, 420.0f, size_of(f.large) + 10.0f, 0, cursor)) chosen = FrontAction::ToTitle;
  row_label(dl, f, y, 420.0f, size_of(f.large) + 10.0f, true, "BACK TO TITLE");
  hud_text(dl, f.medium, cx, H - 30.0f, 0.5f, kWhite, "Enter or Esc: back to the title");
  ImGui::End();
  return chosen;
}

}  // namespace boxing
