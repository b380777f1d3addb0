// The keyboard's fight layout (game/interaction/fight_keys.h): every fight action on each half, no key shared by the
// halves, the modifiers counting only on their own half, and the halves going to their boxers.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <set>
#include <string>

#include "game/interaction/fight_keys.h"
#include "game/interaction/input_events.h"

using namespace boxing;

TEST(FightKeys, EachHalfHasEveryFightActionOnce) {
  for (KeyHalf half : {KeyHalf::Left, KeyHalf::Right}) {
    std::multiset<std::string> actions;
    for (const FightKey& k : fight_keys())
      if (k.half == half) actions.insert(k.action);
    for (const char* a : kKeyActions) EXPECT_EQ(actions.count(a), 1u) << a << " on half " << int(half);
    EXPECT_EQ(actions.size(), size_t(kKeyActionCount));
  }
}

TEST(FightKeys, TheHalvesShareNoKeyAndNoKeyTheWindowUses) {
  std::set<int> left, right;
  for (const FightKey& k : fight_keys()) (k.half == KeyHalf::Left ? left : right).insert(k.key);
  for (int key : left) EXPECT_EQ(right.count(key), 0u) << "key " << key << " on both halves";
  // The window's own keys while playing (app.cpp, control_panel.cpp): throws, ghost, camera, debug, pause, panel.
  for (int key : {GLFW_KEY_T, GLFW_KEY_Y, GLFW_KEY_G, GLFW_KEY_C, GLFW_KEY_H, GLFW_KEY_P, GLFW_KEY_TAB,
                  GLFW_KEY_ESCAPE, GLFW_KEY_1, GLFW_KEY_2, GLFW_KEY_3, GLFW_KEY_4, GLFW_KEY_5, GLFW_KEY_PERIOD,
                  GLFW_KEY_LEFT_BRACKET, GLFW_KEY_RIGHT_BRACKET, GLFW_KEY_BACKSPACE, GLFW_KEY_F12})
    EXPECT_TRUE(left.count(key) == 0 && right.count(key) == 0) << "key " << key << " is the window's";
}

TEST(FightKeys, ShiftTurnsTheMovementKeysIntoDefenceOnItsOwnHalf) {
  EXPECT_STREQ(fight_key(GLFW_KEY_W, 0)->action, "step_forward");
  EXPECT_STREQ(fight_key(GLFW_KEY_W, kHeldLeftShift)->action, "block");
  EXPECT_STREQ(fight_key(GLFW_KEY_A, kHeldLeftShift)->action, "slip_left");
  EXPECT_STREQ(fight_key(GLFW_KEY_D, kHeldLeftShift)->action, "slip_right");
  EXPECT_STREQ(fight_key(GLFW_KEY_S, kHeldLeftShift)->action, "duck");
  EXPECT_STREQ(fight_key(GLFW_KEY_Q, 0)->action, "pivot_left");
  EXPECT_STREQ(fight_key(GLFW_KEY_E, 0)->action, "pivot_right");
  EXPECT_STREQ(fight_key(GLFW_KEY_R, 0)->action, "jab");
  EXPECT_STREQ(fight_key(GLFW_KEY_UP, kHeldRightShift)->action, "block");
  EXPECT_STREQ(fight_key(GLFW_KEY_DOWN, kHeldRightShift)->action, "duck");
  EXPECT_STREQ(fight_key(GLFW_KEY_LEFT, kHeldRightCtrl)->action, "pivot_left");
  EXPECT_STREQ(fight_key(GLFW_KEY_J, 0)->action, "jab");
  // The other half's modifier does not count: player 2 holding Right Shift does not turn player 1's A into a slip.
  EXPECT_STREQ(fight_key(GLFW_KEY_A, kHeldRightShift)->action, "step_left");
  EXPECT_STREQ(fight_key(GLFW_KEY_LEFT, kHeldLeftShift | kHeldLeftCtrl)->action, "step_left");
  EXPECT_STREQ(fight_key(GLFW_KEY_J, kHeldLeftShift)->action, "jab");
  // A combination that is no action gives none (rather than the key without its modifier).
  EXPECT_EQ(fight_key(GLFW_KEY_R, kHeldLeftShift), nullptr);
  EXPECT_EQ(fight_key(GLFW_KEY_W, kHeldLeftCtrl), nullptr);
  EXPECT_EQ(fight_key(GLFW_KEY_T, 0), nullptr);
}

TEST(FightKeys, TheHalvesGoToTheirBoxersInVersusAndAllToThePlayerAlone) {
  EXPECT_EQ(key_boxer(KeyHalf::Left, 0, true, 0), 0);
  EXPECT_EQ(key_boxer(KeyHalf::Right, 0, true, 0), 1);
  EXPECT_EQ(key_boxer(KeyHalf::Right, 1, true, 0), 0) << "one pad is blue's: the whole keyboard red's";
  EXPECT_EQ(key_boxer(KeyHalf::Right, 2, true, 0), 1) << "two pads: the halves as without";
  EXPECT_EQ(key_boxer(KeyHalf::Left, 0, false, 1), 1);
  EXPECT_EQ(key_boxer(KeyHalf::Right, 0, false, 1), 1);
  EXPECT_EQ(key_boxer(KeyHalf::Right, 0, false, -1), 0);
  // What the name plates say.
  EXPECT_EQ(controls_tag(0, 0, true, 0), "LEFT KEYS");
  EXPECT_EQ(controls_tag(1, 0, true, 0), "RIGHT KEYS");
  EXPECT_EQ(controls_tag(0, 1, true, 0), "KEYS");
  EXPECT_EQ(controls_tag(1, 1, true, 0), "PAD 1");
  EXPECT_EQ(controls_tag(0, 2, true, 0), "LEFT KEYS + PAD 1");
  EXPECT_EQ(controls_tag(1, 2, true, 0), "RIGHT KEYS + PAD 2");
  EXPECT_EQ(controls_tag(0, 1, false, 0), "KEYS + PAD 1");
  EXPECT_EQ(controls_tag(1, 1, false, 0), "");
}
