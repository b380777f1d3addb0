#pragma once
// BALANCE STEPS: a step the balance takes on its own (not the clip's), when a push carries the capture point out of
// what the feet can hold. Yin & van de Panne 2006 (sec. IV) split a stepping recovery in three phases; here:
//   1. change of support: the leg the push unloads steps (Yin: "people step using the leg which is unloaded by the
//      push"; here the foot farther from the capture point, stepping_foot, which is that leg under a push), at once
//      (no weight shift: that leg carries little already), to where the body can stop: the capture point (Pratt et
//      al. 2006) predicted at touch-down plus a margin (CapturePoint), or where Kwon & Hodgins' inverted pendulum on
//      a cart comes to rest under LQR (InvertedPendulumLqr); onto a flat foothold on the crates (foothold.h).
//      Repeated while the capture point stays outside the new support: double and multi-step recoveries come out of
//      the same rule;
//   2. reduce momentum: the balance QP's com task over the new, wider support (the caller's);
//   3. return to the stance: once the com has nearly stopped (Yin's gamma = 0.15 m/s), a slower step puts the foot
//      farther from the com (the one the weight is off, so the shift before it is the shorter) where the stance has it
//      relative to the other foot (the boxer's guard), unless the feet already stand as the boxer can fight from
//      (return_keep_width).
// Pure functions over plain data; the game calls them each control tick (game/boxer_stepping.cpp).
#include <Eigen/Core>
#include <vector>

#include "engine/control/biped/foot_geometry.h"
#include "engine/control/biped/foothold.h"
#include "engine/control/biped/ground.h"
#include "engine/control/biped/support_polygon.h"  // outside_distance

