// Eq. 3 as implicit joint springs (implicit_servo.h): gain rule, references, torque limit.
#include "engine/control/servo/implicit_servo.h"

#include <gtest/gtest.h>

#include "engine/control/servo/composite_inertia.h"
#include "engine/control/servo/orientation_error.h"

using namespace eng::control;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {
Quaterniond aa(double a, const Vector3d& ax) { return Quaterniond(Eigen::AngleAxisd(a, ax.normalized())); }

eng::anim::Skeleton chain2() {
  eng::anim::Skeleton skel;
  skel.name = {"a", "b"};
  skel.parent = {-1, 0};
  skel.offset = {Vector3d::Zero(), Vector3d(0.4, 0, 0)};
  return skel;
}
}  // namespace

TEST(ImplicitServo, GainRuleFreeBoneIsSubtreeSupportBoneIsLoadSide) {
  const auto skel = chain2();
  const std::vector<double> m = {2.0, 1.0};
  const std::vector<Vector3d> com = {Vector3d(0, 0, 0.1), Vector3d(0.2, 0, 0.1)};
  const std::vector<Matrix3d> I = {Vector3d(0.1, 0.2, 0.3).asDiagonal(), Vector3d(0.01, 0.05, 0.05).asDiagonal()};
  // Free: same as composite_inertias (subtree about the joint).
  const auto sub = composite_inertias(skel, m, com, I);
  const auto free_rule = servo_inertias(skel, m, com, I, {false, false}, 2);
  EXPECT_NEAR(free_rule[1], sub[1], 1e-12);
  EXPECT_NEAR(free_rule[0], sub[0], 1e-12);
  // Support: body a about joint b at (0.4,0,0): r = (-0.4,0,0.1), |r|^2 = .17:
  //   diag(.1,.2,.3) + 2 [[.01,0,.04],[0,.17,0],[.04,0,.16]] -> trace 1.28, /3, shared by 2 legs.
  const auto sup_rule = servo_inertias(skel, m, com, I, {false, true}, 2);
  EXPECT_NEAR(sup_rule[1], 1.28 / 3.0 / 2.0, 1e-12);
  const auto path = support_path(skel, {1});
  EXPECT_FALSE(path[0]);  // the root is no joint
  EXPECT_TRUE(path[1]);
}

TEST(ImplicitServo, SpringTorqueIsEq3ProportionalTermToFirstOrder) {
  const auto skel = chain2();
  std::vector<ImplicitServoJoint> j(2);
  j[1].kind = JointKind::Ball;
  j[1].K = 100.0;
  j[1].D = 0.0;
  const Quaterniond Wp = aa(0.3, Vector3d(1, 2, 3));
  const Quaterniond q_rel = aa(0.2, Vector3d(0, 1, 0));
  const std::vector<Quaterniond> W_a = {Wp, Wp * q_rel};
  const std::vector<Quaterniond> W_d = {Wp, aa(0.01, Vector3d(1, 0, 1)) * W_a[1]};  // small world error
  const std::vector<Vector3d> zero(2, Vector3d::Zero());
  const std::vector<Vector3d> q_a = {Vector3d::Zero(), quaternion_log_vector(q_rel)};
  std::vector<Vector3d> ref;
  implicit_servo_refs(skel, j, W_d, zero, W_a, zero, q_a, 1.0 / 240.0, ref);
  const Vector3d tau = implicit_servo_spring_torque(j[1], W_a[1], ref[1], q_a[1]);
  const Vector3d eq3 = j[1].K * orientation_error(W_d[1], W_a[1]);
  EXPECT_LT((tau - eq3).norm(), 1e-6 * j[1].K + 1e-3 * eq3.norm());
  // The joint torque acts +tau on the bone and -tau on its parent: internal, sums to zero by construction.
}

