// Restitution (Geom::restitution): a fast contact leaves at e times its approach speed; slow ones settle.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {
struct BallOnFloor {
  Model m;
  Data d;
  int ball = 0;
};
BallOnFloor drop_ball(double restitution, double height) {
  BallOnFloor s;
  Geom floor;
  floor.shape.type = ShapeType::Plane;
  floor.body = 0;
  s.m.add_geom(floor);
  const double r = 0.1, mass = 0.5;
  s.ball = s.m.add_body(make_body("ball", 0, JointType::Free, at({0, 0, r + height}), mass, Vec3::Zero(),
                                  Mat3::Identity() * (0.4 * mass * r * r)));
  Geom g;
  g.body = s.ball;
  g.shape.type = ShapeType::Sphere;
  g.shape.radius = r;
  g.restitution = restitution;
  s.m.add_geom(g);
  s.m.finalize();
  s.d = make_data(s.m);
  return s;
}
// The highest the ball climbs after its first bounce (m above its resting height), run for `seconds`.
double rebound_height(BallOnFloor& s, double seconds) {
  bool bounced = false;
  double top = 0.0;
  const int nsteps = int(seconds / s.m.dt);
  for (int i = 0; i < nsteps; ++i) {
    step(s.m, s.d);
    const double vz = s.d.v[2];
    if (vz > 0.5) bounced = true;
    if (bounced) top = std::max(top, s.d.q[2] - 0.1);
    if (bounced && vz < 0.0) break;
  }
  return top;
}
}  // namespace

// Energy: the ball arrives at sqrt(2 g h) and leaves at e times that, so it climbs back e^2 h (1 % for the
// semi-implicit Euler's per-step velocity error and the gap the contact closes within one step).
TEST(Restitution, BouncingBallReboundsToESquaredTimesTheDropHeight) {
  for (double e : {0.5, 0.8}) {
    BallOnFloor s = drop_ball(e, 1.0);
    const double h = rebound_height(s, 3.0);
    EXPECT_NEAR(h, e * e * 1.0, 0.03) << "e = " << e;
  }
}

// The default (e = 0) never bounces; and a bouncy ball dropped from below the threshold speed (1 m/s) settles.
TEST(Restitution, NoBounceWithoutRestitutionOrBelowTheThresholdSpeed) {
  BallOnFloor dead = drop_ball(0.0, 1.0);
  EXPECT_LT(rebound_height(dead, 2.0), 0.005);
  BallOnFloor slow = drop_ball(0.9, 0.04);  // arrives at 0.89 m/s
  EXPECT_LT(rebound_height(slow, 2.0), 0.005);
  for (int i = 0; i < 480; ++i) step(slow.m, slow.d);
  EXPECT_NEAR(slow.d.q[2], 0.1, 0.01);
  EXPECT_LT(std::abs(slow.d.v[2]), 1e-3);
}
