#include "engine/control/biped/lift_off_gate.h"

#include "engine/control/biped/balance_step.h"
#include "engine/control/biped/support_polygon.h"

namespace eng::control {

bool lift_off_gate_due(LiftGate& g, bool& swing, bool active) {
  if (!swing) {
    g = LiftGate{};
    return false;
  }
  if (g.lifted || !active) return false;
  if (g.skipped) {
    swing = false;
    return false;
  }
  return true;
}

bool quick_step_capturable(const std::vector<Eigen::Vector2d>& stance_hull, const Eigen::Vector2d& xi,
                           double swing_left, const ClipStep& step, const LiftOffGateTuning& t,
                           std::vector<Eigen::Vector2d>& pts, std::vector<Eigen::Vector2d>& hull) {
  if (step.swing > 0.0) swing_left = step.swing;
  if (!t.quick || !step.landing || step.landing->empty() || stance_hull.empty() || swing_left > t.quick_max_swing)
    return false;
  const Eigen::Vector2d p = clamp_to_polygon(stance_hull, xi, 0.0);
  const Eigen::Vector2d xi_T = capture_point_after(xi, p, step.omega, swing_left);
  pts.assign(stance_hull.begin(), stance_hull.end());
  pts.insert(pts.end(), step.landing->begin(), step.landing->end());
  convex_hull_2d_in_place(pts, hull);
  return (clamp_to_polygon(hull, xi_T, t.quick_margin) - xi_T).norm() < 1e-9;
}

GateEvent lift_off_gate_decide(LiftGate& g, bool& swing, const std::vector<Eigen::Vector2d>& stance_points,
                               const Eigen::Vector2d& xi, double swing_left, double dt, const LiftOffGateTuning& t,
                               std::vector<Eigen::Vector2d>& hull, const ClipStep& step,
                               std::vector<Eigen::Vector2d>* pts) {
  bool open = false;
  if (stance_points.size() >= 2) {
    convex_hull_2d(stance_points, hull);
    open = (clamp_to_polygon(hull, xi, t.margin) - xi).norm() < 1e-9;  // inside the shrunk hull: clamping is a no-op
    if (!open && pts) g.quick = open = quick_step_capturable(hull, xi, swing_left, step, t, *pts, hull);
  }
  if (open && swing_left >= t.min_swing) {
    g.lifted = true, g.holding = false;
    return GateEvent::StepTaken;
  }
  g.holding = true;
  g.held += dt;
  swing = false;
  if (g.held > t.max_hold || swing_left < t.min_swing) {
    g.skipped = true, g.holding = false;
    return GateEvent::StepSkipped;
  }
  return GateEvent::None;
}

}  // namespace eng::control
