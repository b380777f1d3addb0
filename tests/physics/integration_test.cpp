// Time-stepping against closed-form solutions and conservation laws.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {
Model one_free_box(const Vec3& p0) {
  Model m;
  m.add_body(make_body("box", 0, JointType::Free, at(p0), 2.0, Vec3::Zero(), box_inertia(2.0, {0.1, 0.2, 0.3})));
  m.finalize();
  return m;
}
// hinge pendulum about world Y, pivot at z = 2, com at distance L below the pivot
Model pendulum(double L, const Mat3& Ic, double mass = 1.0) {
  Model m;
  m.add_body(make_body("bob", 0, JointType::Hinge, at({0, 0, 2}), mass, {0, 0, -L}, Ic, Vec3::UnitY()));
  m.finalize();
  return m;
}
double measure_period(const Model& m, Data& d, double tmax) {
  // time between successive upward zero crossings of the angle (linear interpolation)
  std::vector<double> crossings;
  double prev = d.q[0];
  while (d.time < tmax) {
    const double t0 = d.time;
    step(m, d);
    const double cur = d.q[0];
    if (prev < 0 && cur >= 0) crossings.push_back(t0 + m.dt * (-prev) / (cur - prev));
    prev = cur;
  }
  if (crossings.size() < 2) return 0;
  return (crossings.back() - crossings.front()) / (crossings.size() - 1);
}
}  // namespace

TEST(Integration, FreeFallMatchesClosedForm) {
  const Model m = one_free_box({0, 0, 10});
  Data d = make_data(m);
  const int n = 240;
  for (int i = 0; i < n; ++i) step(m, d);
  const double t = n * m.dt, g = 9.81;
  EXPECT_NEAR(d.v[2], -g * t, 1e-9);
  // semi-implicit Euler: z_n = z0 - g dt^2 n(n+1)/2 exactly; and within g t dt of the closed form
  EXPECT_NEAR(d.q[2], 10 - g * m.dt * m.dt * n * (n + 1) / 2.0, 1e-9);
  EXPECT_NEAR(d.q[2], 10 - 0.5 * g * t * t, g * t * m.dt);
  EXPECT_NEAR(d.q[0], 0.0, 1e-12);
}

TEST(Integration, ProjectilePathAndSpinMatchClosedForm) {
  const Model m = one_free_box({0, 0, 0});
  Data d = make_data(m);
  d.v << 3, -1, 5, 0, 0, 2;  // spin about the body Z (a principal axis): stays constant
  const int n = 480;
  for (int i = 0; i < n; ++i) step(m, d);
  const double t = n * m.dt, g = 9.81;
  EXPECT_NEAR(d.q[0], 3 * t, 1e-9);
  EXPECT_NEAR(d.q[1], -t, 1e-9);
  EXPECT_NEAR(d.q[2], 5 * t - 0.5 * g * t * t, g * t * m.dt);
  const Quat r = quat_from(d.q.data() + 3);
  const Quat ref(Eigen::AngleAxisd(2 * t, Vec3::UnitZ()));
  EXPECT_NEAR(std::abs(r.dot(ref)), 1.0, 1e-9);
}

TEST(Integration, SimplePendulumSmallAnglePeriod) {
  const double L = 1.0;
  const Model m = pendulum(L, Mat3::Identity() * 1e-6);
  Data d = make_data(m);
  d.q[0] = 0.02;
  const double T = measure_period(m, d, 10.0);
  const double T0 = 2 * M_PI * std::sqrt(L / 9.81);
  EXPECT_NEAR(T, T0, 0.002 * T0);
}

TEST(Integration, CompoundPendulumPeriodWithInertia) {
  // uniform rod of length l pivoted at one end: T = 2 pi sqrt(I_pivot / (m g d)) = 2 pi sqrt(2 l / 3 g)
  const double l = 1.2, mass = 3.0;
  const Model m = pendulum(l / 2, rod_inertia_z(mass, l, 0.0), mass);
  Data d = make_data(m);
  d.q[0] = 0.02;
  const double T = measure_period(m, d, 10.0);
  const double T0 = 2 * M_PI * std::sqrt(2 * l / (3 * 9.81));
  EXPECT_NEAR(T, T0, 0.002 * T0);
}

TEST(Integration, PendulumEnergyDriftBoundedOver10s) {
  const Model m = pendulum(1.0, Mat3::Identity() * 0.01);
  Data d = make_data(m);
  d.q[0] = 1.0;  // large swing
  forward_kinematics(m, d);
  const double E0 = kinetic_energy(m, d) + potential_energy(m, d);
  double maxdev = 0;
  while (d.time < 10.0) {
    step(m, d);
    forward_kinematics(m, d);
    maxdev = std::max(maxdev, std::abs(kinetic_energy(m, d) + potential_energy(m, d) - E0));
  }
  const double scale = 1.0 * 9.81 * 1.0;  // m g L
  EXPECT_LT(maxdev / scale, 0.01);
}

