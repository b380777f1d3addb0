#pragma once
// The front end's screens in Dear ImGui (between eng::ui::ui_begin and ui_end): the title, the pause menu and the
// result. Each is one full-screen window over a dimmed scene, drawn in the display face (HudFonts); the keyboard is
// front_end_key's (game/front_end.h), the mouse is each screen's own: a hovered row takes the cursor, a click chooses
// it, and the action chosen comes back for the window to carry out.
#include "game/front_end.h"
#include "game/hud.h"

#include <string>
#include <vector>

namespace boxing {

// The title: the game's name, the modes, the AI level, the rounds, the seed and quit.
FrontAction draw_title(FrontEnd& fe, const HudFonts& fonts);
// Esc's menu while playing: resume, restart, quit to the title; under it the fight's controls (the keyboard's halves
// and the gamepad) and `who`: who has which controls now ("RED: LEFT KEYS", "PADS: 1 (Xbox Controller)").
FrontAction draw_pause_menu(FrontEnd& fe, const HudFonts& fonts, const std::vector<std::string>& who);
// The bout's result: the winner by name in its colour, the method, the round and time, the judges' cards and the
// punches landed / thrown per round; a click or Enter goes back to the title.
FrontAction draw_result(const BoutSummary& r, const HudFonts& fonts);
// The result's headline and its second line ("RED WINS", "BY KO IN ROUND 2 AT 1:12").
std::string result_headline(const BoutSummary& r);
std::string result_method_line(const BoutSummary& r);

}  // namespace boxing
