#pragma once
// LIFT-OFF GATING. A clip's step lifts a foot on its own schedule; the physical body may not have its weight over
// the other foot yet, and a balance controller then has one foot's support for a com outside it. So a foot leaves
// the ground only when the capture point (capture_point.h) lies inside the other (stance) foot's contact hull, less
// a margin; until then it is held planted (`holding`: the caller moves the com target over the stance foot, the
// weight shift before a step). A step held longer than max_hold, or whose clip touch-down is nearer than min_swing,
// is skipped: the foot stays down until the clip lands it.
// A boxer's shuffle is not such a step: the clip lifts a foot for 0.13-0.15 s with the capture point 12-26 cm from
// the stance foot, falling onto the landing foot. So a QUICK step opens too when the body is capturable once the foot
// is down: during the swing the capture point runs away from the stance foot's centre of pressure p (the stance
// hull's point nearest it, where it runs slowest), xi(T) = p + (xi - p) e^(omega T) (Pratt et al. 2006 eq. 8,
// capture_point_after), and the step opens when xi at the clip's touch-down lies inside the hull of the stance
// contacts and the landing sole, less quick_margin. Measurements: docs/decisions/lift-off-gate.md.
//
// Per foot and tick, in two calls so the caller only builds the decision's inputs (stance contacts, capture point,
// the clip's time to touch-down) when a decision is due:
//   if (lift_off_gate_due(gate, swing, active)) event = lift_off_gate_decide(gate, swing, ...);
#include <Eigen/Core>
#include <vector>

namespace eng::control {

struct LiftOffGateTuning {
  double margin = 0.01;     // m, the capture point must lie this far inside the stance foot's hull (a step not near the edge)
  double max_hold = 0.25;   // s, a step held down longer is skipped (a weight shift that never comes)
  double min_swing = 0.12;  // s, a step opened later than this before the clip's touch-down is skipped (too short to swing)
  bool quick = true;              // quick steps: capturable at the touch-down (above)
  double quick_margin = 0.03;     // m, xi(T) this far inside the stance + landing hull
  double quick_max_swing = 0.3;   // s, a longer swing is not a quick step (xi(T) grows as e^(omega T))
};

// The clip's step, for the quick-step test: the landing sole's corners (floor x, y; empty: no quick step), the
// LIP's omega0 = sqrt(g / z) and, for a step that swings longer than the clip's (a carried step), its length.
struct ClipStep {
  const std::vector<Eigen::Vector2d>* landing = nullptr;
  double omega = 0.0;
  double swing = 0.0;  // s, the swing's own length when the step is not the clip's (a carried step); 0: the clip's
};

struct LiftGate {
  bool lifted = false;   // the foot left the ground for this step
  bool holding = false;  // the clip lifts it, it is held down (weight shift under way)
  bool skipped = false;  // held too long: this step is not taken (the foot stays planted until the clip lands it)
  bool quick = false;    // lifted as a quick step (capturable at the touch-down, not over the stance foot)
  double held = 0.0;     // s held so far
};

enum class GateEvent { None, StepTaken, StepSkipped };

// The bookkeeping before a decision: a foot the clip does not lift resets its gate; a lifted step, or an inactive
// gate (active = false: a fallen body), leaves `swing` as the clip has it; a skipped step keeps the foot down
// (swing = false). True when this tick needs lift_off_gate_decide.
bool lift_off_gate_due(LiftGate& g, bool& swing, bool active);

// The decision for a foot the clip lifts: stance_points are the stance foot's touching contact points (floor x, y;
// fewer than 2 never open), xi the capture point, swing_left the clip's time to touch-down (s). Opens (swing stays
// true, StepTaken) or holds (swing = false; StepSkipped once held past max_hold or too late). step: the quick-step
// test's inputs (none: only the weight-shift test). hull, pts: scratch (pts null: no quick test).
GateEvent lift_off_gate_decide(LiftGate& g, bool& swing, const std::vector<Eigen::Vector2d>& stance_points,
                               const Eigen::Vector2d& xi, double swing_left, double dt, const LiftOffGateTuning& t,
                               std::vector<Eigen::Vector2d>& hull, const ClipStep& step = {},
                               std::vector<Eigen::Vector2d>* pts = nullptr);

// The quick-step test alone: xi at the touch-down (swing_left from now, or step.swing when set) inside the stance +
// landing hull. hull: the stance + landing hull out (may be stance_hull itself: read first); pts: scratch.
bool quick_step_capturable(const std::vector<Eigen::Vector2d>& stance_hull, const Eigen::Vector2d& xi,
                           double swing_left, const ClipStep& step, const LiftOffGateTuning& t,
                           std::vector<Eigen::Vector2d>& pts, std::vector<Eigen::Vector2d>& hull);

}  // namespace eng::control
