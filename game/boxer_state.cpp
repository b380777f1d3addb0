#include "game/boxer_state.h"

namespace boxing {

const char* boxer_state_name(BoxerState s) {
  switch (s) {
    case BoxerState::Guard: return "guard";
    case BoxerState::Stunned: return "stunned";
    case BoxerState::Falling: return "falling";
    case BoxerState::Down: return "down";
    case BoxerState::GettingUp: return "getting-up";
  }
  return "?";
}

void boxer_state_enter(BoxerStateMachine& s, BoxerState to, double time, const char* reason) {
  s.state = to;
  s.since = time;
  s.reason = reason;
}

bool boxer_state_update(BoxerStateMachine& s, const FallTuning& t, double pelvis_height, bool other_link_on_ground,
                        double time, double dt) {
  if (!s.have_standing_height) s.standing_height = pelvis_height, s.have_standing_height = true;
  s.ground_contact_time = other_link_on_ground ? s.ground_contact_time + dt : 0.0;
  if (s.state == BoxerState::Down || s.state == BoxerState::GettingUp) return false;
  const char* reason = nullptr;
  if (pelvis_height < t.low_pelvis * s.standing_height)
    reason = "pelvis below half its standing height";
  else if (s.ground_contact_time > t.ground_time)
    reason = "a link other than feet and shanks touched the ground for 0.2 s";
  if (!reason) return false;
  s.state = BoxerState::Down;
  s.since = time;
  s.reason = reason;
  return true;
}

}  // namespace boxing
