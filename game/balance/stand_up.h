#pragma once
// The stand-up (BoxerState::GettingUp, the match's get-up from the crates or the floor). The balance QP plans a body
// standing on its feet; lying, every link pressed on the ground, its torques make the limbs flail (qp_balance.cpp,
// down_or_getting_up). So a stand-up is tracked by the world-space servo's own torques (eq. 3, explicit,
// every bone toward the get-up clip) with the root assist: the paper's root spring (section V) with its position
// term, a force- and torque-limited spring-damper pulling the pelvis toward the clip's root (position and
// orientation), external, no reaction. Its use is reported per get-up (the report's match.getups[].root_assist_*).
#include "engine/control/servo/root_spring.h"
#include "game/balance/getup_plan.h"

namespace boxing {

struct BalanceTick;

struct StandUpTuning {
  eng::control::RootSpringParams assist = [] {
    eng::control::RootSpringParams p;
    p.enabled = true;
    p.omega_n = 4.0;        // rad/s, orientation
    p.zeta = 1.0;
    p.max_torque = 400.0;   // N m
    p.position_spring = true;
    p.pos_omega_n = 4.0;    // rad/s, position
    p.pos_zeta = 1.0;
    p.max_force = 1100.0;   // N (1.5 x the body weight, 75 kg)
    return p;
  }();
  // Share of the body's weight the assist carries as a feed-forward (the rest is the legs' and arms' work): without it
  // the position spring sags under the weight and the boxer stays crouched (docs/decisions/match-fight.md).
  double weight_share = 0.85;
  // N m per joint (vector norm): the servo's explicit leg gains, sized for moving the body over a planted foot, diverge
  // on a foot knocked loose when stronger (docs/decisions/balance-qp-code-history.md).
  double joint_torque_limit = 150.0;
  // --getup unassisted: the get-up the body does (unassisted_getup.h) instead of this carried one; its plan's tuning.
  bool unassisted = false;
  GetUpPlanTuning plan;
};

// Writes the servo's torques and the root assist into the physics data; b.ctl.root_torque / root_force: the assist.
void actuate_stand_up(BalanceTick& tick, const StandUpTuning& t);

}  // namespace boxing
