// The input-event file form (game/interaction/input_events.h): every kind parses, writes back the same, and a bad
// file gets one error naming the event and the field.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "game/interaction/input_events.h"
#include "test_paths.h"

using boxing::InputEvent;
using boxing::InputKind;

namespace {
nlohmann::json every_kind() {
  return nlohmann::json::parse(R"({"events": [
    {"t": 0.5, "drag": {"boxer": 0, "bone": "head", "offset": [0, 0.35, 0], "duration": 1.0}},
    {"t": 0.6, "drag": {"boxer": 1, "bone": "chest", "offset": [0, 0, -0.3], "duration": 1.5, "strong": true,
                        "point": [0.01, 0.02, 0.03]}},
    {"t": 1.0, "grab": {"boxer": 1, "bone": "hand_l", "point": [0.1, 0.2, 0.3], "strong": true}},
    {"t": 1.1, "move": {"target": [1, 2, 3]}},
    {"t": 1.2, "release": {}},
    {"t": 1.3, "grab": {"object": 2}},
    {"t": 2.0, "throw": {"object": "ball", "at_boxer": 1, "speed": 8.0}},
    {"t": 2.1, "throw": {"object": "crate", "from": [0, -3, 1], "velocity": [0, 8, 1.5]}},
    {"t": 2.5, "clear": {}},
    {"t": 3.0, "push": {"boxer": 0, "force": [300, 0, 0], "duration": 0.1}},
    {"t": 3.5, "key": {"action": "jab", "boxer": 1}},
    {"t": 4.0, "set": {"boxer": 0, "servo": "person", "balance": "pd", "omega_n": 12.5, "root_spring": "on",
                       "root_limit": 300, "control": "player", "consciousness": 0.5}},
    {"t": 4.5, "pad": {"pad": 1, "buttons": {"x": true, "dpad_up": true}, "axes": {"left_x": -0.8125, "right_trigger": 1}}},
    {"t": 5.0, "pad": {"pad": 1, "connected": false}},
    {"t": 5.5, "pad": {"pad": 0, "boxer": 1}}
  ]})");
}
}  // namespace

TEST(InputEvents, EveryKindParsesWithItsFields) {
  auto events = boxing::parse_input_events(every_kind());
  ASSERT_TRUE(events.ok()) << events.error();
  ASSERT_EQ(events->size(), 15u);
  const auto& e = *events;
  EXPECT_EQ(e[0].kind, InputKind::Drag);
  EXPECT_EQ(e[0].bone, "head");
  EXPECT_DOUBLE_EQ(e[0].vec.y(), 0.35);
  EXPECT_FALSE(e[0].strong);
  EXPECT_FALSE(e[0].point.has_value());
  EXPECT_TRUE(e[1].strong);
  EXPECT_DOUBLE_EQ(e[1].point->z(), 0.03);
  EXPECT_EQ(e[3].kind, InputKind::Move);
  EXPECT_DOUBLE_EQ(e[3].vec.z(), 3.0);
  EXPECT_EQ(e[5].object, 2);
  EXPECT_EQ(e[6].at_boxer, 1);
  EXPECT_EQ(e[7].object_kind, boxing::ObjectKind::Crate);
  EXPECT_DOUBLE_EQ(e[7].velocity.y(), 8.0);
  EXPECT_EQ(e[9].bone, "chest");  // the push's default bone
  EXPECT_EQ(e[10].action, "jab");
  EXPECT_EQ(*e[11].servo, "person");
  EXPECT_DOUBLE_EQ(*e[11].omega_n, 12.5);
  EXPECT_DOUBLE_EQ(*e[11].consciousness, 0.5);
  // A pad's state: the buttons named are down, the others up; the axes named set, the others at rest.
  EXPECT_EQ(e[12].kind, InputKind::Pad);
  EXPECT_EQ(e[12].pad, 1);
  EXPECT_TRUE(e[12].pad_state.connected);
  EXPECT_TRUE(e[12].pad_state.buttons[boxing::kPadX]);
  EXPECT_TRUE(e[12].pad_state.buttons[boxing::kPadDpadUp]);
  EXPECT_FALSE(e[12].pad_state.buttons[boxing::kPadA]);
  EXPECT_EQ(e[12].pad_state.axes[boxing::kPadLeftX], -0.8125f);
  EXPECT_EQ(e[12].pad_state.axes[boxing::kPadRightTrigger], 1.0f);
  EXPECT_EQ(e[12].pad_state.axes[boxing::kPadLeftTrigger], -1.0f);  // at rest: released
  EXPECT_EQ(e[12].pad_boxer, -1);                                   // the assignment rule's
  EXPECT_FALSE(e[13].pad_state.connected);
  EXPECT_EQ(e[14].pad_boxer, 1);
  EXPECT_EQ(e[14].pad_state, boxing::PadState{true});  // connected, everything at rest
}

