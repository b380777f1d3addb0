// The lift-off gate against hand-built stance contacts: a capture point inside the stance foot's hull (less the
// margin) opens the step, outside holds it, held past the limit (or too near the clip's touch-down) skips it.
#include "engine/control/biped/lift_off_gate.h"

#include <gtest/gtest.h>

#include "engine/control/biped/capture_point.h"
#include "engine/control/biped/support_polygon.h"

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

// QUICK STEPS. The stance sole above, the capture point 14 cm past its toe (xi = (0.40, 0)): the weight-shift test
// holds. With omega = 3.5 /s the capture point at the touch-down T s later is, in closed form (the centre of pressure
// at the toe, p = (0.26, 0)), xi(T) = 0.26 + 0.14 e^(3.5 T): 0.497 m at T = 0.15 s, 0.633 m at T = 0.28 s.
namespace {
std::vector<V> sole_at(double heel_x) {
  return {V(heel_x, -0.05), V(heel_x + 0.26, -0.05), V(heel_x + 0.26, 0.05), V(heel_x, 0.05)};
}
// That body's shuffle, 0.15 s to the touch-down, onto a landing sole whose heel is at heel_x.
GateEvent decide_shuffle(double heel_x, const LiftOffGateTuning& t, LiftGate& g, bool& swing) {
  std::vector<V> hull, pts;
  const std::vector<V> landing = sole_at(heel_x);
  return lift_off_gate_decide(g, swing, stance_sole(), V(0.40, 0.0), 0.15, 0.01, t, hull, {&landing, 3.5}, &pts);
}
}  // namespace

TEST(LiftOffGate, AQuickStepOpensWhenTheCapturePointAtTouchDownLiesInTheNewSupportAndHoldsWhenTheStepIsShort) {
  LiftOffGateTuning t;
  std::vector<V> hull;
  // A shuffle forward (landing sole from 0.45 to 0.71 m; xi(0.15) = 0.497 between the feet): opens, as a quick step.
  {
    LiftGate g;
    bool swing = true;
    EXPECT_EQ(decide_shuffle(0.45, t, g, swing), GateEvent::StepTaken);
    EXPECT_TRUE(swing);
    EXPECT_TRUE(g.quick);
  }
  // The same body, a short step (landing toe at 0.36 m, the capture point reaches 0.497): held down.
  {
    LiftGate g;
    bool swing = true;
    EXPECT_EQ(decide_shuffle(0.10, t, g, swing), GateEvent::None);
    EXPECT_FALSE(swing);
    EXPECT_TRUE(g.holding);
  }
  // Without the quick test (no landing given, or LiftOffGateTuning::quick off) the shuffle is held as before.
  {
    LiftGate g;
    bool swing = true;
    EXPECT_EQ(lift_off_gate_decide(g, swing, stance_sole(), V(0.40, 0.0), 0.15, 0.01, t, hull), GateEvent::None);
    LiftOffGateTuning off = t;
    off.quick = false;
    LiftGate g2;
    bool swing2 = true;
    EXPECT_EQ(decide_shuffle(0.45, off, g2, swing2), GateEvent::None);
  }
}

TEST(LiftOffGate, AQuickStepsSwingTimeDecidesHowFarTheCapturePointRunsBeforeTheFootLands) {
  LiftOffGateTuning t;
  std::vector<V> hull, pts, stance_hull;
  convex_hull_2d(stance_sole(), stance_hull);
  const std::vector<V> landing = sole_at(0.30);  // toe at 0.56 m
  const ClipStep step{&landing, 3.5};
  EXPECT_TRUE(quick_step_capturable(stance_hull, V(0.40, 0.0), 0.15, step, t, pts, hull));   // xi(T) = 0.497
  EXPECT_FALSE(quick_step_capturable(stance_hull, V(0.40, 0.0), 0.28, step, t, pts, hull));  // xi(T) = 0.633
  // Sideways the same: the capture point off the stance sole's side runs sideways, past a landing beside it.
  const std::vector<V> beside = {V(0.0, 0.20), V(0.26, 0.20), V(0.26, 0.30), V(0.0, 0.30)};
  EXPECT_TRUE(quick_step_capturable(stance_hull, V(0.13, 0.12), 0.15, {&beside, 3.5}, t, pts, hull));   // y(T) 0.17
  EXPECT_FALSE(quick_step_capturable(stance_hull, V(0.13, 0.20), 0.15, {&beside, 3.5}, t, pts, hull));  // y(T) 0.30
}

TEST(LiftOffGate, ACarriedStepIsJudgedByItsOwnSwingNotTheClips) {
  // The clip lands the foot in 0.15 s, capturable (xi(T) = 0.497, landing toe at 0.56 m); carried up a crate the
  // swing takes 0.28 s and the capture point runs to 0.633, past the landing: held down for the weight shift.
  LiftOffGateTuning t;
  std::vector<V> hull, pts, stance_hull;
  convex_hull_2d(stance_sole(), stance_hull);
  const std::vector<V> landing = sole_at(0.30);
  EXPECT_TRUE(quick_step_capturable(stance_hull, V(0.40, 0.0), 0.15, {&landing, 3.5, 0.0}, t, pts, hull));
  EXPECT_FALSE(quick_step_capturable(stance_hull, V(0.40, 0.0), 0.15, {&landing, 3.5, 0.28}, t, pts, hull));
  LiftGate g;
  bool swing = true;
  EXPECT_EQ(lift_off_gate_decide(g, swing, stance_sole(), V(0.40, 0.0), 0.15, 0.01, t, hull, {&landing, 3.5, 0.28}, &pts),
            GateEvent::None);
  EXPECT_TRUE(g.holding);
  // Its swing does not excuse a late opening: the clip's touch-down nearer than min_swing still skips it.
  LiftGate late;
  bool swing2 = true;
  EXPECT_EQ(lift_off_gate_decide(late, swing2, stance_sole(), V(0.05, 0.0), 0.5 * t.min_swing, 0.01, t, hull,
                                 {&landing, 3.5, 0.28}, &pts),
            GateEvent::StepSkipped);
}
