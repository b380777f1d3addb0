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

// The soft speed limit (Body::max_speed): for a lone hinge with no gravity, the implicit damping D = M / dt
// (|v| / max_speed - 1) makes (M + dt D) v+ = M v give |v+| = max_speed exactly, in one step.
TEST(SpeedLimit, BringsAFreeSpinningHingeToItsLimitInOneStep) {
  Model m;
  m.gravity.setZero();
  Body b = make_body("arm", 0, JointType::Hinge, at({0, 0, 1}), 2.0, {0.5, 0, 0}, rod_inertia_z(2.0, 1.0),
                     Vec3::UnitY());
  b.max_speed = 30.0;
  m.add_body(b);
  m.finalize();
  Data d = make_data(m);
  d.v[0] = -100.0;
  step(m, d);
  EXPECT_NEAR(d.v[0], -30.0, 1e-9);
  step(m, d);  // at the limit: no damping from it
  EXPECT_NEAR(d.v[0], -30.0, 1e-9);
  EXPECT_EQ(d.speed_damping[0], 0.0);
}

// A limit turned off while the joint is past it leaves nothing behind: the next step is a free spin (the game turns
// the limit off as a boxer stands up).
TEST(SpeedLimit, TurnedOffPastTheLimitLeavesNoDamping) {
  Model m;
  m.gravity.setZero();
  Body b = make_body("arm", 0, JointType::Hinge, at({0, 0, 1}), 2.0, {0.5, 0, 0}, rod_inertia_z(2.0, 1.0),
                     Vec3::UnitY());
  b.max_speed = 30.0;
  m.add_body(b);
  m.finalize();
  Data d = make_data(m);
  d.v[0] = -100.0;
  step(m, d);
  ASSERT_GT(d.speed_damping[0], 0.0);  // the step was limited
  d.v[0] = -100.0;
  m.bodies[1].max_speed = 0.0;
  step(m, d);
  EXPECT_EQ(d.speed_damping[0], 0.0);
  EXPECT_NEAR(d.v[0], -100.0, 1e-9);
}

// Below the limit the joint evolves bit for bit as one without a limit (the damping is exactly zero there).
TEST(SpeedLimit, BelowTheLimitChangesNothing) {
  auto run = [](double max_speed) {
    Model m;
    Body b = make_body("arm", 0, JointType::Ball, at({0, 0, 1}), 2.0, {0.5, 0, 0}, rod_inertia_z(2.0, 1.0));
    b.max_speed = max_speed;
    m.add_body(b);
    m.finalize();
    Data d = make_data(m);
    d.v << 1.0, -2.0, 0.5;
    for (int i = 0; i < 240; ++i) step(m, d);
    return d.q;
  };
  const VecX limited = run(50.0), free = run(0.0);  // a swinging rod stays under 10 rad/s
  for (int i = 0; i < limited.size(); ++i) EXPECT_EQ(limited[i], free[i]);
}

// A ball joint keeps the direction of its angular velocity; only its magnitude comes down, and only energy leaves.
TEST(SpeedLimit, SlowsABallJointAlongItsAxisAndOnlyTakesEnergy) {
  Model m;
  m.gravity.setZero();
  Body b = make_body("arm", 0, JointType::Ball, at({0, 0, 1}), 2.0, {0, 0, -0.4}, rod_inertia_z(2.0, 0.8, 0.05));
  b.max_speed = 20.0;
  m.add_body(b);
  m.finalize();
  Data d = make_data(m);
  d.v << 0.0, 0.0, 60.0;  // spinning about the rod's own axis (a principal axis: constant without the limit)
  const double e0 = 0.5 * d.v.dot(m.bodies[1].inertia * d.v);
  step(m, d);
  EXPECT_NEAR(d.v[2], 20.0, 1e-6);
  EXPECT_NEAR(d.v.head<2>().norm(), 0.0, 1e-9);
  EXPECT_LT(0.5 * d.v.dot(m.bodies[1].inertia * d.v), e0);
}

// The damper is part of the unconstrained dynamics, so the contact solve sees it: a limb driven down onto the floor
// by a huge torque, far past its speed limit, is still held by the floor, and comes to rest on it.
TEST(SpeedLimit, AFloorStillHoldsALimbDrivenIntoItPastTheLimit) {
  Model m;
  Geom floor;
  floor.shape.type = ShapeType::Plane;
  m.add_geom(floor);
  Body b = make_body("arm", 0, JointType::Hinge, at({0, 0, 0.3}), 2.0, {0.5, 0, 0}, rod_inertia_z(2.0, 1.0),
                     Vec3::UnitY());
  b.max_speed = 5.0;
  const int arm = m.add_body(b);
  Geom tip;
  tip.shape.type = ShapeType::Sphere;
  tip.shape.radius = 0.05;
  tip.body = arm;
  tip.local.p = Vec3(1.0, 0, 0);
  m.add_geom(tip);
  m.finalize();
  Data d = make_data(m);
  double lowest = 1.0;
  while (d.time < 2.0) {
    d.tau[0] = 2000.0;  // positive about +Y lowers +X: the tip pressed into the floor
    step(m, d);
    lowest = std::min(lowest, 0.3 - std::sin(d.q[0]) * 1.0 - 0.05);
  }
  EXPECT_GT(lowest, -0.02);  // the sphere's bottom at most 2 cm into the floor
  EXPECT_LT(std::abs(d.v[0]), 0.1);
}
