#pragma once
// The window's live panel (Dear ImGui, right side; README: Controls): per boxer the servo space, balance QP or PD,
// the servo's frequency, the root spring (on / off, limit), consciousness, AI or player (the match); the ghost and the
// debug drawing; time (pause, single step, slow motion) and a restart with a seed. Settings that change the
// simulation go out as input events (set / key: game/interaction/), so they are recorded and replayed; the view and
// time settings are the window's own. Every control also has a key (handle_panel_keys) or a flag.
#include "game/scene_view.h"

namespace boxing {

struct World;

struct PanelState {
  bool open = true;
  bool paused = false;
  bool step_once = false;   // one 60 Hz frame while paused
  int slow = 0;             // 0: real time, 1: 1/2, 2: 1/4, 3: 1/10
  int seed = 1;
  bool restart = false;     // the window rebuilds the world with `seed`
};

double time_scale(const PanelState& p);
const char* time_scale_name(const PanelState& p);

// Builds the panel (between ui_begin and ui_end). `view` holds the ghost and the debug drawing flags.
void draw_control_panel(World& w, SceneView& view, PanelState& p);

// The panel's keys (when the UI does not want the keyboard): F1 / F2 cycle boxer 0's / 1's servo space, F3 / F4
// toggle their balance (QP / PD), F6 / F7 their root spring; 1-5 the debug drawing; P pause, period one step,
// [ and ] slower / faster; F5 restart.
struct KeyState {
  bool (*pressed)(const void* ctx, int glfw_key);
  const void* ctx;
};
void handle_panel_keys(World& w, SceneView& view, PanelState& p, const KeyState& keys);

}  // namespace boxing
