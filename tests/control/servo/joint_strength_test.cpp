// The torque-velocity limit (Hill's force-velocity relation at a joint).
#include <gtest/gtest.h>

#include "engine/control/servo/joint_strength.h"

using eng::control::limit_torque_by_speed;
using eng::control::TorqueVelocityLimit;

TEST(JointStrength, FullStrengthAtOrBelowTheFullSpeed) {
  Eigen::VectorXd tau(3), v(3);
  tau << 50.0, -20.0, 10.0;
  v << 20.0, 0.0, 0.0;  // exactly the full-strength speed
  const Eigen::VectorXd before = tau;
  limit_torque_by_speed(tau, v, TorqueVelocityLimit{20.0, 30.0});
  EXPECT_EQ(tau, before);
}

TEST(JointStrength, NoTorqueDrivesAJointFasterPastTheZeroSpeed) {
  Eigen::VectorXd tau(3), v(3);
  tau << 50.0, -20.0, 10.0;
  v << 0.0, 40.0, 0.0;
  limit_torque_by_speed(tau, v, TorqueVelocityLimit{20.0, 30.0});
  // -20 along v already brakes: kept; the components across the motion are kept
  EXPECT_DOUBLE_EQ(tau[0], 50.0);
  EXPECT_DOUBLE_EQ(tau[1], -20.0);
  EXPECT_DOUBLE_EQ(tau[2], 10.0);
  Eigen::VectorXd drive(1), w(1);
  drive << 80.0;
  w << 35.0;
  limit_torque_by_speed(drive, w, TorqueVelocityLimit{20.0, 30.0});
  EXPECT_DOUBLE_EQ(drive[0], 0.0);
}

TEST(JointStrength, StrengthFallsLinearlyBetweenTheTwoSpeedsAndOnlyAlongTheMotion) {
  Eigen::VectorXd tau(3), v(3);
  tau << 100.0, 30.0, 0.0;
  v << 25.0, 0.0, 0.0;  // halfway: half the driving component
  limit_torque_by_speed(tau, v, TorqueVelocityLimit{20.0, 30.0});
  EXPECT_NEAR(tau[0], 50.0, 1e-12);
  EXPECT_NEAR(tau[1], 30.0, 1e-12);
  EXPECT_NEAR(tau[2], 0.0, 1e-12);
  // the power it may add never exceeds the unlimited torque's
  Eigen::VectorXd t2(3), v2(3);
  t2 << 10.0, 20.0, -5.0;
  v2 << 12.0, 16.0, 9.0;
  const double p0 = t2.dot(v2);
  limit_torque_by_speed(t2, v2, TorqueVelocityLimit{20.0, 30.0});
  EXPECT_LT(t2.dot(v2), p0);
  EXPECT_GT(t2.dot(v2), 0.0);
}
