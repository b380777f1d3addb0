// The gamepad's mapping (game/interaction/gamepad.h) with injected pad states: each button and trigger gives its
// action once per press, the stick steps in its four directions past the threshold and repeats while held at
// kStepRepeat, and a pad that appears or disappears (hot-plug) starts from rest / forgets what it held.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "game/interaction/gamepad.h"

using namespace boxing;

namespace {

PadState pad() {
  PadState s;
  s.connected = true;
  return s;
}

std::vector<std::string> names(const PadActions& a) {
  std::vector<std::string> out;
  for (int i = 0; i < a.count; ++i) out.push_back(a.action[i]);
  return out;
}

using Names = std::vector<std::string>;

}  // namespace

TEST(Gamepad, EachButtonGivesItsActionOnceWhenItGoesDown) {
  const std::pair<PadButton, const char*> cases[] = {
      {kPadX, "jab"},        {kPadY, "cross"},         {kPadA, "lead_hook"},          {kPadB, "rear_hook"},
      {kPadLeftBumper, "lead_uppercut"}, {kPadRightBumper, "rear_uppercut"}, {kPadLeftThumb, "pivot_left"},
      {kPadRightThumb, "pivot_right"}};
  for (const auto& [button, action] : cases) {
    PadReader r;
    EXPECT_TRUE(names(pad_update(r, pad(), 0.0)).empty());
    PadState down = pad();
    down.buttons[button] = true;
    EXPECT_EQ(names(pad_update(r, down, 0.1)), Names{action}) << kPadButtonNames[button];
    // Held: nothing more, however long (a held punch button is one punch).
    EXPECT_TRUE(names(pad_update(r, down, 0.2)).empty());
    EXPECT_TRUE(names(pad_update(r, down, 5.0)).empty());
    EXPECT_TRUE(names(pad_update(r, pad(), 5.1)).empty());  // let go
    EXPECT_EQ(names(pad_update(r, down, 5.2)), Names{action}) << "pressed again";
  }
  // Back, Start and Guide are the window's (Start: the pause menu), never a fight action.
  for (PadButton b : {kPadBack, kPadStart, kPadGuide}) {
    PadReader r;
    PadState down = pad();
    down.buttons[b] = true;
    EXPECT_TRUE(names(pad_update(r, down, 0.0)).empty()) << kPadButtonNames[b];
  }
}

TEST(Gamepad, TwoButtonsTogetherGiveBothActions) {
  PadReader r;
  pad_update(r, pad(), 0.0);
  PadState both = pad();
  both.buttons[kPadX] = both.buttons[kPadY] = true;
  EXPECT_EQ(names(pad_update(r, both, 0.1)), (Names{"jab", "cross"}));
}

TEST(Gamepad, TriggersBlockAndDuckPastHalfWayWithHysteresis) {
  for (int k = 0; k < 2; ++k) {
    const char* action = k == 0 ? "block" : "duck";
    PadReader r;
    PadState s = pad();
    auto pull = [&](float share) {  // a trigger's axis runs -1 (out) .. 1 (pulled)
      s.axes[kPadLeftTrigger + k] = 2.0f * share - 1.0f;
      return names(pad_update(r, s, 0.0));
    };
    EXPECT_TRUE(pull(0.45f).empty()) << "below kPressAt = 0.5";
    EXPECT_EQ(pull(0.55f), Names{action});
    EXPECT_TRUE(pull(1.0f).empty()) << "held";
    EXPECT_TRUE(pull(0.40f).empty()) << "eased to 0.40: still above kReleaseAt = 0.35, not re-armed";
    EXPECT_TRUE(pull(0.60f).empty()) << "so pulling again is no new press";
    EXPECT_TRUE(pull(0.30f).empty()) << "released below 0.35";
    EXPECT_EQ(pull(0.60f), Names{action}) << "a new press";
  }
}

TEST(Gamepad, TheRightStickSlipsLeftAndRight) {
  PadReader r;
  PadState s = pad();
  auto stick = [&](float x) {
    s.axes[kPadRightX] = x;
    return names(pad_update(r, s, 0.0));
  };
  EXPECT_TRUE(stick(-0.45f).empty());
  EXPECT_EQ(stick(-0.7f), Names{"slip_left"});
  EXPECT_TRUE(stick(-1.0f).empty()) << "held: one slip";
  EXPECT_EQ(stick(0.9f), Names{"slip_right"}) << "flicked across";
  EXPECT_TRUE(stick(0.4f).empty()) << "above kReleaseAt: still held";
  EXPECT_TRUE(stick(0.0f).empty());
  EXPECT_EQ(stick(0.6f), Names{"slip_right"});
}

