#pragma once
// The game's UI windows, built with Dear ImGui between eng::ui::ui_begin and ui_end (engine/ui/ui.h).
#include <string>
#include <vector>

struct ImFont;
struct ImDrawList;

namespace boxing {

// What the stats panel shows: the frame time (ms and fps), the GPU, and the game's status lines.
struct HudStats {
  float frame_ms = 0;
  std::string device;
  std::vector<std::string> lines;
  float top = 10.0f;  // px from the top edge
};

// The stats panel at the left edge, `top` down: translucent, takes no input (clicks and drags go to the scene).
void draw_stats_panel(const HudStats& stats);

// The match's broadcast HUD: per boxer a name plate in the boxer's colour (left red, right blue) with its
// consciousness bar, its stamina bar under it, punches landed / thrown and knockdowns, and under the plate why a
// press was refused; the round and its clock in the middle; a knockdown's
// count in large type; the round's cards between rounds; the result. `banner` is the same news as one line of text
// (the count, the cards, the result: what the tests read).
struct MatchHud {
  int round = 1;
  double clock_s = 0.0;  // left in the round (or the rest)
  bool resting = false;  // between rounds
  struct Side {
    std::string name = "RED";
    float colour[3] = {0.85f, 0.15f, 0.12f};  // the boxer's team colour (linear RGB, as the renderer draws it)
    float consciousness = 1.0f;
    int landed = 0, thrown = 0, knockdowns = 0;
    bool player = false;
    std::string tag;  // under the name: "YOU", "P2: RIGHT KEYS" ("" = none)
    const char* state = "";
    float stamina = 1.0f;  // the bar under consciousness (game/match/stamina.h)
    std::string notice;    // a refused press's reason, briefly: "tired", "hurt", "down", "busy" ("" = none)
  } side[2];
  int down = -1;               // the boxer down now (-1: none)
  int count = 0;               // the referee's count (0: not started)
  bool count_stopped = false;  // the count waits for the standing boxer to go to the neutral corner
  std::string cards;           // between rounds: "END OF ROUND 1   10-9  10-9  10-10"
  std::string result;          // the bout over: "RED WINS BY KO IN ROUND 2 (1:12)"
  std::string banner;
};

// The fonts the HUD and the title draw big type with (eng::ui::ui_font); nullptr: ImGui's current font, scaled.
struct HudFonts {
  ImFont* medium = nullptr;  // 18 px
  ImFont* large = nullptr;  // 28 px
  ImFont* huge = nullptr;   // 72 px
};
void draw_broadcast_hud(const MatchHud& hud, const HudFonts& fonts);
// Text with a drop shadow on `dl` at (x, y), its left (align_x 0), centre (0.5) or right (1) at x; its width.
float hud_text_width(ImFont* font, const char* text);
void hud_text(ImDrawList* dl, ImFont* font, float x, float y, float align_x, unsigned colour, const char* text);
// One line of key hints along the bottom of the screen (dim, small), e.g. "Esc menu   Tab physics panel".
void draw_key_hints(const std::string& line, ImFont* font);
// A scenario's caption (scenario_caption), at the top of the screen on a dark band.
void draw_caption(const std::string& text, ImFont* font);
// The bout's end for the result screen: who won and how, and per round the judges' cards and the punches.
struct BoutSummary {
  std::string name[2] = {"RED", "BLUE"};
  float colour[2][3] = {{0.85f, 0.15f, 0.12f}, {0.15f, 0.3f, 0.9f}};
  int winner = -1;         // 0 red, 1 blue, -1 a draw
  std::string method;      // "ko" | "tko" | "decision" | "draw"
  int round = 0;           // the round it ended in
  double time_s = 0.0;     // into that round
  int judges_for[2] = {};  // judges whose cards name red, blue
  struct Round {
    int round = 1;
    int judges[3][2] = {};  // per judge: red, blue
    int landed[2] = {}, thrown[2] = {}, knockdowns[2] = {};
  };
  std::vector<Round> rounds;
};

// The panel's top line: the round and the time left in it, whole seconds as m:ss ("ROUND 1   2:59").
std::string match_clock_text(const MatchHud& hud);

}  // namespace boxing
