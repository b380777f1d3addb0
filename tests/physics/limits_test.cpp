// Joint limits as unilateral soft constraints in the PGS solver.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

TEST(Limits, HingeLimitHoldsUnderGravity) {
  Model m;
  // horizontal arm along +X, hinge about Y: gravity rotates it (positive angle about +Y lowers +X)
  Body b = make_body("arm", 0, JointType::Hinge, at({0, 0, 1}), 2.0, {0.5, 0, 0}, rod_inertia_z(2.0, 1.0),
                     Vec3::UnitY());
  b.limited = true;
  b.lower = -0.3;
  b.upper = 0.3;
  m.add_body(b);
  m.finalize();
  Data d = make_data(m);
  double qmax = -1;
  while (d.time < 3.0) {
    step(m, d);
    qmax = std::max(qmax, d.q[0]);
  }
  EXPECT_LT(qmax, 0.3 + 0.01);
  EXPECT_NEAR(d.q[0], 0.3, 0.01);       // resting on the limit
  EXPECT_LT(std::abs(d.v[0]), 1e-3);    // at rest, no jitter
  // and from the other side with a torque
  d.tau[0] = -40;
  while (d.time < 6.0) step(m, d);
  EXPECT_GT(d.q[0], -0.3 - 0.01);
}

TEST(Limits, BallSwingLimitHolds) {
  Model m;
  Body b = make_body("arm", 0, JointType::Ball, at({0, 0, 1}), 2.0, {0.5, 0, 0}, rod_inertia_z(2.0, 1.0));
  b.swing_limit = 0.4;
  m.add_body(b);
  m.finalize();
  Data d = make_data(m);
  double smax = 0;
  while (d.time < 3.0) {
    step(m, d);
    const Mat3 R = quat_from(d.q.data()).toRotationMatrix();
    smax = std::max(smax, std::acos(std::clamp(R(2, 2), -1.0, 1.0)));
  }
  EXPECT_GT(smax, 0.35);  // it did reach the limit
  EXPECT_LT(smax, 0.4 + 0.015);
}

TEST(Limits, BallTwistLimitHolds) {
  Model m;
  m.gravity.setZero();
  Body b = make_body("arm", 0, JointType::Ball, at({0, 0, 1}), 2.0, {0, 0, -0.3}, rod_inertia_z(2.0, 0.6, 0.05));
  b.twist_limit = 0.5;
  m.add_body(b);
  m.finalize();
  Data d = make_data(m);
  d.tau[2] = 0.5;  // torque about the body Z
  double tmax = 0;
  while (d.time < 3.0) {
    step(m, d);
    const Quat q = quat_from(d.q.data());
    tmax = std::max(tmax, std::abs(2 * std::atan2(q.z(), q.w())));
  }
  EXPECT_GT(tmax, 0.45);
  EXPECT_LT(tmax, 0.5 + 0.015);
}
