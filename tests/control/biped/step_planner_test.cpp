// The step planner: the clip's touch-down found by looking ahead, a landing on flat ground is the clip's own, a
// landing across a crate seam moves to the foothold the search finds.
#include "engine/control/biped/step_planner.h"

#include <gtest/gtest.h>

#include <cmath>

#include "control/biped/boxes.h"

using namespace eng::control;
using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

namespace {
// A root and a foot bone at the root (offset 0): the foot's ankle is the root position.
eng::anim::Skeleton foot_skeleton() {
  eng::anim::Skeleton s;
  s.name = {"root", "foot"};
  s.parent = {-1, 0};
  s.offset = {V3::Zero(), V3::Zero()};
  return s;
}
eng::anim::Pose pose_at(const V3& ankle, double yaw) {
  eng::anim::Pose p;
  p.root_position = ankle;
  p.rotation = {Eigen::Quaterniond(Eigen::AngleAxisd(yaw, V3::UnitZ())), Eigen::Quaterniond::Identity()};
  return p;
}
}  // namespace

TEST(StepPlanner, TouchDownIsTheFirstLookAheadFrameWhoseSoleIsBackWithinTheLift) {
  // The ankle comes down at 0.5 m/s from 0.2 m and moves forward at 1 m/s; the sole is 0.08 below the ankle, so
  // the sole gap is 0.12 - 0.5 t and reaches the lift 0.015 at t = 0.21 s: the first 60 Hz frame is 13/60 s.
  const eng::anim::Skeleton s = foot_skeleton();
  const auto preview = [](double t) { return pose_at(V3(1.0 * t, 0.0, 0.2 - 0.5 * t), 0.3); };
  std::vector<Eigen::Quaterniond> W;
  std::vector<V3> P;
  const Touchdown td = find_touchdown(s, preview, 1, FootGeometry{}, StepTuning{}, W, P);
  EXPECT_NEAR(td.ahead, 13.0 / 60.0, 1e-15);
  EXPECT_NEAR(td.travel.x(), 13.0 / 60.0, 1e-12);
  EXPECT_NEAR(td.travel.y(), 0.0, 1e-12);
  EXPECT_NEAR(td.yaw, 0.3, 1e-12);
}

TEST(StepPlanner, ALandingOnFlatGroundIsTheClipsLanding) {
  const control_test::Boxes floor;  // no boxes: the floor at z = 0 everywhere
  const GroundHeight ground = floor.ground();
  Touchdown td;
  td.ahead = 0.25;
  td.travel = V2(0.3, 0.0);  // clip frame: 30 cm forward
  const double heading = M_PI / 2;  // placed facing +Y
  const V3 ankle(1.0, 2.0, 0.1);
  StepPlan st;
  const double dt = 1.0 / 240;
  start_step(st, td, ankle, heading, V3(1.05, 2.0, 0.0), ground, FootGeometry{}, StepTuning{}, dt);
  EXPECT_TRUE(st.active);
  EXPECT_EQ(st.shift, V2::Zero());
  EXPECT_NEAR(st.landing.x(), 1.0, 1e-12);
  EXPECT_NEAR(st.landing.y(), 2.3, 1e-12);  // the clip's travel turned by the heading
  EXPECT_FALSE(st.step_up);
  EXPECT_DOUBLE_EQ(st.duration, 0.25);
  // Mid-swing the target is the clip's own ankle (no shift to ease in), pressed swing_press below it.
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(heading, V3::UnitZ()));
  advance_step(st, ankle, yaw, ground, FootGeometry{}, StepTuning{}, dt);
  EXPECT_NEAR(st.target.x(), ankle.x(), 1e-15);
  EXPECT_NEAR(st.target.y(), ankle.y(), 1e-15);
  EXPECT_NEAR(st.target.z(), 0.1 - StepTuning{}.swing_press, 1e-15);
  EXPECT_NEAR(st.clip_z, 0.1, 1e-15);
}

