#pragma once
// The unassisted get-up (--getup unassisted; issue 63): the balance QP on a body getting up from the crates, with its
// contacts on the links the get-up plan's current phase names as supports (hands, forearms, knees, shins, feet,
// buttocks: getup_plan.h), the com moved quasi-statically over the next phase's support, every bone tracking the
// get-up clip, each joint's torque within a person's strength (person_strength.h), and no external force: the only
// help is the QP's root assist, a torque (the seed paper's root spring, section V), at most
// GetUpPlanTuning::max_root_torque. The assisted get-up (--getup assisted, the default) is stand_up.h.
namespace boxing {

struct QpBalance;
struct BalanceTick;

// While BoxerState::GettingUp: the plan started (from how the boxer lies) or advanced, the QP solved, its torques
// written to the boxer's DoFs (the root rows: the root assist's torque only), b.ctl.clip_rate set for the next tick.
// Off the ground (no link touching) the body is limp, as the assisted get-up's.
void actuate_unassisted_getup(QpBalance& q, BalanceTick& tick);

// Not getting up: the plan dropped and the clip played at its own speed again.
void end_unassisted_getup(QpBalance& q, BalanceTick& tick);

}  // namespace boxing