TEST(Gamepad, TheLeftStickStepsInItsFourDirectionsPastTheThreshold) {
  // GLFW's (SDL's) sticks: up is negative y.
  const struct {
    float x, y;
    const char* action;
  } cases[] = {{0.0f, -0.8f, "step_forward"}, {0.0f, 0.8f, "step_back"}, {-0.8f, 0.0f, "step_left"},
               {0.8f, 0.0f, "step_right"},   {0.6f, -0.7f, "step_forward"},  // the larger component decides
               {-0.7f, 0.6f, "step_left"}};
  for (const auto& c : cases) {
    PadReader r;
    PadState s = pad();
    s.axes[kPadLeftX] = c.x, s.axes[kPadLeftY] = c.y;
    EXPECT_EQ(names(pad_update(r, s, 0.0)), Names{c.action}) << c.x << ", " << c.y;
  }
  // Within the threshold (a resting stick's drift, a small tilt): no step.
  PadReader r;
  PadState s = pad();
  s.axes[kPadLeftX] = 0.45f, s.axes[kPadLeftY] = -0.3f;
  EXPECT_TRUE(names(pad_update(r, s, 0.0)).empty());
  // The d-pad steps too.
  s = pad();
  s.buttons[kPadDpadLeft] = true;
  EXPECT_EQ(names(pad_update(r, s, 0.1)), Names{"step_left"});
}

TEST(Gamepad, AHeldStickRepeatsItsStepAtTheFootworksPace) {
  PadReader r;
  PadState s = pad();
  s.axes[kPadLeftY] = -1.0f;
  int steps = 0;
  std::vector<double> at;
  // 3 s held, read every physics step (240 Hz) as the world does.
  for (int i = 0; i <= 720; ++i) {
    const double t = i / 240.0;
    for (const std::string& a : names(pad_update(r, s, t))) {
      EXPECT_EQ(a, "step_forward");
      ++steps, at.push_back(t);
    }
  }
  // At 0, 0.75, 1.5, 2.25, 3.0 s: every kStepRepeat.
  ASSERT_EQ(steps, 5);
  for (size_t i = 1; i < at.size(); ++i) EXPECT_NEAR(at[i] - at[i - 1], kStepRepeat, 1.0 / 240.0 + 1e-9);
  // Eased back to 0.4 (above kReleaseAt) it stays held and keeps repeating; below 0.35 it stops.
  s.axes[kPadLeftY] = -0.4f;
  EXPECT_EQ(names(pad_update(r, s, 3.76)), Names{"step_forward"});
  s.axes[kPadLeftY] = -0.3f;
  EXPECT_TRUE(names(pad_update(r, s, 4.6)).empty());
  // A new direction steps at once, whatever the repeat's clock says.
  s.axes[kPadLeftY] = 0.0f, s.axes[kPadLeftX] = 0.9f;
  EXPECT_EQ(names(pad_update(r, s, 4.61)), Names{"step_right"});
  s.axes[kPadLeftX] = 0.0f, s.axes[kPadLeftY] = 0.9f;
  EXPECT_EQ(names(pad_update(r, s, 4.62)), Names{"step_back"});
}

TEST(Gamepad, HotPlugAPadThatAppearsStartsFromRestAndOneThatGoesForgetsItsHolds) {
  PadReader r;
  PadState gone;  // connected = false
  PadState s = pad();
  s.buttons[kPadX] = true;
  s.axes[kPadLeftY] = -1.0f;
  s.axes[kPadRightTrigger] = 1.0f;
  EXPECT_TRUE(names(pad_update(r, gone, 0.0)).empty()) << "no pad: nothing";
  // It appears with X, the stick and RT held: they count as pressed now.
  EXPECT_EQ(names(pad_update(r, s, 0.1)), (Names{"jab", "duck", "step_forward"}));
  // Pulled out while held: nothing, and no held step repeats any more.
  EXPECT_TRUE(names(pad_update(r, gone, 0.2)).empty());
  EXPECT_TRUE(names(pad_update(r, gone, 2.0)).empty());
  EXPECT_EQ(r.step_dir, -1);
  // Plugged in again still held: the same presses again (it starts from rest, not from before it went).
  EXPECT_EQ(names(pad_update(r, s, 2.1)), (Names{"jab", "duck", "step_forward"}));
}

TEST(Gamepad, PadsGoToThePlayerOrInVersusByTheAssignmentRule) {
  // One player: every pad drives the player's boxer (red when none is named).
  EXPECT_EQ(pad_boxer(0, 1, false, 1), 1);
  EXPECT_EQ(pad_boxer(1, 2, false, 1), 1);
  EXPECT_EQ(pad_boxer(0, 1, false, -1), 0);
  // Versus: one pad is blue's (the keyboard red's); two: the first red's, the second blue's; a third nobody's.
  EXPECT_EQ(pad_boxer(0, 1, true, 0), 1);
  EXPECT_EQ(pad_boxer(0, 2, true, 0), 0);
  EXPECT_EQ(pad_boxer(1, 2, true, 0), 1);
  EXPECT_EQ(pad_boxer(2, 3, true, 0), -1);
}