// What --record writes is what --input reads: the written form parses back to the same form, digit for digit.
TEST(InputEvents, WrittenEventsParseBackToTheSameJson) {
  auto events = boxing::parse_input_events(every_kind());
  ASSERT_TRUE(events.ok());
  const std::string path = std::string(BOXING_BINARY_DIR) + "/input_events_roundtrip.json";
  ASSERT_TRUE(boxing::write_input_file(path, *events).ok());
  auto again = boxing::load_input_file(path);
  ASSERT_TRUE(again.ok()) << again.error();
  ASSERT_EQ(again->size(), events->size());
  for (size_t i = 0; i < events->size(); ++i)
    EXPECT_EQ(boxing::input_event_json((*again)[i]), boxing::input_event_json((*events)[i])) << "event " << i;
  // Times that are sums of 1/240 s survive the text form exactly (the replay relies on it).
  InputEvent e;
  e.kind = InputKind::Release;
  e.t = 0.0;
  for (int i = 0; i < 1234; ++i) e.t += 1.0 / 240.0;
  auto back = boxing::parse_input_event(nlohmann::json::parse(boxing::input_event_json(e).dump()));
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->t, e.t);
}

TEST(InputEvents, ABadEventIsOneErrorNamingTheEventAndTheField) {
  struct Case {
    const char* json;
    const char* expected;
  } cases[] = {
      {R"([{"t": 2, "drag": {"boxer": 0, "bone": "head", "offset": [0, 1], "duration": 1}}])",
       "event 0 (t = 2): drag.offset must be an array of 3 numbers"},
      {R"([{"t": 1, "release": {}}, {"t": 2, "drag": {"boxer": 0, "offset": [0, 0, 1], "duration": 1}}])",
       "event 1 (t = 2): drag.bone is missing"},
      {R"([{"t": 1, "throw": {"object": "piano", "at_boxer": 0, "speed": 3}}])", "throw.object must be one of ball | crate"},
      {R"([{"t": 1, "throw": {"object": "ball", "at_boxer": 0, "speed": 300}}])", "throw.speed must be in [0.1, 40]"},
      {R"([{"t": 1, "key": {"action": "headbutt"}}])", "key.action 'headbutt' is not a fight key"},
      {R"([{"t": 1, "set": {"boxer": 0, "servo": "joint"}}])", "set.servo must be one of world | person | parent"},
      {R"([{"t": 1, "push": {"boxer": 0, "force": [1, 2, 3], "duration": 0.1, "strength": 9}}])",
       "push.strength is not a field of push"},
      {R"([{"t": 1, "explode": {}}])", "'explode' is not an event"},
      {R"([{"t": 1, "clear": {}, "release": {}}])", "has two events"},
      {R"([{"drag": {}}])", "event 0: t must be a time in seconds >= 0"},
      {R"([{"t": 3, "clear": {}}, {"t": 2, "clear": {}}])", "events must be in time order"},
      {R"({"evnts": []})", "has no \"events\" array"},
      {R"([{"t": 1, "pad": {"buttons": {"x": true}}}])", "pad.pad is missing"},
      {R"([{"t": 1, "pad": {"pad": 16}}])", "pad.pad must be an integer in [0, 15]"},
      {R"([{"t": 1, "pad": {"pad": 0, "buttons": {"triangle": true}}}])",
       "pad.buttons has 'triangle', not a button (one of: a b x y"},
      {R"([{"t": 1, "pad": {"pad": 0, "buttons": {"a": 1}}}])", "pad.buttons.a must be true or false"},
      {R"([{"t": 1, "pad": {"pad": 0, "axes": {"left_x": 1.5}}}])", "pad.axes.left_x must be a number in [-1, 1]"},
      {R"([{"t": 1, "pad": {"pad": 0, "axes": {"left_z": 0.5}}}])", "pad.axes has 'left_z', not an axis"},
      {R"([{"t": 1, "pad": {"pad": 0, "axes": [0, 1]}}])", "pad.axes must be an object"},
      {R"([{"t": 1, "pad": {"pad": 0, "connected": false, "buttons": {"a": true}}}])",
       "pad.connected is false: an unplugged pad has no buttons"},
      {R"([{"t": 1, "pad": {"pad": 0, "boxer": 2}}])", "pad.boxer must be an integer in [0, 1]"},
      {R"([{"t": 1, "pad": {"pad": 0, "stick": 1}}])", "pad.stick is not a field of pad"},
  };
  for (const Case& c : cases) {
    auto r = boxing::parse_input_events(nlohmann::json::parse(c.json));
    ASSERT_FALSE(r.ok()) << c.json;
    EXPECT_NE(r.error().find(c.expected), std::string::npos) << "got: " << r.error() << "\nwanted: " << c.expected;
    EXPECT_EQ(r.error().find('\n'), std::string::npos) << r.error();
  }
}

TEST(InputEvents, AMissingOrBrokenFileNamesTheFileAndTheProblem) {
  auto missing = boxing::load_input_file("/no/such/input.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("'/no/such/input.json': no such file"), std::string::npos) << missing.error();
  const std::string broken = std::string(BOXING_BINARY_DIR) + "/input_events_broken.json";
  std::ofstream(broken) << "{\"events\": [ {\"t\": 1, ";
  auto bad = boxing::load_input_file(broken);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("not valid JSON"), std::string::npos) << bad.error();
}
