#pragma once
// Every tuning value of the boxer's control, typed, with its default and a one-line why; the one defaults source
// (BoxerTuning{}). Lives in Boxer::settings, read every tick, so a UI panel can edit it live. The measurements behind
// the values: docs/decisions/ (one page per decision).
#include "engine/control/biped/foot_contacts.h"
#include "engine/control/biped/foot_geometry.h"
#include "engine/control/biped/lift_off_gate.h"
#include "engine/control/biped/step_planner.h"
#include "game/balance/pd_balance.h"
#include "game/balance/qp_balance.h"
#include "game/balance/stand_up.h"
#include "game/boxer_state.h"
#include "game/footwork.h"

namespace boxing {

// Placing the clip on the crates and keeping it on the feet (docs/decisions/stance-placement.md).
struct StanceTuning {
  double clip_forward = 0.05;     // m, the clip moved along the heading so both soles lie inside their own crates
  double base_tau = 0.3;          // s, low-pass of the clip's floor under the actual feet (balance QP's steps)
  double tiptoe_deadband = 0.01;  // m, a planted ankle this much higher over its sole than the clip's is pressed down
  double ankle_lever = 0.0;       // m, CoP ankle limit |tau| <= lever Fn (0 = off: 0.10 made every boxer fall)
  double ankle_min_torque = 10.0;  // N m, the CoP limit's floor (with ankle_lever > 0)
};

// Person space's free heading (docs/decisions/person-space-heading.md).
struct PersonSpaceTuning {
  double heading_tau = 1.0;  // s, the pelvis heading low-passed (a push's twist does not turn the desired pose)
  double face_gain = 0.1;    // 1/s, the heading steered toward facing the opponent (1.0: pushes fall)
};

// Applied once when the boxer is built (world.cpp): live edits take effect on the next build
// (docs/decisions/servo-setup.md).
struct ServoSetupTuning {
  double planted_twist_scale = 0.6;  // planted ankle's twist spring vs eq. 3's (0.3: slow yaw creep, falls)
  double servo_torque_limit = 0.0;   // N m per joint, 0 = none (400 tried: no better standing)
  double ankle_torque_limit = 0.0;   // N m planted ankle, 0 = none (80 tried: no better standing)
};

// The root spring / QP root assist (docs/decisions/balance-qp-tuning.md, servo-setup.md); set up in world.cpp.
struct RootTuning {
  double spring_max = 120.0;   // N m, the PD tilt spring's limit (--balance pd)
  double assist_max = 400.0;   // N m, the QP's root assist limit (scaled by consciousness every tick)
  double assist_price = 0.3;   // per (N m)^2, the assist in the QP's cost (below 0.3 the plan leans on it everywhere)
  double qp_torque_price = 1e-3;  // per (N m)^2, joint torques priced with the assist on (a 38 kN m knee otherwise)
};

struct BoxerTuning {
  eng::control::FootGeometry foot;
  eng::control::FootContactThresholds contact;
  eng::control::StepTuning step;
  eng::control::LiftOffGateTuning gate;
  eng::control::BalanceStepTuning balance_step;
  StanceTuning stance;
  PersonSpaceTuning person;
  PdBalanceTuning pd;
  BalanceQpTuning qp;
  FallTuning fall;
  ServoSetupTuning servo;
  RootTuning root;
  StandUpTuning stand_up;
  FootworkTuning footwork;
};

}  // namespace boxing
