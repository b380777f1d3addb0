// Parent-space PD baseline and the meathook (paper section V).
#include "engine/control/servo/parent_space_servo.h"

#include <gtest/gtest.h>

#include <random>

#include "control/control_test_util.h"

using namespace eng::control;
using eng::control::test::aa;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {
eng::anim::PoseSample sample() {
  eng::anim::PoseSample s;
  s.pose.rotation = {aa(0.2, Vector3d::UnitZ()), aa(0.3, Vector3d::UnitY()), aa(-0.4, Vector3d::UnitX()),
                     aa(1.0, Vector3d(1, 0, 1)), aa(0.6, Vector3d::UnitZ())};
  s.angular_velocity = {Vector3d::Zero(), Vector3d(0.5, 0, 0), Vector3d(0, 1, 0), Vector3d(0, 0, -1),
                        Vector3d(1, 1, 0)};
  return s;
}
}  // namespace

TEST(ParentSpaceServo, ZeroWhenJointsMatchAndNetTorqueZero) {
  const auto skel = test::test_skeleton();
  const auto s = sample();
  const std::vector<double> I = {3, 1, 0.2, 0.1, 0.05};
  // Actual: the desired relative rotations/rates on top of an arbitrary (wrong) root orientation and rate.
  std::vector<Quaterniond> Wa(5);
  std::vector<Vector3d> wa(5);
  Wa[0] = aa(1.0, Vector3d(1, 1, 0));
  wa[0] = Vector3d(0.3, -0.2, 0.9);
  for (int i = 1; i < 5; ++i) {
    const int p = skel.parent[i];
    Wa[i] = Wa[p] * s.pose.rotation[i];
    wa[i] = wa[p] + Wa[p] * s.angular_velocity[i];
  }
  std::vector<Vector3d> tau;
  parent_space_torques(skel, ServoGains{}, I, s, Wa, wa, tau);
  for (int i = 0; i < 5; ++i) EXPECT_LT(tau[i].norm(), 1e-9) << i;  // parent space: blind to the root's error

  // Perturb and check the application path conserves angular momentum (internal torques).
  Wa[2] = aa(0.5, Vector3d::UnitY()) * Wa[2];
  wa[4] += Vector3d(1, 2, 3);
  parent_space_torques(skel, ServoGains{}, I, s, Wa, wa, tau);
  EXPECT_EQ(tau[0], Vector3d::Zero());
  std::vector<Vector3d> applied(5, Vector3d::Zero());  // +tau on the child, -tau on its parent
  for (int i = 1; i < 5; ++i) {
    applied[i] += tau[i];
    applied[skel.parent[i]] -= tau[i];
  }
  Vector3d net = Vector3d::Zero();
  for (const auto& a : applied) net += a;
  EXPECT_LT(net.norm(), 1e-12);
  EXPECT_GT(tau[2].norm(), 1e-3);
}

TEST(ParentSpaceServo, MatchesWorldServoWhenParentIsOnTarget) {
  // With every parent exactly at its lifted desired orientation and rate, parent-space and world-space errors
  // coincide (Delta rotates with the frame), so the torques agree.
  const auto skel = test::test_skeleton();
  const auto s = sample();
  const std::vector<double> I = {3, 1, 0.2, 0.1, 0.05};
  std::vector<Quaterniond> Wd;
  lift_to_world(skel, s.pose, s.pose.rotation[0], Wd);
  std::vector<Vector3d> wd(5);
  wd[0].setZero();
  for (int i = 1; i < 5; ++i) wd[i] = wd[skel.parent[i]] + Wd[skel.parent[i]] * s.angular_velocity[i];
  // Only the leaf (forearm, 4) is off target.
  std::vector<Quaterniond> Wa = Wd;
  std::vector<Vector3d> wa = wd;
  Wa[4] = aa(0.4, Vector3d(0, 1, 1)) * Wd[4];
  wa[4] += Vector3d(0.2, -0.1, 0.3);
  std::vector<Vector3d> tp, tw;
  parent_space_torques(skel, ServoGains{}, I, s, Wa, wa, tp);
  inertial_servo_torques(skel, ServoGains{}, I, Wd, wd, Wa, wa, tw);
  for (int i = 0; i < 5; ++i) EXPECT_LT((tp[i] - tw[i]).norm(), 1e-9) << i;
  EXPECT_GT(tw[4].norm(), 0.01);
}

TEST(Meathook, HoldsAgainstGravityAndRestoresOrientation) {
  MeathookParams p;
  const double M = 70.0, I = 12.0;
  const Vector3d x(0, 0, 1);
  const Quaterniond q = aa(0.3, Vector3d::UnitZ());
  Wrench w = meathook(p, M, I, x, Vector3d::Zero(), q, Vector3d::Zero(), x, Vector3d::Zero(), q, Vector3d::Zero());
  EXPECT_LT((w.force - Vector3d(0, 0, M * 9.81)).norm(), 1e-9);
  EXPECT_LT(w.torque.norm(), 1e-12);
  // Displaced and tilted: pulled back toward the desired root.
  const Quaterniond qa = aa(0.2, Vector3d::UnitY()) * q;
  w = meathook(p, M, I, x, Vector3d::Zero(), q, Vector3d::Zero(), x + Vector3d(0.1, 0, 0), Vector3d::Zero(), qa,
               Vector3d::Zero());
  EXPECT_LT(w.force.x(), 0.0);
  EXPECT_LT(w.torque.y(), 0.0);
  p.max_torque = 1.0;
  p.gravity_compensation = false;
  w = meathook(p, M, I, x, Vector3d::Zero(), q, Vector3d::Zero(), x, Vector3d::Zero(), qa, Vector3d::Zero());
  EXPECT_NEAR(w.torque.norm(), 1.0, 1e-12);
  EXPECT_LT(w.force.norm(), 1e-12);
}
