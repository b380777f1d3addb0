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
                       "root_limit": 300, "control": "player", "consciousness": 0.5}}
  ]})");
}
}  // namespace

TEST(InputEvents, EveryKindParsesWithItsFields) {
  auto events = boxing::parse_input_events(every_kind());
  ASSERT_TRUE(events.ok()) << events.error();
  ASSERT_EQ(events->size(), 12u);
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
