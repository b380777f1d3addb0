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
  // ... beyond what a root assist holds in place: this share of its reach tau / (m g) beyond the feet (the centroidal
  // moment pivot, Popovic, Goswami & Herr 2005) is added to trigger_margin
  double assist_reach_share = 0.5;
  double land_margin = 0.05;     // m, the landing's sole centre this far beyond the predicted capture point
  // m, and this far to the side, across the com's motion away from the stance foot: the capture point lands between the
  // feet, not on the new sole's edge (there it leaves the feet's narrow hull, and a crossing step follows)
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
  // ... or, while a push still accelerates the com by more than push_acc (m/s^2, the push observer's; ~150 N on the
  // boxer), until push_replan_until: a landing frozen while the push acts comes down short (balance-steps.md)
  double push_acc = 2.0;
  double push_replan_until = 0.6;
  double push_filter_tau = 0.01;  // s, the observer's low-pass
  double late = 0.15;            // s, a swing not touching down this long after its duration is set down anyway
  double settle_speed = 0.15;    // m/s, com speed under which the return phase may start (Yin's gamma)
  double settle_time = 0.4;      // s, ... for this long, after the last landing
  double return_tolerance = 0.10;  // m, a foot this far from its stance place relative to the other returns
  // m, ... unless the feet stand as the body can fight from: the left foot this far left of the right, min_gap to
  // max_reach apart (a return step, one foot from a wide stance, is the recovery's riskiest phase)
  double return_keep_width = 0.10;
  double return_duration = 0.45;   // s, the return step's swing (unhurried)
  // The other foot returns when this one's return would step off the platform to the floor from a crate (and the
  // other's would not): a lunge across the platform's edge is a poor stance for the next push (balance-steps.md)
  bool return_onto_platform = true;
  bool replace_edge_foot = true;  // re-place a foot left on a poor foothold where no return is taken (boxer_stepping.cpp)
  // ... onto one good by both the clips' margins (the test of a poor one: the core 1.5 cm inside the top's sides) and
  // the balance step's clearance (its landing's search then finds it good as it is)
  FootholdParams replace_foothold = {.side_margin = 0.015, .clearance = 0.05, .sole = {}};
  // The feet looked at again (return, else re-placement) after a return or re-placement lands, at most this many times
  // a recovery: a return can land on an edge too, a re-placement leave the other foot on one (balance-steps.md)
  int follow_ups = 4;
  // m, it lifts once the capture point is this far inside the other sole (a wider margin is often not reached: the com
  // comes to rest short of it; balance-steps.md) ...
  double return_shift_margin = 0.02;
  // s, ... and is given up when the weight shift takes longer (a 0.2-0.3 m shift at the balance QP's
  // return_shift_speed takes over 1 s) ...
  double return_shift_max = 2.5;
  // m/s, ... and the com has come to rest over it (the shift done, not passing through: a foot lifted with the com
  // still moving lets the body run on off the stance foot's edge)
  double return_lift_speed = 0.06;
  // The swing leg lands with at most this share of its length (hip to ankle) between hip and landing ankle: for a lower
  // landing the com comes down (the QP's step_reach_drop), else the leg hangs over it (balance-steps.md)
  double reach_share = 0.95;
  double reach_max_drop = 0.25;  // m, the com is sent at most this far below where it is
  int max_steps = 6;             // balance steps in one recovery (a multi-step stop), then the fall is let happen
  // Where a balance step may land (foothold.h): wider margins than the clips' steps (a recovery's landing misses by
  // ~5 cm): the sole's core 3.5 cm inside its top's sides, no higher top within 5 cm (balance-steps.md)
  FootholdParams foothold = {.side_margin = 0.035, .clearance = 0.05, .sole = {}};
  // InvertedPendulumLqr: Kwon & Hodgins' Q = diag(0, 30000, 30000, 0), R = 1 on (cart x, angle, cart v, angular v).
  double cart_mass_fraction = 0.15;  // the cart (the support: feet and shanks) as a fraction of the body's mass
};

// One balance step (or return step) under way. Positions are the sole centre (foot_geometry.h centre at sole height).
struct BalanceStep {
  bool active = false;
  bool returning = false;    // phase 3's step back to the stance
  // A deliberate step (the game's footwork) through phase 3's machinery: quick, the com not held over the stance foot
  // through its swing nor brought back slowly after it (the caller's balance reads it).
  bool quick = false;
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
  double return_duration = 0.0;  // s, this return's swing (0: BalanceStepTuning::return_duration)
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
// its capture point move toward the foot the push loads). They differ when a first step has left a long diagonal
// stance, the com nearly at rest and its capture point drifting out across the feet's line: the velocity's direction
// then says little, and Yin's rule would lift the foot nearer the capture point and swing it over the far foot
// (docs/decisions/balance-steps.md).
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
// instead, a re-planned landing's jump reads as a kick of metres per second and the foot overshoots.)
// Its acceleration (the second derivative): the feed-forward's other half. A PD on position and velocity alone trails a
// reference that accelerates by a / omega^2; the ease stops the sole in the swing's last 15 %, at 50-100 m/s^2, and
// without it the foot runs on past its landing (docs/decisions/balance-steps.md).
Eigen::Vector3d balance_step_sole_target(const BalanceStep& s, const BalanceStepTuning& t,
                                         Eigen::Vector3d* velocity = nullptr, Eigen::Vector3d* acceleration = nullptr);

}  // namespace eng::control
