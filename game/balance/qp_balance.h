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
#include "game/balance/getup_plan.h"

namespace boxing {

struct Boxer;
struct BalanceTick;

// Tuning (read every tick). Measurements: docs/decisions/balance-qp-tuning.md; the reasons behind the values, field by
// field: docs/decisions/balance-qp-code-history.md.
struct BalanceQpTuning {
  double com_omega = 6.0;             // rad/s, com PD natural frequency (critically damped)
  double momentum_damping = 4.0;      // 1/s, angular momentum about the com damped toward zero ...
  // ... at most this fast (N m): a tumbling or dragged body's momentum, damped faster, asks the arms for hundreds of
  // N m and whips them (docs/decisions/joint-speed.md); standing and fighting never reach it.
  double max_momentum_rate = 200.0;
  double mu = 0.6;                    // friction used in the plan (the crates and soles have 0.9: a margin)
  double planted_foot_weight = 50.0;  // kg m^2, a touching foot's orientation task (little effect 1-500)
  double touch_gap = 0.002;           // m, a contact closer than this carries load in the plan
  double land = 0.03;                 // m, a planted-but-hovering foot aims this far below where it is
  double support_margin = 0.03;       // m, the com target kept this far inside the support polygon
  double shift_margin = 0.03;         // m, a weight shift's target inside the stance foot (lift-off gate)
  double max_com_speed = 1.0;         // m/s, the desired com velocity's bound
  double swing_weight = 1000.0;       // per kg of foot, a swing foot's ankle task (10: lands 10-16 cm off)
  double max_swing_speed = 3.0;       // m/s, the swing foot's feed-forward velocity bound
  double balance_step_omega = 25.0;   // rad/s, a balance step's swing tracked this stiffly (the servo's 15: lands late)
  double balance_step_speed = 4.5;    // m/s, its feed-forward velocity bound
  // A carried or return step's horizontal path acceleration fed forward to its swing task, times this: without it
  // the PD trails the path's stop by a / omega^2 and the sole runs past its landing (docs/decisions/balance-steps.md).
  double swing_acc_feed_forward = 1.0;
  // ... and a balance step's own swing (phase 1), times this: none; its landing margins are tuned on the overshoot.
  double balance_step_acc_feed_forward = 0.0;
  // The com / momentum tasks' price during a balance step's swing (1: the upper body is thrown against the catch).
  double balance_step_com_scale = 0.3;
  bool balance_step_relative = true;   // its swing foot's task relative to the pelvis (QpPointTask::ref_body)
  // The return step's weight shift (balance_step.h phase 3): its com target moves over the other foot at most this
  // fast (set there at once, the com runs off the stance's far side), and back to the clip's as fast afterwards ...
  double return_shift_speed = 0.2;    // m/s
  double return_settle_time = 2.0;    // s, ... for at most this long
  double max_com_acc = 6.0;           // m/s^2, the desired com acceleration's bound
  // With a root assist and no hands on the body, the com task asks the ground only for the horizontal acceleration its
  // centre of pressure can give cop_margin inside the contacts, not the assist (com-acceleration-in-support.md).
  bool com_acc_in_support = true;
  double cop_margin = 0.02;           // m
  double cop_ramp = 0.04;             // m, the com within cop_margin of an edge: its demand ramps to the assist over this
  // Kudoh's priorities (thesis sec. 3), while the boxer stands on its support (actuate): the trunk's orientation tasks
  // priced trunk_weight times a limb's, the com / momentum tasks com_weight times the engine's unit price. 1 / 1 = off;
  // the match fights with 100 / 30 (match_setup; docs/decisions/match-fight.md, docs/decisions/balance-steps.md).
  double trunk_weight = 1.0;
  double com_weight = 1.0;
  // The arms back to their pose after Kudoh's priorities spun them, once the com is slower than arm_return_com_speed
  // for arm_return_after: each arm tracks a target arm_return_step ahead (slow, so the trunk and legs take the reaction),
  // priced arm_return_weight times its inertia; 0 = off (docs/decisions/balance-steps.md).
  double arm_return_weight = 10.0;
  double arm_return_step = 0.5;        // rad
  double arm_return_com_speed = 0.15;  // m/s
  double arm_return_after = 1.0;       // s
  // The feet's joint limits in the plan (BalanceQpParams::w_limit), per (rad/s^2)^2 while the com is slower than
  // limit_calm_speed, fading to none at twice that (10: the cross drill's rear foot slides twice as far; 1000 as 100).
  double limit_weight = 100.0;
  double limit_calm_speed = 0.3;      // m/s
  double stance_drop = 0.04;          // m, the desired root this much below the clip's (knees bent deeper)
  double joint_torque_limit = 500.0;  // N m per joint (vector norm): a guard, never reached in play
  // Losing its balance (fewer than min_support_contacts, or tilted past losing_balance_tilt): each joint's strength
  // falls with its speed (joint_strength.h, Hill), full to 20 rad/s, none past 30 (docs/decisions/joint-speed.md).
  eng::control::TorqueVelocityLimit speed_strength{20.0, 30.0};
  // ... and during a balance step the arms' a looser one (the rest of the body has none there: it must move fast).
  eng::control::TorqueVelocityLimit step_arm_strength{25.0, 40.0};
  double losing_balance_tilt = 30.0 * M_PI / 180.0;  // rad
  int min_support_contacts = 3;       // fewer contact points in the plan: no support polygon ...
  double few_contacts_task_scale = 1e-2;  // ... and the com / momentum tasks priced this much lower
  int recovery_support_contacts = 2;  // ... but in a push's recovery (balance steps) from fewer than this only
  // The legs kept off each other (add_leg_clearance): a separation task where a left-leg geom is within leg_clearance
  // of a right-leg one, priced leg_clearance_weight per kg of the pair's reduced mass; 0 = off (balance-steps.md).
  double leg_clearance = 0.03;         // m
  double leg_clearance_omega = 10.0;   // rad/s, the separation's stiffness (critically damped)
  double leg_clearance_weight = 300.0; // per kg (100 or 1000: fewer pushes stand)
  bool leg_clearance_thighs = true;    // the thighs' pairs too (they also collide: set_self_colliding)
  bool leg_clearance_in_step = false;  // during a balance step's swing too (off: the capture's cross-over passes)
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
  GetUpPlan getup;                         // --getup unassisted: the get-up under way (unassisted_getup.h)
};

inline void adjust_desired(QpBalance&, BalanceTick&) {}  // the QP plans the com itself
// After the servo's targets: the QP's inputs built, solved, its torques written to d.tau.
void actuate(QpBalance& q, BalanceTick& t);
inline double stance_rise(const QpBalance&, const Boxer&) { return 0.0; }  // the rear leg bends up instead
double stance_drop(const QpBalance&, const Boxer& b);
inline constexpr bool plans_steps(const QpBalance&) { return true; }     // lift-off gate and step planner
inline constexpr bool model_springs(const QpBalance&) { return false; }  // the QP writes every joint torque

}  // namespace boxing
