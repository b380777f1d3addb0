#pragma once
// Command-line options of build/boxing. parse_cli never exits: a bad flag or value comes back as an Error whose
// message is the one line main prints before exiting with code 2.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>
#include "engine/core/result.h"
#include "game/scenario.h"

namespace boxing {

struct Options {
  std::string command = "play";        // "play" (the game), "graph" (motion-graph tool), "clips" (contact sheets)
  bool help = false;
  bool headless = false;
  bool headless_forced = false;        // --headless given (vs chosen because there is no display)
  int width = 1280;
  int height = 720;
  double seconds = 0.0;                // simulated seconds to run, then exit (0 = until the window closes;
                                       // headless defaults to 2 s)
  uint64_t seed = 1;
  Scenario scenario_id = Scenario::Arena;  // what the game branches on (scenario.h, game/scenarios/)
  std::string scenario = "arena";       // its name, as given (for display; scenario_name(scenario_id))
  bool scenario_given = false;          // --scenario given (the window then skips the title screen)
  // --mode watch|play|versus|sandbox: a front-end mode started directly (game/front_end.h apply_mode sets the
  // scenario and the players from it); "" = none: the window opens the title screen unless --scenario is given,
  // headless runs --scenario as before.
  std::string mode;
  std::string camera = "default";      // default | closeup | side | top
  std::string screenshot;              // PNG of the last frame
  std::string report;                  // JSON report
  std::string audio_out;               // --audio-out FILE.wav: the mixed sound (game/audio/game_audio.h)
  std::string content_dir;             // where content/ lives (default: the source tree's content/)
  std::string frames_dir;              // headless: write every rendered frame here as PNG
  int render_every = 0;                // headless: render every Nth display frame (0 = only the last)
  double frames_from = 0.0;            // headless: ... from this simulation time (s) on
  bool validation = true;              // Khronos validation layer (default on; errors make tests fail)
  bool overlay = true;                 // ImGui overlay in the window (off in headless screenshots unless asked)
  bool overlay_given = false;
  bool ghost = false;                  // translucent desired-pose ghost
  bool vsync = true;
  // The 3D scene's resolution per axis, upscaled under the HUD; 0 = auto (a CPU rasteriser keeps the scene within
  // eng::render::kCpuScenePixels, a GPU renders native).
  double render_scale = 0.0;
  std::string present = "auto";        // window: auto | swapchain | shm (eng::render::RendererConfig::Present)
  // scenario parameters (boxer / push-recovery scenarios)
  std::string servo = "world";         // world | person | parent | parent-meathook
  double push_dir_deg = 0.0;
  double push_force = 0.0;
  double push_duration = 0.1;
  double push_at = 2.0;
  bool push_sine = false;              // --push-shape sine: push_force * sin(2 pi (t - push_at)) N (Kudoh's Fig. 3.3)
  std::string drill_clip;              // stand / push: play this clip once every drill_every seconds (else guard)
  double drill_every = 3.0;
  // servo gains: ONE pair for the whole body (per joint K = I omega_n^2, D = 2 zeta I omega_n; world.cpp)
  double servo_omega_n = 15.0;         // rad/s
  double servo_zeta = 1.0;
  // Root spring (paper section V: torque-limited, "for some dynamic balance situations"); off by default: the
  // boxers stand with no root help at all.
  std::string root_spring = "auto";    // on | off | auto (on for graph-walk and match)
  // Balance: "qp" = the balance QP (engine/control/balance/balance_qp.h) turns the desired pose into joint torques;
  // "pd" = eq. 3 as implicit joint springs plus the PD shift of the desired root (boxer.cpp's balance layer).
  std::string balance = "qp";
  std::string stepping = "auto";      // --stepping on|off|auto: the balance's own steps (off = in place, Kudoh's
                                      // lab); auto = on in the push lab, the match and the walk, off elsewhere
  // --getup assisted|unassisted: the carried get-up (the root spring's force lifts the pelvis: stand_up.h) or the one
  // the body does (the balance QP on the get-up plan's supports, no force: unassisted_getup.h)
  std::string getup = "assisted";
  std::string step_placement = "capture";  // --step-placement capture|ipc: capture point or Kwon's cart-pole LQR
  std::string footwork = "carry";     // --footwork shuffle|carry: the clips' steps pressed along the crate, or carried
  bool flat = false;                  // --flat: one level platform (the papers' floor) instead of the uneven crates
  // --priorities kudoh|off|auto: Kudoh's priorities in the balance QP (the trunk's posture x100, the com x30, the arms'
  // return; BalanceQpTuning); auto = the match's own (on in guard), off elsewhere.
  std::string priorities = "auto";
  double stance_drop = -1.0;          // --stance-drop M: the desired root this far below the clip's (< 0: 0.04)
  double contact_gap = -1.0;          // m, < 0: each foot-contact purpose its own gap (FootContactThresholds)
  double root_spring_max = -1.0;      // N m, its torque limit; < 0: 400 with the QP, 120 with pd
  // match
  double round_seconds = 180.0;       // --round-seconds: a round's length
  int rounds = 3;                     // --rounds: the bout's rounds (bout.h)
  double start_apart = 2.8;           // --start-apart: the match's marks, pelvis to pelvis (m; arena.h kRingSeparation)
  double rest_seconds = 60.0;         // --rest-seconds: the rest between rounds (BoutTuning::rest_seconds)
  int player = -1;                    // --player 0|1: that boxer takes the keyboard (-1: both AI)
  // --ai LEVEL[,LEVEL]: red's and blue's AI level, easy | normal | hard (fighter_ai.h apply_ai_level; normal is the
  // fight as tuned, bit for bit)
  std::array<std::string, 2> ai = {"normal", "normal"};
  // the player's hands (game/interaction/)
  std::string input;                  // --input FILE.json: timed input events (drags, throws, pushes, keys, settings)
  std::string record;                 // --record FILE.json: every input event applied, in the same form
  std::string debug_draw;             // --debug LIST: contacts,com,support,capture,hits (comma-separated) or none
  int slow = 1;                       // --slow 1|2|4|10: the window's slow motion (1 = real time)
  double chaos = 0.0;                 // --chaos RATE: random input events per second (drags, pushes, throws)
  // graph tool
  std::string graph_report;
  std::string graph_dot;
  // clips tool
  std::string sheet_dir;
};

// The flags are one table in cli.cpp (name, value parser with its range or set, help line); help_text, the --help
// text, is generated from it.
eng::Result<Options> parse_cli(const std::vector<std::string>& args);
std::string help_text();

}  // namespace boxing
