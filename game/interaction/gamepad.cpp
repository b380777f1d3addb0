#include "game/interaction/gamepad.h"

#include <cmath>

namespace boxing {

namespace {

// The step directions in kKeyActions' names: forward (stick up), back, left, right.
constexpr const char* kStepActions[4] = {"step_forward", "step_back", "step_left", "step_right"};

// The step direction the left stick or the d-pad holds (-1 none). The d-pad wins over the stick; the stick's larger
// component picks the direction, past kPressAt to start and held down to kReleaseAt once stepping that way.
int held_step(const PadState& s, int was) {
  if (s.buttons[kPadDpadUp]) return 0;
  if (s.buttons[kPadDpadDown]) return 1;
  if (s.buttons[kPadDpadLeft]) return 2;
  if (s.buttons[kPadDpadRight]) return 3;
  const float x = s.axes[kPadLeftX], y = s.axes[kPadLeftY];
  const bool vertical = std::abs(y) >= std::abs(x);
  const int dir = vertical ? (y < 0.0f ? 0 : 1) : (x < 0.0f ? 2 : 3);
  const float along = vertical ? std::abs(y) : std::abs(x);
  return along > (dir == was ? kReleaseAt : kPressAt) ? dir : -1;
}

}  // namespace

PadActions pad_update(PadReader& r, const PadState& now, double t) {
  PadActions out;
  if (!now.connected) {  // unplugged: nothing held any more
    r = PadReader{};
    return out;
  }
  const PadState& was = r.last.connected ? r.last : PadState{};
  auto pressed = [&](PadButton b) { return now.buttons[b] && !was.buttons[b]; };
  // Punches: the face buttons and the bumpers.
  constexpr std::pair<PadButton, const char*> kPunches[] = {
      {kPadX, "jab"},       {kPadY, "cross"}, {kPadA, "lead_hook"}, {kPadB, "rear_hook"},
      {kPadLeftBumper, "lead_uppercut"}, {kPadRightBumper, "rear_uppercut"}};
  for (const auto& [button, action] : kPunches)
    if (pressed(button)) out.add(action);
  // Defence: the triggers block and duck, the right stick slips.
  constexpr const char* kTriggerActions[2] = {"block", "duck"};
  for (int k = 0; k < 2; ++k) {
    const float pull = 0.5f * (now.axes[kPadLeftTrigger + k] + 1.0f);
    if (!r.trigger_on[k] && pull > kPressAt) r.trigger_on[k] = true, out.add(kTriggerActions[k]);
    else if (r.trigger_on[k] && pull < kReleaseAt) r.trigger_on[k] = false;
  }
  const float rx = now.axes[kPadRightX];
  const int slip = rx < -kPressAt ? -1 : rx > kPressAt ? 1 : std::abs(rx) < kReleaseAt ? 0 : r.slip_dir;
  if (slip != 0 && slip != r.slip_dir) out.add(slip < 0 ? "slip_left" : "slip_right");
  r.slip_dir = slip;
  // Footwork: a new direction steps at once, a held one every kStepRepeat s; pivots on the stick clicks.
  if (pressed(kPadLeftThumb)) out.add("pivot_left");
  if (pressed(kPadRightThumb)) out.add("pivot_right");
  const int dir = held_step(now, r.step_dir);
  if (dir >= 0 && (dir != r.step_dir || t >= r.next_step)) {
    out.add(kStepActions[dir]);
    r.next_step = t + kStepRepeat;
  }
  r.step_dir = dir;
  r.last = now;
  return out;
}

int pad_boxer(int rank, int pads_connected, bool versus, int player) {
  if (!versus) return player >= 0 ? player : 0;
  if (pads_connected == 1) return 1;
  return rank < 2 ? rank : -1;
}

}  // namespace boxing
