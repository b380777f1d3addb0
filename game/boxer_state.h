#pragma once
// The boxer's state machine. Control reads the STATE (a fallen QP boxer goes limp, its feet stop anchoring the clip,
// its steps stop being gated); the report's metrics only observe it.
//
//   Guard <──consciousness──> Stunned          (the match: game/match/match.h)
//   Guard / Stunned ──fall detected──> Down     (a fall the match did not call: reported as a fall without a hit
//                                                unless a punch landed in the 1.5 s before)
//   Guard / Stunned ──knockdown──> Falling ──fall detected──> Down   (the match: a heavy hit)
//   Down ──lying still──> GettingUp ──up in guard──> Guard           (the match: the count and the stand-up)
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
// = FootContacts::other_link_on_ground. True on the tick the boxer goes down (from Guard, Stunned or Falling).
// The match's transitions (no detection): enter `to` now, for `reason`.
void boxer_state_enter(BoxerStateMachine& s, BoxerState to, double time, const char* reason);

bool boxer_state_update(BoxerStateMachine& s, const FallTuning& t, double pelvis_height, bool other_link_on_ground,
                        double time, double dt);

}  // namespace boxing
