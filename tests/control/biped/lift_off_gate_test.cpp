// The lift-off gate against hand-built stance contacts: a capture point inside the stance foot's hull (less the
// margin) opens the step, outside holds it, held past the limit (or too near the clip's touch-down) skips it.
#include "engine/control/biped/lift_off_gate.h"

#include <gtest/gtest.h>

#include "engine/control/biped/capture_point.h"

using namespace eng::control;
using V = Eigen::Vector2d;

namespace {
// A sole's four corners: x in [0, 0.26], y in [-0.05, 0.05].
std::vector<V> stance_sole() { return {V(0, -0.05), V(0.26, -0.05), V(0.26, 0.05), V(0, 0.05)}; }
}  // namespace

TEST(LiftOffGate, ACapturePointInsideTheStanceHullOpensTheStep) {
  LiftGate g;
  bool swing = true;
  std::vector<V> hull;
  ASSERT_TRUE(lift_off_gate_due(g, swing, true));
  const GateEvent e = lift_off_gate_decide(g, swing, stance_sole(), V(0.13, 0.0), 0.3, 1.0 / 240, {}, hull);
  EXPECT_EQ(e, GateEvent::StepTaken);
  EXPECT_TRUE(swing);
  EXPECT_TRUE(g.lifted);
  // Lifted: the next ticks need no decision and leave the swing alone.
  EXPECT_FALSE(lift_off_gate_due(g, swing, true));
  EXPECT_TRUE(swing);
}

TEST(LiftOffGate, ACapturePointWithinTheMarginOfTheEdgeHoldsTheFootDown) {
  LiftGate g;
  bool swing = true;
  std::vector<V> hull;
  LiftOffGateTuning t;
  t.margin = 0.01;
  // The margin moves each corner 1 cm toward the centroid (support_polygon.h): the edge y = 0.05 goes to
  // 0.05 (1 - 0.01 / |(0.13, 0.05)|) = 0.0464. A capture point at y = 0.047 is inside the hull but not inside that.
  const GateEvent e = lift_off_gate_decide(g, swing, stance_sole(), V(0.13, 0.047), 0.3, 0.01, t, hull);
  EXPECT_EQ(e, GateEvent::None);
  EXPECT_FALSE(swing);
  EXPECT_TRUE(g.holding);
  EXPECT_DOUBLE_EQ(g.held, 0.01);
}

TEST(LiftOffGate, AStepHeldLongerThanTheLimitIsSkippedAndStaysDown) {
  LiftGate g;
  std::vector<V> hull;
  LiftOffGateTuning t;
  t.max_hold = 0.25;
  const double dt = 0.01;
  int ticks = 0;
  GateEvent e = GateEvent::None;
  while (e == GateEvent::None && ticks < 100) {
    bool swing = true;
    if (!lift_off_gate_due(g, swing, true)) break;
    e = lift_off_gate_decide(g, swing, stance_sole(), V(0.6, 0.0), 1.0, dt, t, hull);  // capture point 34 cm ahead
    EXPECT_FALSE(swing);
    ++ticks;
  }
  EXPECT_EQ(e, GateEvent::StepSkipped);
  // held > 0.25 s first on the 26th tick of 10 ms (0.26 s); sums of 0.01 are not exact, so 25 or 26.
  EXPECT_GE(ticks, 25);
  EXPECT_LE(ticks, 26);
  EXPECT_TRUE(g.skipped);
  EXPECT_FALSE(g.holding);
  // Skipped: no more decisions; the foot is kept down while the clip still lifts it ...
  bool swing = true;
  EXPECT_FALSE(lift_off_gate_due(g, swing, true));
  EXPECT_FALSE(swing);
  // ... and the clip landing it resets the gate for the next step.
  swing = false;
  EXPECT_FALSE(lift_off_gate_due(g, swing, true));
  EXPECT_FALSE(g.skipped);
  EXPECT_EQ(g.held, 0.0);
}

TEST(LiftOffGate, AStepOpenedTooNearTheClipsTouchDownIsSkipped) {
  LiftGate g;
  bool swing = true;
  std::vector<V> hull;
  LiftOffGateTuning t;
  t.min_swing = 0.12;
  const GateEvent e = lift_off_gate_decide(g, swing, stance_sole(), V(0.13, 0.0), 0.10, 0.01, t, hull);
  EXPECT_EQ(e, GateEvent::StepSkipped);
  EXPECT_FALSE(swing);
}

TEST(LiftOffGate, FewerThanTwoStanceContactsNeverOpen) {
  LiftGate g;
  bool swing = true;
  std::vector<V> hull;
  const GateEvent e = lift_off_gate_decide(g, swing, {V(0.13, 0.0)}, V(0.13, 0.0), 0.3, 0.01, {}, hull);
  EXPECT_EQ(e, GateEvent::None);
  EXPECT_FALSE(swing);
}

TEST(LiftOffGate, AnInactiveGateLeavesTheClipsSwingAlone) {
  LiftGate g;
  bool swing = true;
  EXPECT_FALSE(lift_off_gate_due(g, swing, false));
  EXPECT_TRUE(swing);
}

TEST(CapturePoint, IsTheComPlusItsVelocityOverTheLinearPendulumsFrequency) {
  // z = 0.981 m, g = 9.81: omega0 = sqrt(10) rad/s; v = (0.5, -0.2) m/s.
  const V xi = capture_point(V(0.1, 0.2), V(0.5, -0.2), 0.981, 9.81);
  EXPECT_NEAR(xi.x(), 0.1 + 0.5 / std::sqrt(10.0), 1e-15);
  EXPECT_NEAR(xi.y(), 0.2 - 0.2 / std::sqrt(10.0), 1e-15);
  // At rest the capture point is the com itself.
  EXPECT_EQ(capture_point(V(0.3, -0.4), V::Zero(), 0.9), V(0.3, -0.4));
}

TEST(CapturePoint, ALipmStartedThereComesToRestOverIt) {
  // Integrate x'' = omega0^2 (x - p) with the foot p at the capture point: x -> p, v -> 0 (the divergent mode is zero).
  const double z = 0.9, g = 9.81, w2 = g / z;
  double x = 0.0, v = 0.4;
  const double p = capture_point(V(x, 0), V(v, 0), z, g).x();
  const double dt = 1e-5;
  for (int i = 0; i < 150000; ++i) {  // 1.5 s, semi-implicit Euler (the convergent mode decays to 0.7 %)
    v += dt * w2 * (x - p);
    x += dt * v;
  }
  EXPECT_NEAR(x, p, 2e-3);
  EXPECT_NEAR(v, 0.0, 1e-2);
}