namespace eng::control {

enum class StepPlacement { CapturePoint, InvertedPendulumLqr };

struct BalanceStepTuning {
  double trigger_margin = 0.02;  // m, the capture point this far outside the feet's soles' hull starts a step ...
  double min_speed = 0.15;       // m/s ... with the com moving at least this fast (a body at rest is not pushed)
  // ... beyond what a root assist holds in place (the match's root spring, torque-limited): an external moment tau on
  // the pelvis moves the centroidal moment pivot tau / (m g) beyond the feet (Popovic, Goswami & Herr 2005), so the
  // body holds a capture point that far out without a step; this share of that reach is added to trigger_margin
  double assist_reach_share = 0.5;
  double land_margin = 0.05;     // m, the landing's sole centre this far beyond the predicted capture point
  // m, and this far to the side, across the com's motion away from the stance foot: the capture point lands between the
  // feet, not on the new sole's edge (the com drifts sideways over a single support; landed on its line, the capture
  // point left the two feet's narrow hull after touch-down and a second, crossing step followed)
  double side_margin = 0.08;
  double min_duration = 0.26;    // s, the quickest swing (lift, travel, set down)
  double swing_speed = 2.2;      // m/s, mean horizontal swing speed: a longer step takes longer
  double lift = 0.06;            // m, the sole's clearance at mid-swing above the highest top on its way
  double press = 0.02;           // m, the landing's target this far into the top (it lands, not hovers)
  double max_reach = 0.75;       // m, sole centre to stance sole centre at most (a long lunge)
  double min_gap = 0.24;         // m, sole centre to stance sole centre at least (feet do not overlap)
  double cross_gap = 0.16;       // m, a landing across the stance foot's side keeps this far ahead / behind it ...
  double pass_clearance = 0.16;  // m, ... and the swing passing it keeps its sole centre this far from the stance's
  double replan_until = 0.4;     // the landing is re-planned every tick from the body's state until this fraction of the swing
  double replan_move = 0.02;     // m, ... and the foothold searched again when the plan moved this far
  // ... or, while a push still accelerates the com by more than push_acc (m/s^2; the push observer's, ~150 N on the
  // boxer), until push_replan_until: a landing frozen while the push still acted came down short. 0.4 s pushes of
  // Yin's momentum (forward 207 N, sideways 197 N), seeds 1-48: 127 of 144 stood, 109 without; Yin's own 0.2 s pushes
  // as before (docs/decisions/balance-steps.md, seventh round)
  double push_acc = 2.0;
  double push_replan_until = 0.6;
  double push_filter_tau = 0.01;  // s, the observer's low-pass
  double late = 0.15;            // s, a swing not touching down this long after its duration is set down anyway
  double settle_speed = 0.15;    // m/s, com speed under which the return phase may start (Yin's gamma)
  double settle_time = 0.4;      // s, ... for this long, after the last landing
  double return_tolerance = 0.10;  // m, a foot this far from its stance place relative to the other returns
  // m, ... unless the feet stand as the body can fight from: the left foot this far left of the right (across the
  // heading; not crossed, not in line) and between min_gap and max_reach apart. A return step is a single support
  // from a wide stance, the recovery's riskiest phase: a forward push's step leaves the feet swapped, 0.9 m from the
  // guard's, and their return fell more often than the push.
  double return_keep_width = 0.10;
  double return_duration = 0.45;   // s, the return step's swing (unhurried)
  // The return step is the other foot's when this one's would land off the platform, on the floor, from a stance on a
  // crate (and the other's would not): returned where the stance has it relative to the other, a foot pushed near the
  // platform's edge stepped down 0.36 m to the floor and the boxer stood in a long lunge across the edge until its next
  // balance step failed (right 394 N, seed 3: fell at 9.8 s). Yin's five pushes, seeds 1-96, 14 s: 442 -> 447 of 480
  // stand, 10 returns changed, none fell that stood (docs/decisions/balance-steps.md, fifteenth round).
  bool return_onto_platform = true;
  bool replace_edge_foot = true;  // re-place a foot left on a poor foothold where no return is taken (boxer_stepping.cpp)
  // ... onto one good by both the clips' margins (the test of a poor one: the core 1.5 cm inside the top's sides) and
  // the balance step's clearance (its landing's search then finds it good as it is)
  FootholdParams replace_foothold = {.side_margin = 0.015, .clearance = 0.05, .sole = {}};
  // Once a return or re-placement lands and the body settles, the feet are looked at again, as at the recovery's end
  // (a return if the stance is not one to fight from, else a re-placement), at most this many times a recovery: a
  // return can land on an edge too (12 of 51 return landings on Yin's five pushes, seeds 1-20), and a re-placement
  // can leave the other foot on one. Yin's five, seeds 1-96, 14 s: a foot on an edge at the end for 107 of 455
  // standing with none, 87 with 1, 65 with 2, 57 with 4; 454 stand with any (docs/decisions/balance-steps.md,
  // eighteenth round).
  int follow_ups = 4;
  // m, it lifts once the capture point is this far inside the other sole. 4 cm was not reached by a fifth of the
  // shifts: the com came to rest 1-4 cm short of it and the shift was given up (Yin's pushes, seeds 1-40). 2 cm with
  // the com still moving (0.35 m/s, before return_lift_speed) ran off the stance toe's edge (match seed 19 with the
  // stagger); at rest it holds (docs/decisions/balance-steps.md, thirteenth round) ...
  double return_shift_margin = 0.02;
  // s, ... and is given up when the weight shift takes longer (1 s: a shift of 0.2-0.3 m at the balance QP's
  // return_shift_speed was given up before the com got there, and the feet stayed crossed to the end) ...
  double return_shift_max = 2.5;
  // m/s, ... and the com has come to rest over it (the shift done, not passing through: lifted with the com moving
  // at 0.35 m/s, the body ran on off the stance foot's edge; match seed 19 with the stagger; at 0.15 m/s, still
  // moving toward the stance foot's far side as the shift's target stopped, it ran off during the swing)
  double return_lift_speed = 0.06;
  // The swing leg lands with at most this share of its length (hip to ankle, knee straight) between its hip and the
  // landing's ankle: for a landing lower than that, the com comes down (the stance knee bends; step_reach_drop, the
  // balance QP's com height task, at most its max_com_acc). Held at the clip's height, the com stayed up (it rose 6 cm
  // as the body leaned over the stance foot's higher crate) and a crossing step sent to a top 0.22 m below the
  // stance's hung 10 cm over it, knee straight, until the swing's time ran out and the body fell (right 394 N, seed
  // 24). Yin's five pushes, seeds 1-48 / 49-96: 230 / 230 of 240 stand (225 / 218 without), and no landing is set
  // down by time (15 of 489 steps before, 9 of those runs fell). Shares 0.9, 0.93, 0.95, 0.97 and 1.0 (an earlier
  // build, seeds 1-48): 230, 229, 233, 232 and, on 49-96, 225 for 1.0 (docs/decisions/balance-steps.md, ninth round).
  double reach_share = 0.95;
  double reach_max_drop = 0.25;  // m, the com is sent at most this far below where it is
  int max_steps = 6;             // balance steps in one recovery (a multi-step stop), then the fall is let happen
  // Where a balance step may land (foothold.h): wider margins than the clips' steps, since a recovery's landing
  // misses by 5 cm (median; 14 cm at the 90th percentile): the sole's core 3.5 cm inside its top's sides (1.5) and no
  // higher top within 5 cm of the sole. With the clips' margins a fifth of the landings on the crates touched down
  // early (8% with these), a toe on the side of a higher crate or a sole on the platform's edge that slid off it
  // (docs/decisions/balance-steps.md, fourth round).
  FootholdParams foothold = {.side_margin = 0.035, .clearance = 0.05, .sole = {}};
  // InvertedPendulumLqr: Kwon & Hodgins' Q = diag(0, 30000, 30000, 0), R = 1 on (cart x, angle, cart v, angular v).
  double cart_mass_fraction = 0.15;  // the cart (the support: feet and shanks) as a fraction of the body's mass
};

// One balance step (or return step) under way. Positions are the sole centre (foot_geometry.h centre at sole height).
struct BalanceStep {
  bool active = false;
  bool returning = false;    // phase 3's step back to the stance
  int foot = -1;             // the stepping foot (0 or 1)
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero();  // sole centre, world x y
  // The path's bend around the stance foot: the middle control point of a quadratic Bezier from `from` to `to` is
  // their midpoint plus this (zero: a straight path).
  Eigen::Vector2d bow = Eigen::Vector2d::Zero();
  Eigen::Vector2d stance = Eigen::Vector2d::Zero();  // the stance foot's sole centre as the step started
  double pass_clearance = 0.0;  // m, the path's least distance from `stance` (0: no bend)
  double yaw = 0.0;          // the foot's heading (kept as it lifted)
  double from_top = 0.0, to_top = 0.0, path_top = 0.0;  // crate tops: where it lifts, where it lands, highest between
  double duration = 0.0, elapsed = 0.0;
  // The swing's timing, in fractions of its duration: the sole reaches its clearance at rise_until (<= 0.5) and moves
  // along the path from travel_from to 0.85. A balance step's are 0.3 and 0.1; a carried step up past a higher top's
  // edge rises before it travels (step_planner.cpp).
  double rise_until = 0.3, travel_from = 0.1;
  Eigen::Vector2d asked = Eigen::Vector2d::Zero();  // the landing as planned before the foothold's shift
};

// The recovery's bookkeeping between steps.
struct BalanceStepState {
  BalanceStep step;
  int steps_in_recovery = 0;  // steps since the last time the body stood still
  // A return or re-placement landed: the feet are looked at again once the body settles (BalanceStepTuning::follow_ups,
  // counted since the recovery's first step).
  bool follow_up = false;
  int follow_ups = 0;
  double settled = 0.0;       // s the com has been slower than settle_speed with its capture point in the support
  bool recovering = false;    // a recovery started and has not returned to the stance yet
  int shifting = -1;          // phase 3: this foot will step back once the weight is over the other (-1: none)
  double shift_time = 0.0;    // s shifting so far
  Eigen::Vector2d return_to = Eigen::Vector2d::Zero();  // where it steps back to (sole centre)
  // After the return step's hold on the com (its weight shift and swing, the caller's balance): the com target coming
  // back from where the hold left it to where the stance wants it (world x y), and for how long so far.
  bool settling = false;
  Eigen::Vector2d settle_target = Eigen::Vector2d::Zero();
  double settle_elapsed = 0.0;
  // The push observer (the caller's, after each physics step): the com's horizontal acceleration less what the
  // ground's contact forces give it, low-passed (push_filter_tau), and the com velocity it was differenced from.
  Eigen::Vector2d push_acc = Eigen::Vector2d::Zero(), push_vcom = Eigen::Vector2d::Zero();
  bool push_have_vcom = false;
};

// The linear inverted pendulum's natural frequency sqrt(g / z).
double lip_omega(double com_height, double g = 9.81);

// The capture point after time t with the centre of pressure held at p: xi(t) = p + (xi - p) e^{omega t}
// (the LIP's divergent component, Pratt et al. 2006 eq. 8).
Eigen::Vector2d capture_point_after(const Eigen::Vector2d& xi, const Eigen::Vector2d& p, double omega, double t);

// Yin's rule: the foot the com's motion unloads steps. load_line = foot 1's sole centre - foot 0's; the push moving
// the com toward foot 1 (v . load_line > 0) unloads foot 0.
int unloaded_foot(const Eigen::Vector2d& vcom, const Eigen::Vector2d sole[2]);

// The foot that steps when both stand: the one whose sole (its counter-clockwise hull) lies farther from the capture
// point xi; the other carries the body toward where it is going. For a push this is Yin's unloaded foot (the com and
// its capture point move toward the foot the push loads): on Yin's five pushes, seeds 1-48, this rule applied only
// below 0.7 m/s of com speed, or at every speed, stood and fell on the same runs. They differ when a first step has
// left a long diagonal stance, the com nearly at rest and its capture point drifting out across the feet's line: the
// velocity's direction then says little, Yin's rule lifted the foot nearer the capture point, and the swing over the
// far foot threw the com at 1 m/s (left 394 N, seeds 5 and 16; docs/decisions/balance-steps.md, eighth round).
// Ties: foot 0 stands.
int stepping_foot(const std::vector<Eigen::Vector2d> sole_hull[2], const Eigen::Vector2d& xi);

// Kwon & Hodgins' inverted pendulum on a cart, one axis, linearised about upright: state (cart x, pendulum angle,
// cart velocity, angular velocity), input the cart force; LQR with Q = diag(0, q, q, 0), R = 1. rest_offset returns
// where the cart (the support) comes to rest relative to where the com is now, for a com at height l moving at v
// over a cart under it (angle = offset / l). The gain is solved once per (l, masses) and cached by the caller.
struct CartPoleLqr {
  double l = 1.0, body_mass = 75.0, cart_mass = 11.0;
  Eigen::Matrix<double, 1, 4> K = Eigen::Matrix<double, 1, 4>::Zero();
};
CartPoleLqr solve_cart_pole_lqr(double l, double body_mass, double cart_mass, double q = 30000.0);
// The cart's rest position minus the com's position now, for com - cart = offset and com velocity v (one axis).
double cart_rest_offset(const CartPoleLqr& lqr, double offset, double v, double horizon = 8.0);

// Where a balance step lands (sole centre, world x y) and how long it swings, for the stepping foot from `from`,
// the stance foot's sole centre `stance`, its contact hull (the centre of pressure's reach) and the com state.
struct StepLanding {
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  double duration = 0.0;
};
StepLanding place_balance_step(StepPlacement how, const Eigen::Vector2d& com, const Eigen::Vector2d& vcom, double omega,
                               const Eigen::Vector2d& from, const Eigen::Vector2d& stance,
                               const std::vector<Eigen::Vector2d>& stance_hull, double heading,
                               const CartPoleLqr* lqr, const BalanceStepTuning& t);

// Starts a step of `foot` from `from` to `to` (sole centres) past the stance foot's sole centre `stance`: the landing
// moved onto a flat foothold on the crates (the sole's core on the highest top under it), the path bent to pass the
// stance foot at least pass_clearance from it, the tops along the way measured.
void start_balance_step(BalanceStep& s, int foot, bool returning, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                        const Eigen::Vector2d& stance, double pass_clearance, double yaw, double duration,
                        GroundHeight ground, const FootGeometry& g, const FootholdParams& fp);

// The swing's sole centre on its path (the quadratic Bezier from, from + (to - from) / 2 + bow, to) at e in [0, 1],
// and the path's derivative in e.
Eigen::Vector2d balance_step_path(const BalanceStep& s, double e, Eigen::Vector2d* d_de = nullptr);

// Re-aims a swing under way at a new landing (the body's state moved on: the push still acting, the stance foot's
// centre of pressure not where the plan put it): the foothold is searched again when it moved replan_move or more.
void replan_balance_step(BalanceStep& s, const Eigen::Vector2d& to, GroundHeight ground, const FootGeometry& g,
                         const FootholdParams& fp, const BalanceStepTuning& t);

// How far the hip must come down for a leg `leg` long (hip to ankle, knee straight) to reach `ankle` from `hip`
// with `share` of its length: 0 when it reaches already, at most max_drop (a landing too far out sideways is not
// reached by crouching).
double step_reach_drop(const Eigen::Vector3d& hip, const Eigen::Vector3d& ankle, double leg, double share,
                       double max_drop);

// The swing's sole-centre target at the step's elapsed time (world): horizontal C1 ease along the path, lifted
// over the path's highest top by `lift` mid-swing, set down `press` into the landing top at the end.
// Its velocity (the path's derivative at the elapsed time): the swing's feed-forward. (Differenced tick to tick
// instead, a re-planned landing's jump read as a 4-5 m/s kick and the foot overshot by 40 cm.)
// Its acceleration (the second derivative): the feed-forward's other half. A PD on position and velocity alone trails a
// reference that accelerates by a / omega^2; the ease stops the sole in the swing's last 15 %, at 50-100 m/s^2, and
// without it the foot ran on 3 cm past its landing (median, Yin's five pushes; docs/decisions/balance-steps.md).
Eigen::Vector3d balance_step_sole_target(const BalanceStep& s, const BalanceStepTuning& t,
                                         Eigen::Vector3d* velocity = nullptr, Eigen::Vector3d* acceleration = nullptr);

}  // namespace eng::control
