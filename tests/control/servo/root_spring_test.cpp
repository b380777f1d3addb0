// Root spring (torque limited, consciousness-scaled), paper section V / Fig. 7.
#include "engine/control/servo/root_spring.h"

#include <gtest/gtest.h>

#include "control/control_test_util.h"
#include "engine/control/servo/person_space.h"

using namespace eng::control;
using eng::control::test::aa;
using Eigen::Quaterniond;
using Eigen::Vector3d;

TEST(RootSpring, OffByDefault) {
  RootSpringParams p;
  RootSpring rs;
  const Wrench w = rs.compute(p, 10.0, 70.0, Quaterniond::Identity(), aa(0.5, Vector3d::UnitY()), Vector3d::Zero());
  EXPECT_EQ(w.torque, Vector3d::Zero());
  EXPECT_EQ(w.force, Vector3d::Zero());
}

TEST(RootSpring, PullsTowardUprightAndIsTorqueLimited) {
  RootSpringParams p;
  p.enabled = true;
  p.max_torque = 1e9;
  RootSpring rs;
  const Quaterniond tilted = aa(0.7, Vector3d::UnitZ()) * aa(0.3, Vector3d::UnitY());
  const Quaterniond up = upright_target(tilted);
  EXPECT_NEAR(heading_of(up), 0.7, 1e-12);
  EXPECT_NEAR((up * Vector3d::UnitZ()).z(), 1.0, 1e-12);
  const Wrench w = rs.compute(p, 10.0, 70.0, up, tilted, Vector3d::Zero());
  const Vector3d e = orientation_error(up, tilted);
  EXPECT_LT((w.torque - 10.0 * 36.0 * e).norm(), 1e-9);  // k = I omega_n^2
  p.max_torque = 5.0;
  EXPECT_NEAR(rs.compute(p, 10.0, 70.0, up, tilted, Vector3d::Zero()).torque.norm(), 5.0, 1e-12);
}

TEST(RootSpring, KnockoutDropsGainsAndRecovers) {
  RootSpringParams p;
  p.enabled = true;
  p.position_spring = true;
  RootSpring rs;
  const Quaterniond tilted = aa(0.4, Vector3d::UnitX());
  const Wrench full = rs.compute(p, 10.0, 70.0, Quaterniond::Identity(), tilted, Vector3d::Zero(),
                                 Vector3d(0, 0, 1), Vector3d(0, 0, 0.9), Vector3d::Zero());
  EXPECT_GT(full.force.z(), 0.0);
  rs.hit(p, 0.3);  // light hit: dazed
  EXPECT_NEAR(rs.consciousness(), 0.7, 1e-12);
  const Wrench dazed = rs.compute(p, 10.0, 70.0, Quaterniond::Identity(), tilted, Vector3d::Zero());
  EXPECT_NEAR(dazed.torque.norm(), 0.7 * full.torque.norm(), 1e-9);
  rs.hit(p, 2.0);  // heavy hit: unconscious, gains 0
  EXPECT_EQ(rs.consciousness(), 0.0);
  EXPECT_EQ(rs.compute(p, 10.0, 70.0, Quaterniond::Identity(), tilted, Vector3d::Zero()).torque, Vector3d::Zero());
  const double dt = 1.0 / 60;
  for (double t = 0; t < p.stun_time - 0.1; t += dt) rs.update(p, dt);
  EXPECT_EQ(rs.consciousness(), 0.0);  // still out during the stun
  for (double t = 0; t < 0.1 + 1.0 / p.recovery_rate + 0.1; t += dt) rs.update(p, dt);
  EXPECT_DOUBLE_EQ(rs.consciousness(), 1.0);  // fully recovered
}
