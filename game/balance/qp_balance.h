#pragma once
// The balance QP controller (--balance qp, the default): joint torques for the whole body from
// engine/control/balance/balance_qp.h (contacts, com and momentum tasks, eq. 3 per bone as accelerations, swing
// feet toward their steps), the root spring as the QP's root assist. One of the two balance controllers
// (balance_controller.h).
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/control/balance/balance_qp.h"
#include "engine/control/servo/joint_strength.h"
#include "engine/core/latency_histogram.h"

namespace boxing {

struct Boxer;
struct BalanceTick;

// Tuning (read every tick). Measurements: docs/decisions/balance-qp-tuning.md.
struct BalanceQpTuning {
  double com_omega = 6.0;             // rad/s, com PD natural frequency (critically damped)
  double momentum_damping = 4.0;      // 1/s, angular momentum about the com damped toward zero ...
  // ... at a rate of at most this (N m). A boxer yanked by a strong drag or tumbling carries 50+ kg m^2/s; damping it
  // at 4 /s asked the arms, the only links free to give it, for hundreds of N m: they whipped at 60-120 rad/s (gloves
  // 30-38 m/s, the chaos soak). Standing and fighting it never binds (the match sweep is the same bit for bit).
  double max_momentum_rate = 200.0;
  double mu = 0.6;                    // friction used in the plan (the crates and soles have 0.9: a margin)
  double planted_foot_weight = 50.0;  // kg m^2, a touching foot's orientation task (little effect 1-500)
  double touch_gap = 0.002;           // m, a contact closer than this carries load in the plan
  double land = 0.03;                 // m, a planted-but-hovering foot aims this far below where it is
  double support_margin = 0.03;       // m, the com target kept this far inside the support polygon
  double shift_margin = 0.03;         // m, a weight shift's target inside the stance foot (lift-off gate)
  double max_com_speed = 1.0;         // m/s, the desired com velocity's bound
  double swing_weight = 1000.0;       // per kg of foot, a swing foot's ankle task (10: landed 10-16 cm off)
  double max_swing_speed = 3.0;       // m/s, the swing foot's feed-forward velocity bound
  double balance_step_omega = 25.0;   // rad/s, a balance step's swing tracked this stiffly (the servo's 15: landed late)
  double balance_step_speed = 4.5;    // m/s, its feed-forward velocity bound
  // A carried or return step's path acceleration (balance_step_sole_target), horizontal, as the swing task's
  // feed-forward, times this. Without it the PD trails the ease's stop by a / omega^2 and the sole ran on past its
  // landing: a return step landed 3.4 cm from its plan (median), 0.4 cm with it (Yin's five pushes, seeds 1-96). Not
  // the set-down's vertical part: fed forward, the sole met the top before its horizontal travel ended (a balance
  // step's landing 15 cm short at the 10th percentile).
  double swing_acc_feed_forward = 1.0;
  // ... and a balance step's own swing (phase 1), times this: none. Its landing margins were tuned on the overshoot
  // (it landed 4 cm beyond its plan, median); fed forward, a long swing re-planned farther out (0.9 m in 0.26 s), the
  // foot behind its path, was braked short of it and forward pushes fell (91 of 96 stood, against 96); braked only
  // when not behind, sideways pushes stood 362 of 420 against 372 (docs/decisions/balance-steps.md, seventeenth round).
  double balance_step_acc_feed_forward = 0.0;
  // the com / momentum tasks' price during its swing (1: fewer pushes survived; 0.1 before the com fell as the LIP)
  double balance_step_com_scale = 0.3;
  bool balance_step_relative = true;   // its swing foot's task relative to the pelvis (QpPointTask::ref_body)
  // The return step's weight shift (balance_step.h phase 3): the com target moves over the other foot at most this fast.
  // Set there at once, the com ran 0.4 m/s off the far side of a post-step stance 0.5 m wide and the return fell.
  // When the return's hold ends (its touch-down, or the shift given up) the target comes back to the clip's as fast,
  // for at most return_settle_time.
  double return_shift_speed = 0.2;    // m/s
  double return_settle_time = 2.0;    // s
  double max_com_acc = 6.0;           // m/s^2, the desired com acceleration's bound
  // With a root assist (the match's and the walks' root spring), the com task asks the ground only for the horizontal
  // acceleration its centre of pressure can give: scaled down until that lies cop_margin inside the contacts
  // (support_polygon.h ground_com_acceleration). Asked for more, the plan bought the rest from the assist: a clip's
  // own lean or lunge (slip_right, the uppercuts, the hooks) took 60-100 N m rms of it while they played, most of the
  // walks' assist (docs/decisions/com-acceleration-in-support.md). Not while the player's hands act on the body (their
  // force moves the com too), and not without the assist (the push lab): there nothing can buy the rest and the plan
  // trades it against the arms' and trunk's tracking (Kudoh's strategy); the lab was not measured with the limit.
  bool com_acc_in_support = true;
  double cop_margin = 0.02;           // m
  // ... and with the com itself within cop_margin of an edge (nothing free there), the com task's demand goes to the
  // assist in a ramp, all of it cop_ramp further out (support_polygon.h). Handed over at once (0), it came in 230 N m
  // bursts, most of what was left of the walks' assist (docs/decisions/com-acceleration-in-support.md, second round).
  double cop_ramp = 0.04;             // m
  // Kudoh's priorities (qp-balance-kudoh-thesis section 3: the trunk's posture held above the com's place): the
  // trunk's orientation tasks (pelvis, abdomen, chest, neck, head) priced trunk_weight times a limb's per unit of
  // inertia, the com / momentum tasks com_weight times the engine's unit price, while the boxer stands on its support
  // (actuate). The match's boxers fight with 100 / 30 (match_setup): at 1 / 1 the com task outweighed the trunk, a
  // boxer rocked by a hit or by its own blocked punch folded at the waist and fell, fought on stunned and landed 6-10
  // a match. Off (1 / 1) elsewhere: on, balance steps after 400 N from behind fell (3 of 3), a head dragged sideways
  // floored the boxer after release and the chaos soak's drags whipped limbs to 32-45 m/s. Measured in
  // docs/decisions/match-fight.md and docs/decisions/balance-steps.md.
  double trunk_weight = 1.0;
  double com_weight = 1.0;
  // The arms back to their pose after the trunk priority spun them (Kudoh's priorities on, the com slower than
  // arm_return_com_speed for arm_return_after): each upper arm and forearm tracks a target at most arm_return_step
  // ahead of where it is (a carrot, so the return is slow and the trunk and legs take its reaction), priced
  // arm_return_weight times its inertia. Why: after Kudoh's 500 N from behind the trunk priority holds the trunk with
  // the arms as reaction wheels, and they stayed 1.6-2.0 rad off for good (the com task outweighs their tracking);
  // brought back at full gain they threw the boxer over; priced up without the carrot they stay
  // (docs/decisions/balance-steps.md). 0 = off.
  double arm_return_weight = 10.0;
  double arm_return_step = 0.5;        // rad
  double arm_return_com_speed = 0.15;  // m/s
  double arm_return_after = 1.0;       // s
  // The feet's joint limits in the plan (BalanceQpParams::w_limit, actuate): priced limit_weight per (rad/s^2)^2 while
  // the com is slower than limit_calm_speed, fading to none at twice that, none in a balance step's recovery or in the
  // player's hands.
  double limit_weight = 100.0;        // (10: the cross drill's rear foot slid twice as far; 1000 as 100)
  double limit_calm_speed = 0.3;      // m/s
  double stance_drop = 0.04;          // m, the desired root this much below the clip's (knees bent deeper)
  double joint_torque_limit = 500.0;  // N m per joint (vector norm): a guard, never reached in play
  // While the boxer is losing its balance (fewer than min_support_contacts, or the pelvis tilted more than
  // losing_balance_tilt from the desired), each joint's strength falls with its speed (joint_strength.h, Hill): full
  // to 20 rad/s, none driving it past 30. A plan that spun the arms as reaction wheels no longer can.
  eng::control::TorqueVelocityLimit speed_strength{20.0, 30.0};
  // ... and during a balance step the arms' (upper arm, forearm, glove) a looser one, where the rest of the body has
  // none: a stunned boxer tilting 45 deg over a step spun an arm back from 180 deg off its pose, the glove at 38 m/s
  // (the chaos soak, match seed 7 at 229.8 s, no hands on it; 29 m/s with this). Yin's five pushes, seeds 1-8: 40 of
  // 40 as without it; seeds 1-48: 229 of 240 against 230 (docs/decisions/joint-speed.md).
  eng::control::TorqueVelocityLimit step_arm_strength{25.0, 40.0};
  double losing_balance_tilt = 30.0 * M_PI / 180.0;  // rad
  int min_support_contacts = 3;       // fewer contact points in the plan: no support polygon ...
  double few_contacts_task_scale = 1e-2;  // ... and the com / momentum tasks priced this much lower
  int recovery_support_contacts = 2;  // ... but in a push's recovery (balance steps) from fewer than this only
  // The legs kept off each other (actuate, add_leg_clearance): a left-leg geom within leg_clearance of a right-leg one
  // gets a separation task, the two points' relative acceleration along their normal at leg_clearance_omega^2
  // (leg_clearance + depth) - 2 leg_clearance_omega v_n (none where that is negative: already parting fast enough),
  // priced leg_clearance_weight per kg of the pair's reduced mass. Not during a balance step's swing (the capture's
  // cross-over must pass the stance leg; with it there, Yin's five on seeds 1-40 stood 185 of 200 at 8 s against 193).
  // Measured: docs/decisions/balance-steps.md, sixteenth round. 0 = off.
  double leg_clearance = 0.03;         // m
  double leg_clearance_omega = 10.0;   // rad/s
  double leg_clearance_weight = 300.0; // per kg (100: the bar's seed 7 left 394 N falls; 1000: 187 of 200 at 14 s)
  bool leg_clearance_thighs = true;    // the thighs' pairs too (they also collide: set_self_colliding)
  bool leg_clearance_in_step = false;  // during a balance step's swing too
};

// The leg clearance's separation tasks a tick at most (BalanceQpTuning::leg_clearance*; reserved by the world, so a
// recovery's crossed legs allocate nothing): 3 x 3 leg geom pairs, 4 points each, with room.
inline constexpr int kMaxLegSeparations = 64;

// The controller's state and workspace (inputs rebuilt every tick, capacity kept).
struct QpBalance {
  eng::control::BalanceQpInput in;
  eng::control::BalanceQpParams params;  // prices and the root assist's limit (world.cpp, per tick the limit)
  std::vector<uint8_t> trunk;            // per bone: 1 for the trunk's (BalanceQpTuning::trunk_weight; world.cpp)
  std::vector<uint8_t> arm;              // per bone: 1 for an upper arm or forearm (BalanceQpTuning::arm_return_*)
  bool return_shift = false;              // the return step's weight shift under way: its com target ...
  Eigen::Vector2d return_shift_target = Eigen::Vector2d::Zero();  // ... moving over the other foot
  double slow_since = -1.0;              // s, the com slower than arm_return_com_speed since (< 0: not now)
  eng::control::BalanceQp ws;
  eng::control::BalanceQpResult out;
  long ticks = 0;
  eng::control::BalanceQpParams solve_params;  // this tick's prices (params, lowered on a poor support)
  Eigen::Vector3d com_d_rel_last = Eigen::Vector3d::Zero();  // desired com - desired support centre, last tick
  bool have_com_d = false;
  int support_set = 0;  // which feet were planted last tick (bit 0 left, bit 1 right)
  bool swing_prev[2] = {false, false};  // the foot was swinging last tick (swing feed-forward)
  Eigen::Vector3d swing_target_prev[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::vector<int> leg_geoms[2];           // each leg's geoms (thigh first), listed on the first tick (leg clearance)
  std::vector<Eigen::Vector2d> pts, hull;  // scratch: contact points on the floor, their hull
  std::vector<Eigen::Vector2d> ground_hull;  // this tick's hull of every ground contact (com_acc_in_support)
  eng::core::LatencyHistogram solve_us;    // wall-clock cost of each solve (report only)
};

inline void adjust_desired(QpBalance&, BalanceTick&) {}  // the QP plans the com itself
// After the servo's targets: the QP's inputs built, solved, its torques written to d.tau.
void actuate(QpBalance& q, BalanceTick& t);
inline double stance_rise(const QpBalance&, const Boxer&) { return 0.0; }  // the rear leg bends up instead
double stance_drop(const QpBalance&, const Boxer& b);
inline constexpr bool plans_steps(const QpBalance&) { return true; }     // lift-off gate and step planner
inline constexpr bool model_springs(const QpBalance&) { return false; }  // the QP writes every joint torque

}  // namespace boxing
