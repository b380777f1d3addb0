// Balance steps (engine/control/biped/balance_step.h): the linear inverted pendulum's capture point against its
// closed form, the cart-pole LQR against a simulation of the linearised system, the landing's rules (past the
// capture point, within reach, not across the stance foot), the foothold on uneven ground and the swing's path.
#include "engine/control/biped/balance_step.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "control/biped/boxes.h"
#include "engine/control/biped/support_polygon.h"

namespace {

using eng::control::BalanceStepTuning;
using Eigen::Vector2d;

// A rectangle sole hull (counter-clockwise) centred at c, 0.26 x 0.10 m, facing +x.
std::vector<Vector2d> sole_at(const Vector2d& c) {
  std::vector<Vector2d> pts = {c + Vector2d(-0.13, -0.05), c + Vector2d(0.13, -0.05), c + Vector2d(0.13, 0.05),
                               c + Vector2d(-0.13, 0.05)};
  std::vector<Vector2d> hull;
  eng::control::convex_hull_2d(pts, hull);
  return hull;
}

TEST(CapturePointAfter, MatchesTheLinearInvertedPendulumsClosedForm) {
  // x'' = w^2 (x - p): x(t) = p + (x0 - p) cosh(wt) + v0/w sinh(wt); xi(t) = x(t) + x'(t)/w.
  const double w = eng::control::lip_omega(0.95), t = 0.3;
  const Vector2d x0(0.1, -0.05), v0(0.6, 0.2), p(0.02, 0.01);
  const Vector2d x = p + (x0 - p) * std::cosh(w * t) + v0 / w * std::sinh(w * t);
  const Vector2d v = (x0 - p) * w * std::sinh(w * t) + v0 * std::cosh(w * t);
  const Vector2d xi = eng::control::capture_point_after(x0 + v0 / w, p, w, t);
  EXPECT_NEAR((xi - (x + v / w)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(w, std::sqrt(9.81 / 0.95), 1e-12);
}

TEST(UnloadedFoot, IsTheOneTheComMovesAwayFrom) {
  const Vector2d sole[2] = {Vector2d(0.0, 0.15), Vector2d(0.0, -0.15)};  // left, right
  EXPECT_EQ(eng::control::unloaded_foot(Vector2d(0.0, 0.5), sole), 1);   // pushed left: the right leg steps
  EXPECT_EQ(eng::control::unloaded_foot(Vector2d(0.0, -0.5), sole), 0);  // pushed right: the left leg steps
}

TEST(SteppingFoot, IsYinsUnloadedFootUnderAPushAndTheFootFartherFromTheCapturePointAtACrawl) {
  // Pushed left over a square stance: the capture point runs toward the left foot, the right one steps, as Yin's.
  std::vector<Vector2d> hull[2] = {sole_at(Vector2d(0.0, 0.15)), sole_at(Vector2d(0.0, -0.15))};
  EXPECT_EQ(eng::control::stepping_foot(hull, Vector2d(0.0, 0.45)), 1);
  EXPECT_EQ(eng::control::stepping_foot(hull, Vector2d(0.0, -0.45)), 0);
  // A long diagonal stance after a crossing step (left 394 N, seed 16, 2.96 s): the com at a crawl (0.19, 0.11) m/s,
  // its capture point 2 cm out across the feet's line. The velocity's component along the line is small and says the
  // left foot is loaded, so Yin's rule lifts the right foot and leaves the body over the left one, 0.39 m from the
  // capture point; the right sole is 0.26 m from it, so it stands and the left foot steps.
  const Vector2d left(-0.334, 0.130), right(-0.820, 0.809), xi(-0.515, 0.562);
  std::vector<Vector2d> diagonal[2] = {sole_at(left), sole_at(right)};
  const Vector2d sole[2] = {left, right};
  EXPECT_EQ(eng::control::unloaded_foot(Vector2d(0.19, 0.11), sole), 1);
  EXPECT_NEAR(eng::control::outside_distance(diagonal[0], xi), 0.385, 0.002);
  EXPECT_NEAR(eng::control::outside_distance(diagonal[1], xi), 0.263, 0.002);
  EXPECT_EQ(eng::control::stepping_foot(diagonal, xi), 0);
}

TEST(CartPoleLqr, StabilisesTheLinearisedPendulumAndBringsTheCartUnderTheCom) {
  const auto lqr = eng::control::solve_cart_pole_lqr(0.95, 64.0, 11.0);
  // Stabilising: a com 10 cm ahead of the cart, moving on at 0.5 m/s, ends at rest over the cart: the cart's rest
  // position is ahead of where the com is now (it runs under the falling body).
  const double ahead = eng::control::cart_rest_offset(lqr, 0.10, 0.5);
  EXPECT_GT(ahead, 0.0);
  // Converged: a longer horizon does not move it.
  EXPECT_NEAR(eng::control::cart_rest_offset(lqr, 0.10, 0.5, 16.0), ahead, 1e-3);
  // Linear in the state (a linear closed loop): the rest position (offset + this) doubles with the state; mirrored,
  // mirrored.
  EXPECT_NEAR(eng::control::cart_rest_offset(lqr, 0.20, 1.0) + 0.20, 2.0 * (ahead + 0.10), 1e-6);
  EXPECT_NEAR(eng::control::cart_rest_offset(lqr, -0.10, -0.5), -ahead, 1e-9);
  // Faster com, farther rest.
  EXPECT_GT(eng::control::cart_rest_offset(lqr, 0.0, 1.0), eng::control::cart_rest_offset(lqr, 0.0, 0.5));
}

TEST(PlaceBalanceStep, LandsPastTheCapturePointAtTouchDown) {
  BalanceStepTuning t;
  const double w = eng::control::lip_omega(0.95);
  const Vector2d stance(0.0, 0.12), from(-0.1, -0.12), com(0.05, 0.0), v(0.6, 0.0);
  const auto hull = sole_at(stance);
  const auto land = eng::control::place_balance_step(eng::control::StepPlacement::CapturePoint, com, v, w, from, stance,
                                                     hull, 0.0, nullptr, t);
  ASSERT_LT((land.to - stance).norm(), t.max_reach - 0.05) << "a push the leg's reach does not bound";
  // The capture point at touch-down with the centre of pressure at the stance sole's edge nearest to it.
  const Vector2d xi = com + v / w, p = eng::control::clamp_to_polygon(hull, xi, 0.0);
  const Vector2d xi_T = eng::control::capture_point_after(xi, p, w, land.duration);
  EXPECT_GT((land.to - p).norm(), (xi_T - p).norm()) << "lands beyond the capture point (the margin)";
  // land_margin beyond it, away from the stance foot's centre of pressure, and side_margin across the com's motion
  // away from the stance foot (here to the right: the stance foot is the left one).
  const Vector2d expected = xi_T + t.land_margin * (xi_T - p).normalized() + t.side_margin * Vector2d(0.0, -1.0);
  EXPECT_LT((land.to - expected).norm(), 1e-9);
  // So the capture point at touch-down lies between the feet across the motion, not on the new sole's edge.
  EXPECT_GT(xi_T.y() - land.to.y(), 0.5 * t.side_margin);
  EXPECT_LT(xi_T.y(), stance.y());
  EXPECT_GE(land.duration, t.min_duration);
}

TEST(PlaceBalanceStep, StaysWithinReachAndOffTheStanceFoot) {
  BalanceStepTuning t;
  const double w = eng::control::lip_omega(0.95);
  const Vector2d stance(0.0, 0.12), from(0.0, -0.12);
  const auto hull = sole_at(stance);
  // A huge push: the leg's reach bounds the step.
  auto land = eng::control::place_balance_step(eng::control::StepPlacement::CapturePoint, Vector2d(0.0, 0.0),
                                               Vector2d(4.0, 0.0), w, from, stance, hull, 0.0, nullptr, t);
  EXPECT_NEAR((land.to - stance).norm(), t.max_reach, 1e-9);
  // Pushed left (toward the stance foot) with the right foot stepping: it crosses over, ahead or behind the stance
  // foot by cross_gap, never onto it.
  land = eng::control::place_balance_step(eng::control::StepPlacement::CapturePoint, Vector2d(0.0, 0.05),
                                          Vector2d(0.0, 0.9), w, from, stance, hull, 0.0, nullptr, t);
  EXPECT_GE((land.to - stance).norm(), t.min_gap - 1e-9);
  if (land.to.y() > stance.y() - 0.5 * t.min_gap) {
    EXPECT_GE(std::abs(land.to.x() - stance.x()), t.cross_gap - 1e-9);
  }
}

TEST(PlaceBalanceStep, InvertedPendulumLqrStepsFartherForAFasterCom) {
  BalanceStepTuning t;
  const double w = eng::control::lip_omega(0.95);
  const auto lqr = eng::control::solve_cart_pole_lqr(0.95, 64.0, 11.0);
  const Vector2d stance(0.0, 0.12), from(-0.2, -0.12);
  const auto hull = sole_at(stance);
  auto at = [&](double v) {
    return eng::control::place_balance_step(eng::control::StepPlacement::InvertedPendulumLqr, Vector2d(0.0, 0.0),
                                            Vector2d(v, 0.0), w, from, stance, hull, 0.0, &lqr, t)
        .to.x();
  };
  EXPECT_LT(at(0.4), at(0.8));
  EXPECT_GT(at(0.4), 0.0);
}

TEST(StartBalanceStep, LandsFlatOnOneTopAndClearsTheHighestOnTheWay) {
  // A 0.2 m high block from x = 0.3 to 0.8; the step asked to land with its sole straddling the block's edge.
  auto terrain = [](double x, double) { return x >= 0.3 && x <= 0.8 ? 0.2 : 0.0; };
  const auto ground = eng::control::GroundHeight::of(terrain);
  eng::control::BalanceStep s;
  eng::control::FootGeometry g;
  eng::control::FootholdParams fp;
  BalanceStepTuning t;
  eng::control::start_balance_step(s, 1, false, Vector2d(0.0, 0.0), Vector2d(0.3, 0.0), Vector2d(0.0, 0.3),
                                   t.pass_clearance, 0.0, 0.3, ground, g, fp);
  EXPECT_TRUE(eng::control::foothold_ok(ground, s.to - g.centre.head<2>(), 0.0, fp)) << "shifted onto one top";
  EXPECT_NEAR(s.path_top, 0.2, 1e-12);
  // The path: starts at the sole, clears the block by `lift` mid-swing, ends pressed into the landing top.
  s.elapsed = 0.0;
  EXPECT_NEAR(eng::control::balance_step_sole_target(s, t).z(), 0.0, 1e-12);
  s.elapsed = 0.5 * s.duration;
  EXPECT_NEAR(eng::control::balance_step_sole_target(s, t).z(), 0.2 + t.lift, 1e-12);
  s.elapsed = s.duration;
  const Eigen::Vector3d end = eng::control::balance_step_sole_target(s, t);
  EXPECT_NEAR((end.head<2>() - s.to).norm(), 0.0, 1e-12);
  EXPECT_NEAR(end.z(), s.to_top - t.press, 1e-12);
}

TEST(StartBalanceStep, ThePathsTopCountsACrateBesideThePathUnderTheSolesEdge) {
  // A straight step along x at y = 0 on a floor 0.28 m high, beside a crate 0.44 m high whose side is at y = 0.07:
  // the path's line never crosses the crate, the sole's edge (half width 5 cm, plus the foothold's side margin)
  // does. Counted from the line alone, the swing brushed that side and its touch ended the step short.
  auto terrain = [](double, double y) { return y >= 0.07 ? 0.44 : 0.28; };
  const auto ground = eng::control::GroundHeight::of(terrain);
  eng::control::BalanceStep s;
  eng::control::FootGeometry g;
  BalanceStepTuning t;
  eng::control::start_balance_step(s, 0, false, Vector2d(0.0, 0.0), Vector2d(0.5, 0.0), Vector2d(0.0, -0.3), 0.0,
                                   0.0, 0.3, ground, g, t.foothold);
  EXPECT_NEAR(s.path_top, 0.44, 1e-12);
  // A crate farther than the sole's edge and margin (side at y = 0.1) is not in the way.
  auto far = [](double, double y) { return y >= 0.1 ? 0.44 : 0.28; };
  eng::control::start_balance_step(s, 0, false, Vector2d(0.0, 0.0), Vector2d(0.5, 0.0), Vector2d(0.0, -0.3), 0.0,
                                   0.0, 0.3, eng::control::GroundHeight::of(far), g, t.foothold);
  EXPECT_NEAR(s.path_top, 0.28, 1e-12);
}

TEST(StartBalanceStep, AFootAcrossASeamLiftsFromTheTopItStandsOn) {
  // The sole centre over the 1.2 cm seam between two crates (the terrain reads the floor there): the swing starts
  // from the higher top under the sole, not from the floor (read at the centre alone, a carried step rose 0.4 m).
  const control_test::Boxes crates = control_test::two_crates();
  eng::control::BalanceStep s;
  eng::control::FootGeometry g;
  BalanceStepTuning t;
  ASSERT_DOUBLE_EQ(crates(0.0, 0.0), 0.0);
  eng::control::start_balance_step(s, 0, false, Vector2d(0.0, 0.0), Vector2d(-0.3, 0.0), Vector2d(0.0, -0.3), 0.0,
                                   0.0, 0.3, crates.ground(), g, t.foothold);
  EXPECT_NEAR(s.from_top, 0.40, 1e-12);
  s.elapsed = 0.0;
  EXPECT_NEAR(eng::control::balance_step_sole_target(s, t).z(), 0.40, 1e-12);
}

TEST(BalanceStepSoleTarget, VelocityIsThePathsDerivative) {
  eng::control::BalanceStep s;
  s.from = Vector2d(0.0, 0.0);
  s.to = Vector2d(0.4, 0.1);
  s.from_top = 0.1, s.to_top = 0.15, s.path_top = 0.15, s.duration = 0.3;
  BalanceStepTuning t;
  const double h = 1e-6;
  for (double e : {0.02, 0.06, 0.12, 0.2, 0.25, 0.29}) {
    s.elapsed = e;
    Eigen::Vector3d v;
    const Eigen::Vector3d p0 = eng::control::balance_step_sole_target(s, t, &v);
    s.elapsed = e + h;
    const Eigen::Vector3d p1 = eng::control::balance_step_sole_target(s, t);
    EXPECT_NEAR(((p1 - p0) / h - v).norm(), 0.0, 1e-4) << "at " << e << " s";
  }
}

// The acceleration feed-forward is the velocity's derivative, on a bent path (the Bezier's curvature term) and through
// the lift and the set-down; it is zero once the swing's time is up (the foot is held where it landed).
TEST(BalanceStepSoleTarget, AccelerationIsTheVelocitysDerivative) {
  eng::control::BalanceStep s;
  s.from = Vector2d(0.0, 0.0);
  s.to = Vector2d(0.4, 0.1);
  s.bow = Vector2d(-0.05, 0.12);
  s.from_top = 0.1, s.to_top = 0.15, s.path_top = 0.15, s.duration = 0.3;
  BalanceStepTuning t;
  const double h = 1e-6;
  double peak = 0.0;
  for (double e : {0.02, 0.06, 0.12, 0.2, 0.23, 0.25, 0.29}) {
    s.elapsed = e;
    Eigen::Vector3d v0, a;
    eng::control::balance_step_sole_target(s, t, &v0, &a);
    s.elapsed = e + h;
    Eigen::Vector3d v1;
    eng::control::balance_step_sole_target(s, t, &v1);
    EXPECT_NEAR(((v1 - v0) / h - a).norm(), 0.0, 1e-3 * (1.0 + a.norm())) << "at " << e << " s";
    peak = std::max(peak, a.head<2>().norm());
  }
  // The ease's stop is sharp: 6 L / (0.75 T)^2 at its ends, about 50 m/s^2 here.
  EXPECT_GT(peak, 20.0);
  s.elapsed = 0.31;
  Eigen::Vector3d v, a;
  eng::control::balance_step_sole_target(s, t, &v, &a);
  EXPECT_EQ(a, Eigen::Vector3d::Zero());
}

// The landing's side of the stance foot follows the capture point: a forward step by the foot 5 cm behind the stance
// foot and 15 cm beside it lands ahead of it, 8 cm across (the side margin; the old rule put every landing within
// half min_gap across behind the stance foot, by the side the foot came from: 0.5 m back while the body ran forward);
// a cross-over forward lands ahead by cross_gap.
TEST(PlaceBalanceStep, ALandingGoesAheadOrBehindTheStanceFootWhereTheCapturePointIs) {
  BalanceStepTuning t;
  const double w = eng::control::lip_omega(0.95);
  const Vector2d stance(0.0, 0.0), from(-0.05, 0.15);
  const auto hull = sole_at(stance);
  // Pushed forward with the com over the stance foot's line: the capture point lands ahead, 8 cm across (side_margin).
  auto land = eng::control::place_balance_step(eng::control::StepPlacement::CapturePoint, Vector2d(0.0, 0.0),
                                               Vector2d(1.0, 0.0), w, from, stance, hull, 0.0, nullptr, t);
  EXPECT_GT(land.to.x(), stance.x() + t.cross_gap);
  EXPECT_NEAR(land.to.y(), stance.y() + t.side_margin, 1e-9);
  // Pushed forward and to the right: the left foot crosses over in front of the stance foot.
  land = eng::control::place_balance_step(eng::control::StepPlacement::CapturePoint, Vector2d(0.0, -0.05),
                                          Vector2d(1.0, -0.6), w, from, stance, hull, 0.0, nullptr, t);
  EXPECT_LT(land.to.y(), stance.y());
  EXPECT_GE(land.to.x(), stance.x() + t.cross_gap - 1e-9);
}

// A cross-over's swing bends around the stance foot (its sole centre kept pass_clearance from the stance's all the
// way, within the path's sampling); a step that does not pass the stance foot swings straight.
TEST(StartBalanceStep, ACrossOversPathPassesTheStanceFootAtTheClearanceAndAPlainStepIsStraight) {
  auto flat = [](double, double) { return 0.0; };
  const auto ground = eng::control::GroundHeight::of(flat);
  eng::control::FootGeometry g;
  eng::control::FootholdParams fp;
  BalanceStepTuning t;
  eng::control::BalanceStep s;
  const Vector2d stance(0.0, 0.0);
  // From behind-left to ahead-right: the straight path runs 2.5 cm from the stance sole's centre.
  eng::control::start_balance_step(s, 0, false, Vector2d(-0.3, 0.05), Vector2d(0.3, -0.1), stance, t.pass_clearance,
                                   0.0, 0.3, ground, g, fp);
  ASSERT_GT(s.bow.norm(), 0.0);
  double nearest = 1e9;
  for (int i = 0; i <= 200; ++i) nearest = std::min(nearest, (eng::control::balance_step_path(s, i / 200.0) - stance).norm());
  EXPECT_GE(nearest, t.pass_clearance - 0.005);
  EXPECT_LE(nearest, t.pass_clearance + 0.03);  // bent no further than it needs
  // It bends on the side the straight path passed (2.5 cm to the right of the stance sole's centre: around its heel
  // and along its right side), further out than the straight path.
  EXPECT_LT(eng::control::balance_step_path(s, 0.5).y(), -0.025 - 0.1);
  EXPECT_NEAR((eng::control::balance_step_path(s, 1.0) - s.to).norm(), 0.0, 1e-12);
  // A side step away from the stance foot: straight.
  eng::control::start_balance_step(s, 0, false, Vector2d(0.0, 0.2), Vector2d(0.1, 0.5), stance, t.pass_clearance, 0.0,
                                   0.3, ground, g, fp);
  EXPECT_EQ(s.bow, Vector2d::Zero());
  EXPECT_NEAR((eng::control::balance_step_path(s, 0.5) - 0.5 * (s.from + s.to)).norm(), 0.0, 1e-12);
}

// How far the hip comes down for the swing leg to reach a landing below it: the circle of radius share * leg about
// the hip, cut at the landing's horizontal distance (closed form), and nothing for a landing already within it.
TEST(StepReachDrop, IsTheHipsHeightOverTheLegsCircleAtTheLandingsDistance) {
  const Eigen::Vector3d hip(0.0, 0.0, 1.0);
  const double leg = 0.9, share = 0.95, reach = share * leg;
  // 0.5 m out and 0.9 m below: the ankle reaches sqrt(reach^2 - 0.5^2) = 0.694 m down, 0.206 m short.
  const Eigen::Vector3d low(0.3, -0.4, 0.1);
  EXPECT_NEAR(eng::control::step_reach_drop(hip, low, leg, share, 1.0), 0.9 - std::sqrt(reach * reach - 0.25), 1e-12);
  EXPECT_NEAR(eng::control::step_reach_drop(hip, low, leg, share, 0.1), 0.1, 1e-12);  // at most max_drop
  // Lowered by what it asked, the hip reaches the landing at exactly share * leg.
  const double drop = eng::control::step_reach_drop(hip, low, leg, share, 1.0);
  EXPECT_NEAR((hip - Eigen::Vector3d(0.0, 0.0, drop) - low).norm(), reach, 1e-12);
  // Within reach (0.4 m out, 0.6 m below: 0.72 m away): none.
  EXPECT_EQ(eng::control::step_reach_drop(hip, Eigen::Vector3d(0.4, 0.0, 0.4), leg, share, 1.0), 0.0);
  // Farther out than the leg reaches: crouching cannot get there; the hip comes down to the landing's height, capped.
  EXPECT_NEAR(eng::control::step_reach_drop(hip, Eigen::Vector3d(1.0, 0.0, 0.2), leg, share, 0.25), 0.25, 1e-12);
}

}  // namespace