TEST(ImplicitServo, SupportJointControlsTheParent) {
  const auto skel = chain2();
  std::vector<ImplicitServoJoint> j(2);
  j[1].kind = JointKind::Ball;
  j[1].K = 100.0;
  j[1].support = true;
  // Child (the "foot") held level, parent (the "shank") tilted 0.1 rad away from its desired upright.
  const std::vector<Quaterniond> W_a = {aa(0.1, Vector3d::UnitY()), Quaterniond::Identity()};
  const std::vector<Quaterniond> W_d = {Quaterniond::Identity(), Quaterniond::Identity()};
  const std::vector<Vector3d> zero(2, Vector3d::Zero());
  const Quaterniond q_rel = W_a[0].conjugate() * W_a[1];
  const std::vector<Vector3d> q_a = {Vector3d::Zero(), quaternion_log_vector(q_rel)};
  std::vector<Vector3d> ref;
  implicit_servo_refs(skel, j, W_d, zero, W_a, zero, q_a, 1.0 / 240.0, ref);
  const Vector3d tau_child = implicit_servo_spring_torque(j[1], W_a[1], ref[1], q_a[1]);
  // The parent gets -tau_child: it must be K * (its world error) = K * (-0.1 about Y).
  EXPECT_LT((-tau_child - j[1].K * orientation_error(W_d[0], W_a[0])).norm(), 1e-6);
}

TEST(ImplicitServo, TorqueLimitClampsTheSpring) {
  const auto skel = chain2();
  std::vector<ImplicitServoJoint> j(2);
  j[1].kind = JointKind::Hinge;
  j[1].axis = Vector3d::UnitY();
  j[1].K = 1000.0;
  j[1].limit = 50.0;
  const std::vector<Quaterniond> W_a = {Quaterniond::Identity(), Quaterniond::Identity()};
  const std::vector<Quaterniond> W_d = {Quaterniond::Identity(), aa(1.0, Vector3d::UnitY())};
  const std::vector<Vector3d> zero(2, Vector3d::Zero());
  std::vector<Vector3d> ref;
  implicit_servo_refs(skel, j, W_d, zero, W_a, zero, zero, 1.0 / 240.0, ref);
  EXPECT_NEAR(j[1].K * ref[1].x(), 50.0, 1e-9);
}

TEST(ImplicitServo, PlantedTwistScaleWeakensOnlyTheFootTwist) {
  const auto skel = chain2();
  std::vector<ImplicitServoJoint> j(2);
  j[1].kind = JointKind::Ball;
  j[1].K = 100.0;
  j[1].support = true;
  j[1].planted = true;
  // Foot (child) actually yawed 0.2 rad and pitched 0.1 rad against its desired (identity); shank as desired.
  const Quaterniond foot = aa(0.2, Vector3d::UnitZ()) * aa(0.1, Vector3d::UnitY());
  const std::vector<Quaterniond> W_a = {Quaterniond::Identity(), foot};
  const std::vector<Quaterniond> W_d = {Quaterniond::Identity(), Quaterniond::Identity()};
  const std::vector<Vector3d> zero(2, Vector3d::Zero());
  const std::vector<Vector3d> q_a = {Vector3d::Zero(), quaternion_log_vector(foot)};
  std::vector<Vector3d> full, weak;
  implicit_servo_refs(skel, j, W_d, zero, W_a, zero, q_a, 1.0 / 240.0, full);
  j[1].twist_scale = 0.25;
  implicit_servo_refs(skel, j, W_d, zero, W_a, zero, q_a, 1.0 / 240.0, weak);
  const Vector3d tf = W_a[1].conjugate() * implicit_servo_spring_torque(j[1], W_a[1], full[1], q_a[1]);
  const Vector3d tw = W_a[1].conjugate() * implicit_servo_spring_torque(j[1], W_a[1], weak[1], q_a[1]);
  EXPECT_GT(std::abs(tf.z()), 1.0);
  EXPECT_NEAR(tw.z(), 0.25 * tf.z(), 0.05 * std::abs(tf.z()));  // twist (foot frame z) scaled
  EXPECT_NEAR(tw.y(), tf.y(), 0.05 * std::abs(tf.y()) + 1e-9);  // tilt untouched
}
