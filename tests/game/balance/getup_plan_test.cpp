// The unassisted get-up's plan (game/balance/getup_plan.h) on its own: the clip's clock runs while the body keeps up
// and waits while it does not, a phase ends only where the next support set carries the com (or the wait is over),
// and the support sets are the ones the clips' keys put the body on.
#include <gtest/gtest.h>

#include "engine/anim/skeleton.h"
#include "game/balance/getup_plan.h"

namespace boxing {
namespace {

constexpr double kDt = 1.0 / 240.0;

eng::anim::Skeleton boxer_skeleton() {
  eng::anim::Skeleton s;
  s.name = {"pelvis", "abdomen", "chest", "head", "upper_arm_l", "forearm_l", "glove_l", "upper_arm_r",
            "forearm_r", "glove_r", "thigh_l", "shank_l", "foot_l", "thigh_r", "shank_r", "foot_r"};
  s.parent.assign(s.name.size(), 0);
  s.parent[0] = -1;
  s.offset.assign(s.name.size(), Eigen::Vector3d::Zero());
  return s;
}

// Carried: the next support set has a polygon and the com is well inside it.
GetUpMeasure carried() {
  GetUpMeasure m;
  m.next_points = 6;
  m.next_inside = 0.1;
  return m;
}

TEST(GetUpPlan, FromTheFrontPushesUpThenHandsAndKneesThenOneKneeThenStands) {
  const GetUpSchedule& s = getup_schedule(false);
  EXPECT_EQ(s.clip, "getup_front");
  ASSERT_EQ(s.phases.size(), 4u);
  EXPECT_EQ(s.phases[0].name, "push_up");
  EXPECT_EQ(s.phases[1].name, "hands_knees");
  EXPECT_EQ(s.phases[2].name, "one_knee");
  EXPECT_EQ(s.phases[3].name, "stand");
  const GetUpSchedule& b = getup_schedule(true);
  EXPECT_EQ(b.clip, "getup_back");
  EXPECT_EQ(b.phases[0].name, "sit_up");
  // The phases tile the clip: each starts where the last ended (the clips' keys).
  for (const GetUpSchedule* sc : {&s, &b})
    for (size_t k = 1; k < sc->phases.size(); ++k) EXPECT_EQ(sc->phases[k].clip_from, sc->phases[k - 1].clip_to);
}

TEST(GetUpPlan, SupportSetsHaveHandsAndKneesThenFeetOnly) {
  const eng::anim::Skeleton sk = boxer_skeleton();
  GetUpPlan p;
  getup_plan_start(p, false, sk);
  EXPECT_EQ(getup_supports(p)[sk.find("chest")], 1);        // lying on it
  EXPECT_EQ(getup_next_supports(p)[sk.find("chest")], 0);   // off the ground on hands and knees
  EXPECT_EQ(getup_next_supports(p)[sk.find("glove_l")], 1);
  EXPECT_EQ(getup_next_supports(p)[sk.find("shank_r")], 1);
  EXPECT_EQ(p.masks.back()[sk.find("glove_l")], 0);          // standing: no hands
  EXPECT_EQ(p.masks.back()[sk.find("foot_l")], 1);
  // A person's strengths (person_strength.h), looked up by bone: the knee's 250 N m, none for the root.
  EXPECT_EQ(p.strength[sk.find("shank_l")], 250.0);
  EXPECT_EQ(p.strength[0], 0.0);
}

TEST(GetUpPlan, TheClipWaitsForABodyBehindIt) {
  const eng::anim::Skeleton sk = boxer_skeleton();
  const GetUpPlanTuning t;
  GetUpPlan p;
  getup_plan_start(p, false, sk);
  GetUpMeasure behind = carried();
  behind.com_error = 2.0 * t.track_tolerance;
  for (int i = 0; i < 240; ++i) EXPECT_EQ(getup_plan_advance(p, t, behind, kDt), 0.0);
  EXPECT_EQ(p.clip_time, 0.0);
  EXPECT_EQ(getup_plan_advance(p, t, carried(), kDt), t.clip_rate);
  EXPECT_NEAR(p.clip_time, t.clip_rate * kDt, 1e-15);  // (one tick's clock, summed once)
}

TEST(GetUpPlan, APhaseEndsOnlyWhereTheNextSupportCarriesTheCom) {
  const eng::anim::Skeleton sk = boxer_skeleton();
  const GetUpPlanTuning t;
  GetUpPlan p;
  getup_plan_start(p, false, sk);
  GetUpMeasure outside = carried();
  outside.next_inside = -0.05;  // the com 5 cm outside the hands' and knees' polygon
  const double phase_ticks = getup_schedule(false).phases[0].clip_to / (t.clip_rate * kDt);
  for (int i = 0; i < int(phase_ticks) + 10; ++i) getup_plan_advance(p, t, outside, kDt);
  EXPECT_EQ(p.phase, 0);
  EXPECT_EQ(p.rate, 0.0);  // held at the key
  getup_plan_advance(p, t, carried(), kDt);
  EXPECT_EQ(p.phase, 1);
  EXPECT_EQ(getup_phase_name(p), "hands_knees");
}

TEST(GetUpPlan, AGateWaitsAtMostMaxHold) {
  const eng::anim::Skeleton sk = boxer_skeleton();
  const GetUpPlanTuning t;
  GetUpPlan p;
  getup_plan_start(p, true, sk);
  GetUpMeasure nothing;  // no support points at all: the gate never opens by itself
  const int phase_ticks = int(getup_schedule(true).phases[0].clip_to / (t.clip_rate * kDt)) + 2;
  const int hold_ticks = int(t.max_hold / kDt);
  for (int i = 0; i < phase_ticks + hold_ticks - 2; ++i) getup_plan_advance(p, t, nothing, kDt);
  EXPECT_EQ(p.phase, 0);
  for (int i = 0; i < 4; ++i) getup_plan_advance(p, t, nothing, kDt);
  EXPECT_EQ(p.phase, 1);
}

}  // namespace
}  // namespace boxing
