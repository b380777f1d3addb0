// control_step dispatch over the four servo spaces.
#include "engine/control/servo/controller.h"

#include <gtest/gtest.h>

#include "control/control_test_util.h"

using namespace eng::control;
using eng::control::test::aa;
using Eigen::Quaterniond;
using Eigen::Vector3d;

TEST(Controller, SpacesRouteToTheRightServoAndSupport) {
  const auto skel = test::test_skeleton();
  eng::anim::PoseSample s;
  s.pose.root_position = Vector3d(0, 0, 1);
  s.pose.rotation.assign(5, Quaterniond::Identity());
  s.angular_velocity.assign(5, Vector3d::Zero());
  std::vector<Quaterniond> Wa(5, Quaterniond::Identity());
  Wa[0] = aa(0.3, Vector3d::UnitY());  // the pelvis leans
  for (int i = 1; i < 5; ++i) Wa[i] = Wa[0];  // joints straight (parent space is happy)
  std::vector<Vector3d> wa(5, Vector3d::Zero());
  ActualState act{&Wa, &wa, Vector3d(0, 0, 0.95), Vector3d::Zero()};
  ControlBody body{{10, 3, 0.3, 0.2, 0.05}, 70.0};
  ServoState st;
  Wrench help;
  const MeathookParams hook;

  control_step(skel, ServoSpace::World, ServoGains{}, body, hook, s, 0.0, 1.0 / 30, act, st, help);
  EXPECT_EQ(st.tau[0], Vector3d::Zero());
  EXPECT_EQ(help.force, Vector3d::Zero());
  EXPECT_GT(st.tau[1].norm(), 1.0);  // world space sees the lean through every bone and straightens them

  control_step(skel, ServoSpace::Parent, ServoGains{}, body, hook, s, 0.0, 1.0 / 30, act, st, help);
  for (int i = 0; i < 5; ++i) EXPECT_LT(st.tau[i].norm(), 1e-9);  // parent space is blind to the lean
  EXPECT_EQ(help.force, Vector3d::Zero());

  control_step(skel, ServoSpace::ParentMeathook, ServoGains{}, body, hook, s, 0.0, 1.0 / 30, act, st, help);
  EXPECT_GT(help.force.z(), 70.0 * 9.81);  // holds the weight and lifts toward the desired height
  EXPECT_LT(help.torque.y(), 0.0);         // and un-leans the pelvis
}