TEST(StepPlanner, ALandingAcrossACrateSeamMovesToTheFoothold) {
  const control_test::Boxes crates = control_test::two_crates();  // low top 0.30 at x < 0, high 0.40 at x > 0
  const GroundHeight ground = crates.ground();
  Touchdown td;
  td.ahead = 0.2;
  td.travel = V2(0.2, 0.0);
  const V3 ankle(-0.30, 0.0, 0.40);  // the clip lands the ankle at x = -0.10: the toe on the high crate
  StepPlan st;
  const double dt = 0.01;
  const StepTuning t;
  start_step(st, td, ankle, 0.0, V3(-0.25, 0.0, 0.3), ground, FootGeometry{}, t, dt);
  const Foothold f = find_foothold(ground, V2(-0.10, 0.0), 0.0, 0.0, t.foothold);
  ASSERT_TRUE(f.found);
  EXPECT_NEAR(f.shift.x(), -0.08, 1e-9);  // (tests/control/biped/foothold_test.cpp: the same seam)
  EXPECT_EQ(st.shift, f.shift);
  EXPECT_FALSE(st.step_up);  // it lands back on the low crate
  // The shift is eased in: none at the start, all of it at the clip's touch-down (3 u^2 - 2 u^3).
  advance_step(st, ankle, Eigen::Quaterniond::Identity(), ground, FootGeometry{}, t, dt);
  const double u = 0.05;
  EXPECT_NEAR(st.target.x(), ankle.x() + (3 * u * u - 2 * u * u * u) * f.shift.x(), 1e-12);
  for (int i = 1; i < 20; ++i) advance_step(st, ankle, Eigen::Quaterniond::Identity(), ground, FootGeometry{}, t, dt);
  EXPECT_NEAR(st.target.x(), ankle.x() + f.shift.x(), 1e-12);
  // Height: the clip's ankle over its top (0.40 - 0.30), over the highest top under the foot's middle and the landing.
  EXPECT_NEAR(st.clip_z, 0.10, 1e-12);
  EXPECT_NEAR(st.target.z(), 0.10 + 0.30 - t.swing_press, 1e-12);
}

TEST(StepPlanner, ALandingOnAHigherCrateIsAStepUpWithoutThePress) {
  const control_test::Boxes crates = control_test::two_crates();
  const GroundHeight ground = crates.ground();
  Touchdown td;
  td.ahead = 0.2;
  td.travel = V2(0.5, 0.0);  // from the low crate's middle onto the high crate's middle
  StepPlan st;
  start_step(st, td, V3(-0.30, 0.0, 0.40), 0.0, V3(-0.25, 0.0, 0.3), ground, FootGeometry{}, StepTuning{}, 0.01);
  EXPECT_EQ(st.shift, V2::Zero());
  EXPECT_TRUE(st.step_up);
}

