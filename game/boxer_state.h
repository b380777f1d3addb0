#pragma once
// The boxer's state machine. Control reads the STATE (a fallen QP boxer goes limp, its feet stop anchoring the clip,
// its steps stop being gated); the report's metrics only observe it.
//
//   Guard ──fall detected──> Down
//
// Stunned, Falling and GettingUp are the match's states (a knock-out's wobble, the fall itself, the stand-up); no
// transition reaches them yet.
#include <string>

namespace boxing {

enum class BoxerState { Guard, Stunned, Falling, Down, GettingUp };

const char* boxer_state_name(BoxerState s);

// When a fall is detected (docs/decisions/fall-detection.md).
struct FallTuning {
  double low_pelvis = 0.5;   // the pelvis below this share of its standing height above the support
  double ground_time = 0.2;  // s, a link other than feet and shanks touching the ground this long
};

struct BoxerStateMachine {
  BoxerState state = BoxerState::Guard;
  double since = 0.0;            // s, simulation time the state was entered
  const char* reason = "";       // why the last transition happened
  double standing_height = 0.0;  // m, pelvis above its support at the start (the first update)
  bool have_standing_height = false;
  double ground_contact_time = 0.0;  // s, continuous time a non-foot, non-shank link touches crates / floor
  bool fallen() const { return state == BoxerState::Falling || state == BoxerState::Down; }
};

// One update after a physics step: pelvis_height = the pelvis above the stance's lower crate (m), other_link_on_ground
// = FootContacts::other_link_on_ground. True on the tick the boxer goes down.
bool boxer_state_update(BoxerStateMachine& s, const FallTuning& t, double pelvis_height, bool other_link_on_ground,
                        double time, double dt);

}  // namespace boxing