TEST(Integration, DoublePendulumEnergyDriftBounded) {
  Model m;
  int a = m.add_body(make_body("a", 0, JointType::Hinge, at({0, 0, 3}), 1.0, {0, 0, -0.5},
                               rod_inertia_z(1.0, 1.0), Vec3::UnitY()));
  m.add_body(make_body("b", a, JointType::Hinge, at({0, 0, -1.0}), 1.0, {0, 0, -0.5}, rod_inertia_z(1.0, 1.0),
                       Vec3::UnitY()));
  m.finalize();
  Data d = make_data(m);
  d.q << 1.2, -0.5;  // chaotic regime
  forward_kinematics(m, d);
  const double E0 = kinetic_energy(m, d) + potential_energy(m, d);
  double maxdev = 0;
  while (d.time < 10.0) {
    step(m, d);
    forward_kinematics(m, d);
    maxdev = std::max(maxdev, std::abs(kinetic_energy(m, d) + potential_energy(m, d) - E0));
  }
  EXPECT_LT(maxdev / (2.0 * 9.81 * 1.0), 0.06);  // chaotic, large swings: 240 Hz Euler
}

// Reduced-coordinate semi-implicit Euler conserves momentum only to O(dt) (the velocity-product terms
// are evaluated at the start of the step). We check: no external force -> momentum error is small at
// 240 Hz and shrinks linearly with dt (so the dynamics is consistent, the residual is integrator error).
TEST(Integration, TumblingBallJointChainConservesMomentum) {
  auto run = [](double dt, Vec6& dh, Vec6& h0, double& dE, double& E0) {
    Model m;
    m.gravity.setZero();
    m.dt = dt;
    int prev = m.add_body(make_body("l0", 0, JointType::Free, at({0, 0, 1}), 2.0, {0, 0, 0.15},
                                    box_inertia(2.0, {0.05, 0.07, 0.15})));
    for (int i = 1; i < 5; ++i)
      prev = m.add_body(make_body("li", prev, JointType::Ball, at({0, 0, 0.3}), 1.0 + 0.3 * i, {0.02, 0, 0.15},
                                  box_inertia(1.0 + 0.3 * i, {0.04, 0.06, 0.15})));
    m.finalize();
    Data d = make_data(m);
    std::mt19937 rng(1);
    randomize(m, d, rng);  // random pose, ~1 rad/s per DoF: vigorous tumbling
    clear_applied(d);
    forward_kinematics(m, d);
    h0 = spatial_momentum(m, d, 1);
    E0 = kinetic_energy(m, d);
    const int n = static_cast<int>(std::lround(1.0 / dt));
    for (int i = 0; i < n; ++i) step(m, d);
    forward_kinematics(m, d);
    dh = spatial_momentum(m, d, 1) - h0;
    dE = kinetic_energy(m, d) - E0;
  };
  Vec6 dh1, dh4, h0;
  double dE1, dE4, E0;
  run(1.0 / 240, dh1, h0, dE1, E0);
  run(1.0 / 960, dh4, h0, dE4, E0);
  EXPECT_LT(lin(dh1).norm(), 0.01 * lin(h0).norm());
  EXPECT_LT(ang(dh1).norm(), 0.05 * ang(h0).norm());
  EXPECT_LT(std::abs(dE1), 0.01 * E0);
  // first order convergence: 4x smaller dt -> ~4x smaller error
  EXPECT_LT(lin(dh4).norm(), 0.3 * lin(dh1).norm());
  EXPECT_LT(ang(dh4).norm(), 0.3 * ang(dh1).norm());
}

// The velocity update alone (fixed q) conserves momentum exactly when the bias terms vanish
// (start from rest, pure internal joint torques): exact to round-off.
TEST(Integration, InternalTorquesConserveMomentumExactlyFromRest) {
  Model m;
  m.gravity.setZero();
  int prev = m.add_body(make_body("l0", 0, JointType::Free, at({0, 0, 1}), 2.0, {0, 0, 0.15},
                                  box_inertia(2.0, {0.05, 0.07, 0.15})));
  for (int i = 1; i < 5; ++i)
    prev = m.add_body(make_body("li", prev, JointType::Ball, at({0, 0, 0.3}), 1.0, {0.02, 0, 0.15},
                                box_inertia(1.0, {0.04, 0.06, 0.15})));
  m.finalize();
  Data d = make_data(m);
  for (int k = 6; k < m.nv; ++k) d.tau[k] = 0.5 * std::sin(k);
  forward_kinematics(m, d);  // the step pipeline without the final position update
  collide(m, d);
  compute_constraints(m, d);
  passive_forces(m, d);
  forward_dynamics(m, d);
  solve_constraints(m, d);
  forward_kinematics(m, d);
  EXPECT_LT(spatial_momentum(m, d, 1).norm(), 1e-12);
  EXPECT_GT(d.v.norm(), 1e-3);
}

