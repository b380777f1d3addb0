#include "engine/control/biped/support_polygon.h"

#include <gtest/gtest.h>

#include <cmath>

using eng::control::clamp_to_polygon;
using eng::control::convex_hull_2d;
using V = Eigen::Vector2d;

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
