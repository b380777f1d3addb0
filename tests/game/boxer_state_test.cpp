// The boxer's state machine: a fall (pelvis low, or a link other than feet and shanks on the ground too long) takes
// Guard to Down once, with the reason; the standing height is the first update's.
#include "game/boxer_state.h"

#include <gtest/gtest.h>

using namespace boxing;

TEST(BoxerState, APelvisBelowHalfItsStandingHeightGoesDownOnce) {
  BoxerStateMachine s;
  const FallTuning t;
  const double dt = 0.01;
  EXPECT_FALSE(boxer_state_update(s, t, 0.90, false, 0.01, dt));  // stands at 0.90 m: the standing height
  EXPECT_DOUBLE_EQ(s.standing_height, 0.90);
  EXPECT_FALSE(boxer_state_update(s, t, 0.46, false, 0.02, dt));  // above 0.45: still in guard
  EXPECT_EQ(s.state, BoxerState::Guard);
  EXPECT_TRUE(boxer_state_update(s, t, 0.44, false, 0.03, dt));
  EXPECT_EQ(s.state, BoxerState::Down);
  EXPECT_TRUE(s.fallen());
  EXPECT_DOUBLE_EQ(s.since, 0.03);
  EXPECT_STREQ(s.reason, "pelvis below half its standing height");
  EXPECT_FALSE(boxer_state_update(s, t, 0.10, false, 0.04, dt)) << "down is entered once";
  EXPECT_DOUBLE_EQ(s.standing_height, 0.90);
}

TEST(BoxerState, ALinkOnTheGroundLongerThanTheLimitGoesDownAndABriefTouchDoesNot) {
  BoxerStateMachine s;
  const FallTuning t;  // 0.2 s
  const double dt = 0.05;
  double time = 0.0;
  // A hand brushing a crate for 0.15 s, then off: the count restarts.
  for (int i = 0; i < 3; ++i) EXPECT_FALSE(boxer_state_update(s, t, 0.9, true, time += dt, dt));
  EXPECT_FALSE(boxer_state_update(s, t, 0.9, false, time += dt, dt));
  EXPECT_EQ(s.ground_contact_time, 0.0);
  // On the ground: down on the first update past 0.2 s (the fifth of 0.05 s).
  int ticks = 0;
  bool down = false;
  while (!down && ticks < 10) down = boxer_state_update(s, t, 0.9, true, time += dt, dt), ++ticks;
  EXPECT_TRUE(down);
  EXPECT_EQ(ticks, 5);
  EXPECT_EQ(s.state, BoxerState::Down);
  EXPECT_STREQ(s.reason, "a link other than feet and shanks touched the ground for 0.2 s");
}

TEST(BoxerState, StatesHaveTheirNames) {
  EXPECT_STREQ(boxer_state_name(BoxerState::Guard), "guard");
  EXPECT_STREQ(boxer_state_name(BoxerState::Down), "down");
  EXPECT_STREQ(boxer_state_name(BoxerState::GettingUp), "getting-up");
}