TEST(Integration, ImplicitDampingStableAtHighGain) {
  Model m;
  Body b = make_body("arm", 0, JointType::Hinge, at({0, 0, 1}), 0.2, {0, 0, -0.2}, rod_inertia_z(0.2, 0.4));
  b.damping = 1e4;  // explicit Euler would explode (dt * d / I >> 2)
  b.stiffness = 1e5;
  m.add_body(b);
  m.finalize();
  Data d = make_data(m);
  d.q[0] = 0.5;
  for (int i = 0; i < 480; ++i) {
    step(m, d);
    ASSERT_TRUE(std::isfinite(d.q[0]));
    ASSERT_LT(std::abs(d.q[0]), 0.5 + 1e-9);
  }
  EXPECT_LT(std::abs(d.q[0]), 0.5);
}

TEST(Integration, AppliedForceAndTorqueWithReaction) {
  // a force through the com of a free body gives a = F/m, no rotation
  const Model m0 = [] {
    Model m;
    m.gravity.setZero();
    m.add_body(make_body("b", 0, JointType::Free, at({0, 0, 0}), 2.0, {0.1, 0, 0}, box_inertia(2.0, {0.1, 0.1, 0.1})));
    m.finalize();
    return m;
  }();
  Data d = make_data(m0);
  forward_kinematics(m0, d);
  apply_force_at_point(m0, d, 1, {0, 4, 0}, d.com_world[1]);
  step(m0, d);
  EXPECT_NEAR(d.qacc[1], 2.0, 1e-9);
  EXPECT_NEAR(d.v.tail<3>().norm(), 0.0, 1e-12);
  // internal torque pair on a free 2-body system leaves the angular momentum unchanged
  Model m;
  m.gravity.setZero();
  int a = m.add_body(make_body("a", 0, JointType::Free, at({0, 0, 0}), 2.0, Vec3::Zero(), box_inertia(2.0, {0.1, 0.1, 0.1})));
  m.add_body(make_body("b", a, JointType::Ball, at({0, 0, 0.3}), 1.0, {0, 0, 0.1}, box_inertia(1.0, {0.1, 0.1, 0.1})));
  m.finalize();
  Data e = make_data(m);
  forward_kinematics(m, e);
  apply_world_torque_with_reaction(m, e, 2, {0, 0, 3});
  for (int i = 0; i < 10; ++i) step(m, e);
  forward_kinematics(m, e);
  EXPECT_LT(spatial_momentum(m, e, 1).norm(), 1e-9);
  EXPECT_GT(std::abs(e.v[8]), 0.1);  // but the bodies counter-rotate
}

TEST(Integration, StiffImplicitServoTracksTargetAt240Hz) {
  // a 2 kg forearm-like link on a hinge + a ball joint, very stiff servos (explicit PD would diverge:
  // dt^2 k / I >> 4), gravity on: converges to the targets (minus the gravity sag k^-1 m g r) calmly.
  Model m;
  Body a = make_body("upper", 0, JointType::Ball, at({0, 0, 1.5}), 2.0, {0, 0, -0.15}, rod_inertia_z(2.0, 0.3));
  a.stiffness = 2e4;
  a.damping = 200;
  int ia = m.add_body(a);
  Body f = make_body("fore", ia, JointType::Hinge, at({0, 0, -0.3}), 1.5, {0, 0, -0.15}, rod_inertia_z(1.5, 0.3),
                     Vec3::UnitY());
  f.stiffness = 5e3;
  f.damping = 50;
  m.add_body(f);
  m.finalize();
  Data d = make_data(m);
  d.spring_ref << 0.0, 0.6, 0.0, -1.2;  // ball: rotate 0.6 rad about body Y; elbow: -1.2 rad
  double elbow_min = 0;
  while (d.time < 2.0) {
    step(m, d);
    ASSERT_TRUE(d.v.allFinite());
    elbow_min = std::min(elbow_min, d.q[4]);
  }
  const Vec3 rv = quat_log(quat_from(d.q.data()));
  EXPECT_NEAR(rv.y(), 0.6, 0.02);
  EXPECT_NEAR(d.q[4], -1.2, 0.02);
  EXPECT_LT(d.v.norm(), 1e-3);  // settled, no ringing
  EXPECT_GT(elbow_min, -1.2 - 0.05);  // over-damped servo (zeta ~ 1.6): no overshoot
}