// Carried steps (StepTuning::carry): the landing is where the clip has the foot relative to the stance foot at
// touch-down, whatever the anchored placement says; the target follows its own path, with the path's velocity.
TEST(StepPlanner, ACarriedStepLandsWhereTheClipHasItRelativeToTheStanceFoot) {
  const control_test::Boxes floor;  // the floor at z = 0
  const GroundHeight ground = floor.ground();
  const FootGeometry g;
  StepTuning t;
  t.carry = true;
  Touchdown td;
  td.ahead = 0.15;
  td.travel = V2(0.15, 0.0);   // clip frame: 15 cm forward ...
  td.apart = V2(0.40, 0.25);   // ... to 40 cm ahead of and 25 cm left of the other ankle
  const double heading = M_PI / 2;  // placed facing +Y: ahead is +Y, left is -X
  const V2 stance_ankle(0.0, 0.0);
  const V3 ankle_placed(-0.25, 0.20, 0.08);  // the anchored placement: 5 cm off the relative landing's start
  const Eigen::Rotation2Dd yaw(heading);
  const V3 from = V3(-0.25, 0.25, 0.0) + V3((yaw * g.centre.head<2>()).x(), (yaw * g.centre.head<2>()).y(), 0.0);
  StepPlan st;
  const double dt = 1.0 / 240;
  start_step(st, td, ankle_placed, heading, from, ground, g, t, dt, stance_ankle, V2(yaw * g.centre.head<2>()));
  ASSERT_TRUE(st.carried);
  EXPECT_NEAR(st.landing.x(), -0.25, 1e-12);  // stance ankle + R(heading) (0.40, 0.25)
  EXPECT_NEAR(st.landing.y(), 0.40, 1e-12);
  EXPECT_EQ(st.shift, V2::Zero());  // flat floor: no foothold shift
  EXPECT_NEAR((st.path.to - (st.landing + yaw * g.centre.head<2>())).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(st.duration, std::max(0.15, t.carry_lift / t.carry_rise_speed));
  // Mid-swing: the target's velocity is the target's rate (central difference over two ticks).
  const Eigen::Quaterniond foot(Eigen::AngleAxisd(heading, V3::UnitZ()));
  for (int i = 0; i < 16; ++i) advance_step(st, ankle_placed, foot, ground, g, t, dt);  // about 0.45 of the swing
  const V3 before = st.target;
  advance_step(st, ankle_placed, foot, ground, g, t, dt);
  const V3 v = st.velocity;
  advance_step(st, ankle_placed, foot, ground, g, t, dt);
  ASSERT_TRUE(st.has_velocity);
  EXPECT_NEAR((v - (st.target - before) / (2 * dt)).norm(), 0.0, 0.02 * v.norm() + 1e-3);
  EXPECT_GT(v.head<2>().norm(), 0.5);  // it is moving (15 cm in 0.15 s)
  // At the end: on the landing (the sole centre pressed carry_press into the floor).
  for (int i = 0; i < 60; ++i) advance_step(st, ankle_placed, foot, ground, g, t, dt);
  const V3 sole = st.target + foot * g.sole_offset();
  EXPECT_NEAR((sole.head<2>() - st.path.to).norm(), 0.0, 1e-9);
  EXPECT_NEAR(sole.z(), -t.carry_press, 1e-9);
  // A landing that far from the foot (the body turned off the heading: more than carry_max_extra past the clip's
  // travel) falls back to the placement's.
  StepPlan turned;
  start_step(turned, td, ankle_placed, heading, from, ground, g, t, dt, V2(-1.0, 0.0), V2(-1.0, 0.0));
  EXPECT_NEAR(turned.landing.x(), ankle_placed.x(), 1e-12);
  EXPECT_NEAR(turned.landing.y(), ankle_placed.y() + 0.15, 1e-12);
}

TEST(StepPlanner, ACarriedStepUpPastAHigherEdgeRisesAboveItBeforeItTravels) {
  // Stepping back (-X) from the low crate's twin at x > 0 (top 0.30) onto a higher one at x < 0 (top 0.40): the sole
  // centre starts 12 cm from the higher crate's side, its heel 1 cm off it (carried walk seed 3: the heel caught the
  // edge as the target travelled from the start). The target may not come nearer the side until the sole is
  // carry_edge_clearance above the higher top, and the rise keeps to carry_rise_speed.
  control_test::Boxes crates;
  crates.boxes.push_back({{0.25, 0.0, 0.15}, {0.244, 0.244, 0.15}});
  crates.boxes.push_back({{-0.25, 0.0, 0.20}, {0.244, 0.244, 0.20}});
  const GroundHeight ground = crates.ground();
  const FootGeometry g;
  StepTuning t;
  t.carry = true;
  Touchdown td;
  td.ahead = 0.15;
  td.travel = V2(-0.22, 0.0);
  td.apart = V2(0.25, 0.0);  // lands 25 cm ahead of the stance ankle
  const V2 stance_ankle(-0.40, -0.25);
  const V3 from(0.126, 0.0, 0.30);  // sole centre
  const V2 stance_centre = stance_ankle + g.centre.head<2>();
  StepPlan st;
  const double dt = 1.0 / 240;
  start_step(st, td, V3(0.126 - g.centre.x(), 0.0, 0.38), 0.0, from, ground, g, t, dt, stance_ankle, stance_centre);
  ASSERT_TRUE(st.carried);
  ASSERT_NEAR(st.path.from_top, 0.30, 1e-12);
  ASSERT_NEAR(st.path.to_top, 0.40, 1e-12);
  const double rise = 0.40 + t.carry_lift - 0.30;
  EXPECT_GE(st.duration, rise / t.carry_rise_speed / 0.5 - 1e-12) << "the rise, at most half the swing";
  EXPECT_NEAR(st.path.rise_until * st.duration, rise / t.carry_rise_speed, 1e-12);
  const Eigen::Quaterniond foot = Eigen::Quaterniond::Identity();
  double peak_rate = 0.0, prev_z = -1.0;
  for (int i = 0; st.elapsed < st.duration; ++i) {
    advance_step(st, V3::Zero(), foot, ground, g, t, dt);
    const V3 sole = st.target + foot * g.sole_offset();
    const bool below = sole.z() < 0.40 + t.carry_edge_clearance - 1e-9;
    if (below && st.elapsed < 0.5 * st.duration) {
      EXPECT_NEAR(sole.x(), from.x(), 1e-9) << "travels while still below the higher top, at t = " << st.elapsed;
    }
    if (prev_z >= 0.0 && st.elapsed < 0.5 * st.duration) peak_rate = std::max(peak_rate, (sole.z() - prev_z) / dt);
    prev_z = sole.z();
  }
  EXPECT_LE(peak_rate, 1.5 * t.carry_rise_speed + 1e-6);  // smoothstep's peak rate is 1.5 times its mean
  const V3 end = st.target + foot * g.sole_offset();
  EXPECT_NEAR(end.x(), st.path.to.x(), 1e-9);
  EXPECT_NEAR(end.z(), 0.40 - t.carry_press, 1e-9);
}
