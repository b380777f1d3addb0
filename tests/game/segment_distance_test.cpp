// The closed-form segment distance (game/segment_distance.h) against hand cases and a brute-force search.
#include <gtest/gtest.h>

#include <random>

#include "engine/physics/collision.h"
#include "game/segment_distance.h"

using namespace boxing;
using Eigen::Vector3d;

TEST(SegmentDistance, HandCases) {
  // Crossing perpendicular segments 0.3 apart in z: the distance is the gap, at their middles.
  SegmentClosest c = segment_distance({-1, 0, 0}, {1, 0, 0}, {0, -1, 0.3}, {0, 1, 0.3});
  EXPECT_NEAR(c.distance, 0.3, 1e-12);
  EXPECT_NEAR(c.s, 0.5, 1e-12);
  EXPECT_NEAR(c.t, 0.5, 1e-12);
  // Parallel, overlapping along x, 0.2 apart.
  EXPECT_NEAR(segment_distance({0, 0, 0}, {1, 0, 0}, {0.5, 0.2, 0}, {2, 0.2, 0}).distance, 0.2, 1e-12);
  // Collinear, end to end 0.5 apart.
  EXPECT_NEAR(segment_distance({0, 0, 0}, {1, 0, 0}, {1.5, 0, 0}, {3, 0, 0}).distance, 0.5, 1e-12);
  // A point and a segment; two points.
  EXPECT_NEAR(segment_distance({0.5, 1, 0}, {0.5, 1, 0}, {0, 0, 0}, {1, 0, 0}).distance, 1.0, 1e-12);
  EXPECT_NEAR(segment_distance({0, 0, 0}, {0, 0, 0}, {3, 4, 0}, {3, 4, 0}).distance, 5.0, 1e-12);
  // Skew, the closest points past an end: clamped to the end (1, 0, 0) and the other's nearest point.
  c = segment_distance({0, 0, 0}, {1, 0, 0}, {2, -1, 1}, {2, 1, 1});
  EXPECT_NEAR(c.distance, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(c.s, 1.0, 1e-12);
}

TEST(SegmentDistance, MatchesBruteForceOnRandomSegments) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto v = [&] { return Vector3d(u(rng), u(rng), u(rng)); };
  for (int i = 0; i < 200; ++i) {
    const Vector3d p0 = v(), p1 = v(), q0 = v(), q1 = v();
    double best = 1e9;
    for (int a = 0; a <= 200; ++a)
      for (int b = 0; b <= 200; ++b)
        best = std::min(best, ((p0 + (p1 - p0) * (a / 200.0)) - (q0 + (q1 - q0) * (b / 200.0))).norm());
    const SegmentClosest c = segment_distance(p0, p1, q0, q1);
    EXPECT_LE(c.distance, best + 1e-12);
    EXPECT_NEAR(c.distance, best, 0.02);
    EXPECT_NEAR((c.p - c.q).norm(), c.distance, 1e-12);
  }
}

TEST(SegmentDistance, SweptGeomsOverlapByTheirRadii) {
  eng::physics::Shape cap;
  cap.type = eng::physics::ShapeType::Capsule;
  cap.radius = 0.06, cap.half_length = 0.2;
  eng::physics::Pose a, b;
  b.p = Vector3d(0.1, 0, 0);  // two upright capsules 0.1 apart: 2 cm overlap
  EXPECT_NEAR(swept_distance(swept_segment(cap, a), swept_segment(cap, b)), -0.02, 1e-12);
  eng::physics::Shape box;
  box.type = eng::physics::ShapeType::Box;
  box.half_extents = Vector3d(0.12, 0.05, 0.04);  // a foot: its inscribed capsule along x, radius 0.04
  const SweptSegment s = swept_segment(box, a);
  EXPECT_NEAR(s.radius, 0.04, 1e-12);
  EXPECT_NEAR((s.b - s.a).norm(), 2 * 0.08, 1e-12);
}
