// World-space servo, eq. 3: tau = k1 Delta(W_d, W_a) + k2 (omega_d - omega_a), k1 = I wn^2, k2 = 2 zeta I wn.
#include "engine/control/servo/inertial_servo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "control/control_test_util.h"

using namespace eng::control;
using eng::control::test::aa;
using eng::control::test::RigidBody;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {
Quaterniond random_q(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}
Vector3d random_v(std::mt19937& rng, double s) {
  std::normal_distribution<double> n(0.0, s);
  return Vector3d(n(rng), n(rng), n(rng));
}

struct Response {
  double overshoot = 0;   // max excursion past zero along the initial error axis (rad)
  double final_err = 0;   // |Delta| at the end
  double max_err = 0;     // largest |Delta| seen (blow-up detector)
};

// One free rigid body driven by the servo toward identity from a 1 rad error, dt = 1/240.
Response drive_single_body(const ServoGains& g, const Vector3d& I_body, double seconds, double e0 = 1.0) {
  const Vector3d axis = Vector3d(1, 2, -1).normalized();
  RigidBody b;
  b.I_body = I_body;
  b.q = aa(e0, axis);
  const double I_eff = I_body.mean();
  const double dt = 1.0 / 240;
  Response r;
  const int steps = static_cast<int>(seconds / dt);
  for (int k = 0; k < steps; ++k) {
    const Vector3d tau = servo_torque_one(g, I_eff, Quaterniond::Identity(), Vector3d::Zero(), b.q, b.omega,
                                          std::numeric_limits<double>::infinity());
    b.step(tau, dt);
    const Vector3d e = orientation_error(b.q, Quaterniond::Identity());  // actual relative to target
    r.overshoot = std::max(r.overshoot, -e.dot(axis));
    r.max_err = std::max(r.max_err, e.norm());
    if (!b.q.coeffs().allFinite()) {
      r.max_err = 1e9;
      break;
    }
  }
  r.final_err = orientation_error(b.q, Quaterniond::Identity()).norm();
  return r;
}
}  // namespace

TEST(InertialServo, GainRule) {
  ServoGains g;
  g.omega_n = 10;
  g.zeta = 0.7;
  EXPECT_DOUBLE_EQ(servo_k1(g, 2.0), 200.0);
  EXPECT_DOUBLE_EQ(servo_k2(g, 2.0), 28.0);
}

TEST(InertialServo, ZeroTorqueWhenOnTarget) {
  const auto skel = test::test_skeleton();
  std::mt19937 rng(3);
  std::vector<Quaterniond> W(5);
  std::vector<Vector3d> w(5);
  for (int i = 0; i < 5; ++i) {
    W[i] = random_q(rng);
    w[i] = random_v(rng, 2.0);
  }
  std::vector<double> I = {3, 1, 0.2, 0.1, 0.05};
  std::vector<Vector3d> tau;
  ServoGains g;
  g.root_k_scale = 1.0;
  for (bool spd : {false, true}) {
    g.stable_pd = spd;
    inertial_servo_torques(skel, g, I, W, w, W, w, tau);
    for (int i = 0; i < 5; ++i) EXPECT_LT(tau[i].norm(), 1e-9) << i;
  }
}

TEST(InertialServo, InternalTorquesSumToZeroAndRootIsUnactuatedByDefault) {
  const auto skel = test::test_skeleton();
  std::mt19937 rng(7);
  std::vector<double> I = {3, 1, 0.2, 0.1, 0.05};
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Quaterniond> Wd(5), Wa(5);
    std::vector<Vector3d> wd(5), wa(5), tau;
    for (int i = 0; i < 5; ++i) {
      Wd[i] = random_q(rng);
      Wa[i] = random_q(rng);
      wd[i] = random_v(rng, 3.0);
      wa[i] = random_v(rng, 3.0);
    }
    ServoGains g;
    g.max_angular_accel = trial % 2 ? 300.0 : 0.0;
    inertial_servo_torques(skel, g, I, Wd, wd, Wa, wa, tau);
    EXPECT_EQ(tau[0], Vector3d::Zero());
    // The game's application path: +tau_i on bone i, -tau_i on its parent.
    std::vector<Vector3d> applied(5, Vector3d::Zero());
    for (int i = 1; i < 5; ++i) {
      applied[i] += tau[i];
      applied[skel.parent[i]] -= tau[i];
    }
    Vector3d net = Vector3d::Zero();
    for (const auto& a : applied) net += a;
    EXPECT_LT(net.norm(), 1e-12);
    if (g.max_angular_accel > 0) {
      for (int i = 1; i < 5; ++i) EXPECT_LE(tau[i].norm(), 300.0 * I[i] * (1 + 1e-12));
    }
  }
}

TEST(InertialServo, TorqueLimitsPerKg) {
  ServoGains g;
  g.torque_limit_per_kg = 50;
  g.max_angular_accel = 1000;
  const auto lim = servo_torque_limits(g, {2.0, 0.1}, {10.0, 1.0});
  EXPECT_DOUBLE_EQ(lim[0], 500.0);  // min(50*10, 1000*2)
  EXPECT_DOUBLE_EQ(lim[1], 50.0);   // min(50*1, 1000*0.1 = 100)
}

