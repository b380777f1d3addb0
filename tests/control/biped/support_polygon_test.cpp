#include "engine/control/biped/support_polygon.h"

#include <gtest/gtest.h>

#include <cmath>

using eng::control::clamp_to_polygon;
using eng::control::convex_hull_2d;
using V = Eigen::Vector2d;

TEST(OutsideDistance, IsSignedDistanceToTheSoleRectangle) {
  // A sole's rectangle, 0.26 x 0.10 m, centred at the origin, facing +x.
  std::vector<V> hull;
  convex_hull_2d({V(-0.13, -0.05), V(0.13, -0.05), V(0.13, 0.05), V(-0.13, 0.05)}, hull);
  EXPECT_NEAR(eng::control::outside_distance(hull, V(0.23, 0.0)), 0.10, 1e-12);   // 10 cm past the toe
  EXPECT_NEAR(eng::control::outside_distance(hull, V(0.0, 0.0)), -0.05, 1e-12);   // centre: 5 cm from the sides
  EXPECT_NEAR(eng::control::outside_distance(hull, V(0.16, 0.09)), 0.05, 1e-12);  // off the corner (3, 4, 5)
  EXPECT_TRUE(std::isinf(eng::control::outside_distance({}, V::Zero())));
}

TEST(SupportPolygon, HullOfASquareWithInteriorAndEdgePointsIsItsFourCornersCounterClockwise) {
  std::vector<V> hull;
  convex_hull_2d({V(0, 0), V(1, 0), V(1, 1), V(0, 1), V(0.5, 0.5), V(0.5, 0), V(0.2, 0.7)}, hull);
  ASSERT_EQ(hull.size(), 4u);
  double area2 = 0;
  for (size_t i = 0; i < hull.size(); ++i) {
    const V& a = hull[i];
    const V& b = hull[(i + 1) % hull.size()];
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_NEAR(area2, 2.0, 1e-12);  // positive: counter-clockwise, area 1
}

TEST(SupportPolygon, ClampLeavesInsidePointsAndPutsOutsideOnesOnTheShrunkEdge) {
  std::vector<V> hull;
  convex_hull_2d({V(-1, -1), V(1, -1), V(1, 1), V(-1, 1)}, hull);
  EXPECT_TRUE(clamp_to_polygon(hull, V(0.3, -0.2), 0.1).isApprox(V(0.3, -0.2)));
  // Corners pulled 0.1 toward the centre along the diagonal: the right edge sits at x = 1 - 0.1 / sqrt(2).
  const V c = clamp_to_polygon(hull, V(2.0, 0.0), 0.1);
  EXPECT_NEAR(c.x(), 1.0 - 0.1 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(c.y(), 0.0, 1e-12);
}

TEST(SupportPolygon, DegenerateSupportsClampToTheSegmentOrPoint) {
  std::vector<V> hull;
  convex_hull_2d({V(0, 0), V(2, 0), V(1, 0)}, hull);  // collinear: a segment
  ASSERT_EQ(hull.size(), 2u);
  EXPECT_TRUE(clamp_to_polygon(hull, V(0.5, 3.0), 0.1).isApprox(V(0.5, 0.0)));
  EXPECT_TRUE(clamp_to_polygon(hull, V(5.0, 1.0), 0.1).isApprox(V(2.0, 0.0)));
  convex_hull_2d({V(0.3, 0.4)}, hull);
  EXPECT_TRUE(clamp_to_polygon(hull, V(1, 1), 0.1).isApprox(V(0.3, 0.4)));
}

TEST(SupportPolygon, ShareInsideStopsAMoveAtTheMarginOfTheEdgeItHeadsFor) {
  std::vector<V> hull;
  convex_hull_2d({V(-1, -1), V(1, -1), V(1, 1), V(-1, 1)}, hull);
  using eng::control::share_inside;
  EXPECT_NEAR(share_inside(hull, V(0, 0), V(2, 0), 0.1), 0.45, 1e-12);   // stops at x = 0.9
  EXPECT_NEAR(share_inside(hull, V(0, 0), V(-1, 2), 0.1), 0.45, 1e-12);  // the top edge binds first (y = 0.9)
  EXPECT_NEAR(share_inside(hull, V(0, 0), V(0.5, 0.5), 0.1), 1.0, 1e-12);  // stays inside: all of it
  EXPECT_NEAR(share_inside(hull, V(0.95, 0), V(-1, 0), 0.1), 0.0, 1e-12);  // starts within the margin: none
  convex_hull_2d({V(0, 0), V(1, 0)}, hull);  // a segment has no inside to keep to: the caller's call
  EXPECT_NEAR(share_inside(hull, V(0.5, 0), V(3, 3), 0.1), 1.0, 1e-12);
}

// A com 1 m over a 0.2 m square of contacts: an acceleration a needs its centre of pressure at com - z a / (g + a_z)
// (the LIP's ZMP). 3 m/s^2 forward needs it 0.31 m behind the com, past the heel edge; what the soles can give puts it
// on the margin, 0.08 m behind: a = 0.08 (g + a_z) / z.
TEST(SupportPolygon, GroundComAccelerationPutsTheCentreOfPressureOnTheMarginAsTheLipSays) {
  std::vector<V> hull;
  convex_hull_2d({V(-0.1, -0.1), V(0.1, -0.1), V(0.1, 0.1), V(-0.1, 0.1)}, hull);
  using eng::control::ground_com_acceleration;
  const Eigen::Vector3d com(0, 0, 1.0);
  const double g = 9.81;
  const Eigen::Vector3d a = ground_com_acceleration(hull, com, Eigen::Vector3d(3, 0, 0), 1.0, 0.02, 0.0, g);
  EXPECT_NEAR(a.x(), 0.08 * g, 1e-12);
  EXPECT_NEAR(a.y(), 0.0, 1e-12);
  // Pressing down harder (a_z > 0) lets the same centre of pressure give more; the vertical part is kept.
  const Eigen::Vector3d b = ground_com_acceleration(hull, com, Eigen::Vector3d(0, -3, 2), 1.0, 0.02, 0.0, g);
  EXPECT_NEAR(b.y(), -0.08 * (g + 2), 1e-12);
  EXPECT_EQ(b.z(), 2.0);
  // The direction is kept (scaled, not clamped to the nearest point of the polygon).
  const Eigen::Vector3d c = ground_com_acceleration(hull, com, Eigen::Vector3d(4, 2, 0), 1.0, 0.02, 0.0, g);
  EXPECT_NEAR(c.y() / c.x(), 0.5, 1e-12);
  EXPECT_NEAR(c.x(), 0.08 * g, 1e-12);
  // What the soles can give passes unchanged; so does anything while the com is itself at the edge (nothing free)
  // with no ramp.
  EXPECT_TRUE(ground_com_acceleration(hull, com, Eigen::Vector3d(0.5, 0.3, 0), 1.0, 0.02, 0.0, g).isApprox(Eigen::Vector3d(0.5, 0.3, 0)));
  EXPECT_TRUE(ground_com_acceleration(hull, Eigen::Vector3d(0.09, 0, 1), Eigen::Vector3d(-5, 0, 0), 1.0, 0.02, 0.0, g)
                  .isApprox(Eigen::Vector3d(-5, 0, 0)));
}

// The same 0.2 m square, the com 1 m up, asked for 5 m/s^2 back inside from near the +x edge. With a ramp of 0.08 m the
// demand the soles cannot give is handed over in proportion to how far the com is past the 0.02 m margin: an eighth
// 1 cm inside the edge, half 2 cm outside, all of it 6 cm outside. Across the margin the acceleration is continuous
// (without the ramp it jumps from ~0 to the whole 5 m/s^2).
TEST(SupportPolygon, GroundComAccelerationHandsTheRestOverInARampPastTheMargin) {
  std::vector<V> hull;
  convex_hull_2d({V(-0.1, -0.1), V(0.1, -0.1), V(0.1, 0.1), V(-0.1, 0.1)}, hull);
  using eng::control::ground_com_acceleration;
  const Eigen::Vector3d back(-5, 0, 0);
  auto at = [&](double x, double ramp) { return ground_com_acceleration(hull, Eigen::Vector3d(x, 0, 1), back, 1.0, 0.02, ramp); };
  EXPECT_NEAR(at(0.09, 0.08).x(), -5.0 / 8.0, 1e-12);
  EXPECT_NEAR(at(0.12, 0.08).x(), -2.5, 1e-12);
  EXPECT_NEAR(at(0.16, 0.08).x(), -5.0, 1e-12);
  EXPECT_NEAR(at(0.30, 0.08).x(), -5.0, 1e-12);
  EXPECT_EQ(at(0.12, 0.08).z(), 0.0);
  // Continuous at the margin (x = 0.08): both sides near zero, 1e-4 m apart.
  EXPECT_LT(std::abs(at(0.0799, 0.08).x() - at(0.0801, 0.08).x()), 0.01);
  EXPECT_GT(std::abs(at(0.0799, 0.0).x() - at(0.0801, 0.0).x()), 4.9);  // the jump the ramp removes
}
