#include "engine/control/biped/lift_off_gate.h"

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

GateEvent lift_off_gate_decide(LiftGate& g, bool& swing, const std::vector<Eigen::Vector2d>& stance_points,
                               const Eigen::Vector2d& xi, double swing_left, double dt, const LiftOffGateTuning& t,
                               std::vector<Eigen::Vector2d>& hull) {
  bool open = false;
  if (stance_points.size() >= 2) {
    convex_hull_2d(stance_points, hull);
    open = (clamp_to_polygon(hull, xi, t.margin) - xi).norm() < 1e-9;  // inside the shrunk hull: clamping is a no-op
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
