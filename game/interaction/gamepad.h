#pragma once
// GAMEPADS: a pad's state (the buttons held, the axes' positions) turned into fight actions. Pure functions of the
// state now and what was read before, no GLFW: the window polls GLFW's gamepad API each frame
// (engine/platform/window.h read_gamepad) and sends a `pad` input event when a pad's state changes, --input files
// carry the same events, and the world reads every pad each physics step with pad_update, so a pad's fight is
// recorded and replayed like the keys' (interaction.h).
//
// The state is GLFW 3.3's GLFWgamepadstate: GLFW maps every pad it knows (the SDL GameController database built into
// GLFW 3.3, https://www.glfw.org/docs/3.3/input_guide.html#gamepad) to the Xbox layout of 15 buttons and 6 axes; the
// sticks run -1..1 with up NEGATIVE (SDL's convention), the triggers -1 (released) .. 1 (pulled).
//
// THE MAPPING (README: Controls; docs/guide/controls.md):
//   left stick or d-pad   step in / out / left / right; held, the step repeats every kStepRepeat s
//   L3 / R3 (stick clicks) pivot left / right
//   X / Y                 jab / cross            A / B    lead / rear hook       LB / RB   lead / rear uppercut
//   LT / RT               block / duck           right stick left / right        slip left / right
//   Start                 the pause menu (the window's, not a fight action)
// A button acts when it goes down (held, it does not repeat: a held punch button is one punch); the triggers and
// the right stick act when they cross kPressAt and re-arm below kReleaseAt (hysteresis, so a trigger resting near the
// threshold does not chatter).
#include <array>
#include <cstdint>

namespace boxing {

inline constexpr int kPadButtons = 15, kPadAxes = 6;
inline constexpr int kMaxPads = 16;  // GLFW_JOYSTICK_1 .. GLFW_JOYSTICK_LAST
// GLFW_GAMEPAD_BUTTON_* and GLFW_GAMEPAD_AXIS_* order (glfw3.h); the names are the --input file's.
enum PadButton : uint8_t {
  kPadA, kPadB, kPadX, kPadY, kPadLeftBumper, kPadRightBumper, kPadBack, kPadStart, kPadGuide, kPadLeftThumb,
  kPadRightThumb, kPadDpadUp, kPadDpadRight, kPadDpadDown, kPadDpadLeft
};
enum PadAxis : uint8_t { kPadLeftX, kPadLeftY, kPadRightX, kPadRightY, kPadLeftTrigger, kPadRightTrigger };
inline constexpr const char* kPadButtonNames[kPadButtons] = {
    "a",          "b",           "x",       "y",          "left_bumper", "right_bumper", "back",     "start",
    "guide",      "left_thumb",  "right_thumb", "dpad_up", "dpad_right",  "dpad_down",    "dpad_left"};
inline constexpr const char* kPadAxisNames[kPadAxes] = {"left_x",  "left_y",       "right_x",
                                                       "right_y", "left_trigger", "right_trigger"};

struct PadState {
  bool connected = false;
  std::array<bool, kPadButtons> buttons{};
  std::array<float, kPadAxes> axes{0.0f, 0.0f, 0.0f, 0.0f, -1.0f, -1.0f};  // at rest: sticks centred, triggers out
  bool operator==(const PadState&) const = default;
};
// An axis's resting value (sticks 0, triggers -1).
inline constexpr float pad_axis_rest(int axis) { return axis >= kPadLeftTrigger ? -1.0f : 0.0f; }

// Stick and trigger thresholds (share of full deflection; a trigger's 0..1 is (axis + 1) / 2). 0.5 to act is past
// the worn-stick drift (SDL's and GLFW's docs leave dead zones to the game; pads rest within about 0.1-0.2) and
// half way, so a flick counts; 0.35 to re-arm gives the hysteresis.
inline constexpr float kPressAt = 0.5f, kReleaseAt = 0.35f;
// s between the steps of a held stick: a footwork move is two steps of FootworkTuning::swing (0.28 s) after at least
// min_shift (0.08 s) of weight shift each, about 0.72 s (game/footwork.h); asking sooner only queues moves the feet
// cannot take yet.
inline constexpr double kStepRepeat = 0.75;

// What the world keeps per pad between reads.
struct PadReader {
  PadState last;      // the state read before (edges are against it)
  int step_dir = -1;  // the held step direction (kStepActions index), -1 none
  double next_step = 0.0;  // s: the held step repeats then
  bool trigger_on[2] = {false, false};  // LT, RT past kPressAt (until below kReleaseAt)
  int slip_dir = 0;   // the right stick's slip held: -1 left, +1 right, 0 none
};

// The fight actions one read gives (kKeyActions' names, game/interaction/input_events.h), in a fixed order.
struct PadActions {
  std::array<const char*, 16> action{};
  int count = 0;
  void add(const char* a) {
    if (count < static_cast<int>(action.size())) action[count++] = a;
  }
};

// Reads a pad at time t (s): the actions of what changed since the last read, and the held step's repeat. A pad
// that disconnects gives nothing and forgets what was held (hot-plug); one that (re)connects starts from rest, so a
// button already down when it appears counts as pressed.
PadActions pad_update(PadReader& r, const PadState& now, double t);

// Which boxer a pad drives (README: Controls, two players). rank: the pad's place among the connected pads in GLFW's
// order (0 first). Outside versus every pad drives the player's boxer (player, or red when none). In versus one pad
// is blue's (the keyboard is red's); with two or more the first is red's and the second blue's, the others nobody's
// (-1).
int pad_boxer(int rank, int pads_connected, bool versus, int player);

}  // namespace boxing
