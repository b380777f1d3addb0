#pragma once
// The game's front end in the window: a state machine of screens (title, playing, paused, the result) and the menus'
// keyboard. Plain data and free functions, no window or ImGui: the window loop (game/app.cpp) feeds it the menu keys
// and the match's end, the screens (front_end_screens.h) draw it and give back what the mouse chose. Headless runs
// have no screens: --mode starts a mode directly (apply_mode), in the window or not. Why it is built this way:
// docs/decisions/front-end.md.
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "game/cli.h"

namespace boxing {

enum class Screen { Title, Playing, Paused, Result };
// The title's modes: AI vs AI, the player (red) vs the AI, two players, the hands-on lab (the stand scenario).
enum class Mode { Watch, Play, Versus, Sandbox };
inline constexpr std::array<const char*, 3> kAiLevels = {"easy", "normal", "hard"};

const char* mode_name(Mode m);  // as --mode spells it
std::optional<Mode> mode_from_name(const std::string& name);
const char* screen_name(Screen s);  // "title", "playing", "paused", "result" (the report's front_end.screen)

// What the title sets up. Rounds and seed start from the command line's.
struct FrontEndSettings {
  Mode mode = Mode::Play;
  int ai_level = 1;  // kAiLevels index: the AI's level (both AIs in watch; blue's in play)
  int rounds = 3;
  uint64_t seed = 1;
};

// The title menu's rows, top to bottom; the pause menu's.
enum class TitleItem { Watch, Play, Versus, Sandbox, AiLevel, Rounds, Seed, Quit, Count };
enum class PauseItem { Resume, Restart, ToTitle, Count };
enum class MenuKey { Up, Down, Left, Right, Enter, Back };
// What a key or a click asks of the window: start the title's mode (a new world), resume, restart the mode (a new
// world, the same settings), back to the title, quit the game.
enum class FrontAction { None, Start, Resume, Restart, ToTitle, Quit };

struct FrontEnd {
  Screen screen = Screen::Title;
  FrontEndSettings settings;
  int title_cursor = static_cast<int>(TitleItem::Play);
  int pause_cursor = 0;
  double result_at = -1.0;  // s of simulated time: the result screen opens then (< 0: the bout is not over)
};

// The front end of a window run: the title, or with --mode or --scenario given, playing at once.
FrontEnd front_end_for(const Options& o);

// A menu key on the current screen: moves the cursor, changes a title option (left / right), or chooses. Esc (Back):
// the title quits, playing pauses, paused resumes, the result goes to the title.
FrontAction front_end_key(FrontEnd& fe, MenuKey k);
// A title row chosen (Enter or a click): a mode starts, Quit quits, an option steps forward.
FrontAction title_choose(FrontEnd& fe, TitleItem item);
// A title option stepped by dir (+1 / -1): the AI level (easy / normal / hard), the rounds (1-15), the seed (>= 1).
void title_step(FrontEnd& fe, TitleItem item, int dir);
// A pause menu row chosen.
FrontAction pause_choose(FrontEnd& fe, PauseItem item);
// The screen an action leads to (Start / Resume / Restart: playing; ToTitle: the title).
void front_end_apply(FrontEnd& fe, FrontAction a);
// Each frame while playing: once the bout is over, the result screen opens result_delay s of simulated time later
// (the knockout or the last bell seen first).
inline constexpr double kResultDelay = 3.0;
void front_end_watch_bout(FrontEnd& fe, bool bout_over, double time_s);

// The run's options for a mode: watch, play and versus the match (play: red is the keyboard's; versus: both are
// players', match_setup reads the mode: the keyboard's halves and the pads, fight_keys.h), sandbox the stand scenario (two boxers in guard to
// drag, push and throw at).
Options apply_mode(Options o, Mode m);
// The options the title's settings start: the mode, the seed, the rounds and the AI level (both AIs' level).
Options options_for(const Options& base, const FrontEndSettings& s);

}  // namespace boxing
