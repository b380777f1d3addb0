#pragma once
// The boxer's steps (balance QP, BalanceController's plans_steps): stages of boxer_control, in this order each tick.
#include "engine/assets/character.h"
#include "engine/physics/data.h"
#include "engine/physics/model.h"
#include "game/arena.h"

namespace boxing {

struct Boxer;

// The clip's floor: the lower of the crate tops under the two feet where they actually are, low-passed
// (StanceTuning::base_tau): b.ctl.support_base.
void update_support_base(const eng::physics::Data& d, const Arena& arena, Boxer& b, double dt);
// Lift-off gating (lift_off_gate.h): clears swing[k] for a foot held down; counts steps taken / skipped.
void gate_lift_off(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   const Arena& arena, Boxer& b, bool swing[2], double dt);
// The step planner (step_planner.h) on the placed desired pose: b.ctl.step. A carried step (StepTuning::carry) keeps
// its foot swinging (swing[k] true) until it touches down, and down (false) until the clip's own swing ends.
void plan_steps(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, const Arena& arena, Boxer& b,
                bool swing[2], double dt);
// The push observer, after each physics step (its contact forces solved): the com's horizontal acceleration over the
// step less what the ground's contacts gave it, m a = F_ground + F_push (gravity is vertical): a push at the chest, a
// punch, a thrown crate, the player's hand. Low-passed into b.ctl.balance_steps.push_acc (m/s^2); read by
// take_balance_steps (a landing is re-planned until the push is over).
void observe_push(const eng::physics::Model& m, const eng::physics::Data& d, Boxer& b, double dt);
// The feet stand as the body can fight from (BalanceStepTuning::return_keep_width): the left sole's centre at least
// that far left of the right's across the stance's heading (not crossed, not in line) and the two between min_gap
// and max_reach apart. The return step's test (no return from such a stance), and the match AI's before footwork.
bool stance_can_fight(const eng::physics::Data& d, const Boxer& b);
// Foot k stands on a poor foothold: an edge of a higher top under its sole's core (foothold_ok, by the clips' margins,
// StepTuning::foothold), at its actual place and heading. The re-placement's test (BalanceStepTuning::replace_edge_foot).
bool on_poor_foothold(const eng::physics::Data& d, const Arena& arena, const Boxer& b, int k);
// Balance steps (balance_step.h), after plan_steps: a step of the balance's own overrides the clip's feet (swing,
// b.ctl.step) while it lasts; started when the capture point leaves the feet, or to return to the stance after.
void take_balance_steps(const eng::physics::Model& m, const eng::physics::Data& d,
                        const eng::assets::CharacterDesc& desc, const Arena& arena, Boxer& b, bool swing[2], double dt);

}  // namespace boxing
