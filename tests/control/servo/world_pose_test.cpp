// Lifting (section IV) and desired world angular velocity (eq. 2).
#include "engine/control/servo/world_pose.h"

#include <gtest/gtest.h>

#include "control/control_test_util.h"
#include "engine/control/servo/inertial_servo.h"

using namespace eng::control;
using eng::anim::Pose;
using eng::anim::PoseSample;
using eng::control::test::aa;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {
double qdist(const Quaterniond& a, const Quaterniond& b) { return orientation_error(a, b).norm(); }

Pose test_pose() {
  Pose p;
  p.rotation = {aa(2.0, Vector3d(1, 0, 0)),  // ignored by lift_to_world (root comes from outside)
                aa(0.3, Vector3d(0, 1, 0)), aa(-0.5, Vector3d(1, 1, 0)), aa(1.1, Vector3d(0, 0, 1)),
                aa(0.8, Vector3d(1, 0, 0))};
  return p;
}
}  // namespace

TEST(LiftToWorld, MatchesManualComposition) {
  const auto skel = test::test_skeleton();
  const Pose p = test_pose();
  const Quaterniond root = aa(0.4, Vector3d(0, 0, 1)) * aa(0.1, Vector3d(0, 1, 0));
  std::vector<Quaterniond> W;
  lift_to_world(skel, p, root, W);
  ASSERT_EQ(W.size(), 5u);
  const Quaterniond W1 = root * p.rotation[1];
  const Quaterniond W2 = root * p.rotation[1] * p.rotation[2];
  const Quaterniond W3 = root * p.rotation[1] * p.rotation[3];
  const Quaterniond W4 = root * p.rotation[1] * p.rotation[3] * p.rotation[4];
  EXPECT_LT(qdist(W[0], root), 1e-14);
  EXPECT_LT(qdist(W[1], W1), 1e-14);
  EXPECT_LT(qdist(W[2], W2), 1e-14);
  EXPECT_LT(qdist(W[3], W3), 1e-14);
  EXPECT_LT(qdist(W[4], W4), 1e-14);
}

TEST(LiftToWorld, ActualPoseOfNonRootBonesDoesNotEnter) {
  // Paper section IV: "The actual orientation of all bones except the root are ignored."
  const auto skel = test::test_skeleton();
  PoseSample s;
  s.pose = test_pose();
  s.angular_velocity.assign(5, Vector3d(0.1, -0.2, 0.3));
  const std::vector<double> I(5, 0.5);
  std::vector<Vector3d> w_a(5, Vector3d::Zero());
  std::vector<Quaterniond> W_a1(5, Quaterniond::Identity()), W_a2(5, Quaterniond::Identity());
  for (int i = 1; i < 5; ++i) W_a2[i] = aa(0.3 * i, Vector3d(1, -1, 2));
  ServoState s1, s2;
  ServoGains g;
  inertial_servo_step(skel, ServoSpace::World, g, I, s, 0.0, 1.0 / 30, W_a1, w_a, s1);
  inertial_servo_step(skel, ServoSpace::World, g, I, s, 0.0, 1.0 / 30, W_a2, w_a, s2);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(s1.W_d[i].coeffs(), s2.W_d[i].coeffs()) << i;
    EXPECT_EQ(s1.omega_d[i], s2.omega_d[i]) << i;
  }
  // ... but the torques do see them (that is the feedback).
  EXPECT_GT((s1.tau[2] - s2.tau[2]).norm(), 1e-3);
}

TEST(DesiredWorldVelocity, LookAheadEqualsAnalyticRateForConstantRate) {
  // Bone 1 turns at a constant rate w about a parent-frame axis; the root is held at a fixed tilted
  // orientation. The world rate is R(root) w exactly, and eq. 2 recovers it exactly for any delta.
  eng::anim::Skeleton skel;
  skel.name = {"root", "bone"};
  skel.parent = {-1, 0};
  skel.offset = {Vector3d::Zero(), Vector3d(0, 0, 1)};
  const Quaterniond root = aa(0.6, Vector3d(1, 2, 0));
  const Vector3d w(0.5, -1.5, 2.0);
  const double t = 0.37;
  for (double delta : {1.0 / 240, 1.0 / 30, 0.2}) {
    Pose now, ahead;
    now.rotation = {root, rotation_from_vector(w * t) * aa(0.2, Vector3d::UnitX())};
    ahead.rotation = {root, rotation_from_vector(w * (t + delta)) * aa(0.2, Vector3d::UnitX())};
    WorldPoseScratch scratch;
    std::vector<Vector3d> omega;
    desired_world_velocity_lookahead(skel, now, root, ahead, root, delta, scratch, omega);
    EXPECT_LT(omega[0].norm(), 1e-12);
    EXPECT_LT((omega[1] - root * w).norm(), 1e-9) << delta;
    // Same through the PoseSample path (extrapolation at the sampled rate), and the analytic composition.
    PoseSample s;
    s.pose = now;
    s.angular_velocity = {Vector3d::Zero(), w};
    desired_world_velocity(skel, s, root, root, delta, DesiredVelocityMode::LookAhead, scratch, omega);
    EXPECT_LT((omega[1] - root * w).norm(), 1e-9) << delta;
    desired_world_velocity(skel, s, root, root, delta, DesiredVelocityMode::Analytic, scratch, omega);
    EXPECT_LT((omega[1] - root * w).norm(), 1e-12) << delta;
  }
}

TEST(DesiredWorldVelocity, LookAheadConvergesToAnalyticOnAMovingChain) {
  const auto skel = test::test_skeleton();
  PoseSample s;
  s.pose = test_pose();
  s.angular_velocity = {Vector3d(0.3, 0.1, 0.7), Vector3d(1, 0, 0), Vector3d(0, 2, 0), Vector3d(0.5, 0.5, -1),
                        Vector3d(0, 0, 3)};
  const Quaterniond root = s.pose.rotation[0];
  WorldPoseScratch scratch;
  std::vector<Vector3d> exact, approx;
  const double delta = 1e-4;
  const Quaterniond root_ahead = integrate_rotation(root, s.angular_velocity[0], delta);
  desired_world_velocity(skel, s, root, root_ahead, delta, DesiredVelocityMode::Analytic, scratch, exact);
  desired_world_velocity(skel, s, root, root_ahead, delta, DesiredVelocityMode::LookAhead, scratch, approx);
  EXPECT_LT((exact[0] - s.angular_velocity[0]).norm(), 1e-9);
  for (int i = 0; i < skel.size(); ++i) EXPECT_LT((exact[i] - approx[i]).norm(), 1e-3) << i;
}