TEST(InertialServo, SingleBodyCriticallyDampedResponse) {
  ServoGains g;  // omega_n = 12, zeta = 1
  const Response r = drive_single_body(g, Vector3d::Constant(0.4), 1.5);
  EXPECT_LT(r.overshoot, 0.05);  // < 5 % of the 1 rad step
  EXPECT_LT(r.final_err, 1e-3);
  // Settling consistent with omega_n = 12: (1 + wn t) e^{-wn t} at t = 0.5 s is ~1.7e-2.
  const Response half = drive_single_body(g, Vector3d::Constant(0.4), 0.5);
  EXPECT_LT(half.final_err, 0.03);
  EXPECT_GT(half.final_err, 0.005);
}

TEST(InertialServo, SingleBodyUnderdampedOvershootMatchesZeta) {
  ServoGains g;
  g.zeta = 0.5;  // continuous overshoot exp(-pi zeta / sqrt(1 - zeta^2)) = 16.3 %
  const Response r = drive_single_body(g, Vector3d::Constant(0.4), 2.0);
  EXPECT_NEAR(r.overshoot, std::exp(-M_PI * 0.5 / std::sqrt(0.75)), 0.03);
  EXPECT_LT(r.final_err, 1e-3);
}

TEST(InertialServo, AnisotropicBodyConverges) {
  ServoGains g;
  const Response r = drive_single_body(g, Vector3d(0.05, 0.4, 0.45), 3.0);  // a forearm-like body
  EXPECT_LT(r.final_err, 1e-3);
  EXPECT_LT(r.max_err, 1.0 + 1e-9);
}

TEST(InertialServo, StablePdAtHighGain) {
  ServoGains g;
  g.omega_n = 40;
  g.stable_pd = true;
  const Response r = drive_single_body(g, Vector3d::Constant(0.4), 1.0);
  EXPECT_LT(r.final_err, 1e-4);
  EXPECT_LT(r.overshoot, 0.05);
  // Far beyond the explicit limit (omega_n dt = 1.7): explicit PD diverges, stable PD does not.
  g.omega_n = 400;
  const Response spd = drive_single_body(g, Vector3d::Constant(0.4), 1.0);
  EXPECT_LT(spd.final_err, 1e-3);
  EXPECT_LE(spd.max_err, 1.0 + 1e-9);
  g.stable_pd = false;
  const Response pd = drive_single_body(g, Vector3d::Constant(0.4), 1.0);
  EXPECT_GT(pd.max_err, 1.0 + 1e-3);
}

TEST(InertialServo, PersonSpaceKeepsGameHeading) {
  const auto skel = test::test_skeleton();
  eng::anim::PoseSample s;
  const Quaterniond clip_root = aa(1.0, Vector3d::UnitZ()) * aa(0.2, Vector3d::UnitY());  // clip faces 1 rad, leans
  s.pose.rotation = {clip_root, aa(0.3, Vector3d::UnitY()), Quaterniond::Identity(), Quaterniond::Identity(),
                     Quaterniond::Identity()};
  s.angular_velocity.assign(5, Vector3d::Zero());
  s.angular_velocity[0] = Vector3d(0, 0, 0.5);  // the clip turns; person space ignores the clip's yaw
  std::vector<double> I(5, 0.3);
  std::vector<Quaterniond> Wa(5, Quaterniond::Identity());
  std::vector<Vector3d> wa(5, Vector3d::Zero());
  ServoState st;
  const double game_heading = -2.0;
  inertial_servo_step(skel, ServoSpace::Person, ServoGains{}, I, s, game_heading, 1.0 / 30, Wa, wa, st);
  EXPECT_NEAR(heading_of(st.W_d[0]), game_heading, 1e-12);
  EXPECT_LT(orientation_error(remove_heading(st.W_d[0]), remove_heading(clip_root)).norm(), 1e-12);  // same lean
  EXPECT_LT(st.omega_d[0].norm(), 1e-9);  // the clip's yaw rate is not commanded in person space
  EXPECT_NEAR(heading_of(st.W_d[1]), game_heading, 1e-12);  // children follow the person-space root
  EXPECT_EQ(st.tau[0], Vector3d::Zero());
  // World space keeps the clip's own heading and rate.
  inertial_servo_step(skel, ServoSpace::World, ServoGains{}, I, s, game_heading, 1.0 / 30, Wa, wa, st);
  EXPECT_NEAR(heading_of(st.W_d[0]), 1.0, 1e-12);
  EXPECT_NEAR(st.omega_d[0].z(), 0.5, 1e-9);
}

TEST(InertialServo, StepDoesNotReallocateOnceSized) {
  const auto skel = test::test_skeleton();
  eng::anim::PoseSample s;
  s.pose.rotation.assign(5, Quaterniond::Identity());
  s.angular_velocity.assign(5, Vector3d(0.1, 0, 0));
  std::vector<double> I(5, 0.3);
  std::vector<Quaterniond> Wa(5, aa(0.1, Vector3d::UnitX()));
  std::vector<Vector3d> wa(5, Vector3d::Zero());
  ServoState st;
  st.resize(5);
  inertial_servo_step(skel, ServoSpace::World, ServoGains{}, I, s, 0, 1.0 / 60, Wa, wa, st);
  const auto* p1 = st.tau.data();
  const auto* p2 = st.scratch.W_ahead.data();
  inertial_servo_step(skel, ServoSpace::World, ServoGains{}, I, s, 0, 1.0 / 60, Wa, wa, st);
  EXPECT_EQ(p1, st.tau.data());
  EXPECT_EQ(p2, st.scratch.W_ahead.data());
}
