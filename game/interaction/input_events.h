#pragma once
// The player's hands as data: timed input events (a grab, the mouse's drag, a release, a scripted drag, a throw, a
// push, a fight key, a setting changed on the panel). The window's mouse and keys, --input FILE.json and --record
// FILE.json all speak this one form, and the world applies every event through one path (interaction.h), so a
// recorded session plays back headless bit for bit.
//
// FILE FORMAT (README: Scripted input): {"events": [EVENT, ...]} or a bare [EVENT, ...]; each EVENT is
// {"t": seconds, KIND: {fields}} with one KIND:
//   drag    {"boxer": 0, "bone": "head", "offset": [x, y, z], "duration": 1.0, "strong": false, "point": [x, y, z]}
//           pulls the bone's point (bone frame, default its centre of mass) toward its start + offset (world m, z up)
//   grab    {"boxer": 0, "bone": "head", "point": [x, y, z], "strong": false}  or  {"object": 2, "point": [...]}
//           the mouse: takes hold of a point (bone / object frame); the target starts at the point
//   move    {"target": [x, y, z]}   the mouse's target (world)
//   release {}                      the mouse lets go
//   throw   {"object": "ball" | "crate", "at_boxer": 1, "speed": 8.0}  or  {"object": ..., "from": [..], "velocity": [..]}
//   clear   {}                      removes the thrown objects
//   push    {"boxer": 0, "bone": "chest", "force": [x, y, z], "duration": 0.1}   (N, world, at the bone's com)
//   key     {"action": "jab", "boxer": 0}   a fight key (jab cross lead_hook rear_hook lead_uppercut
//           rear_uppercut block slip_left slip_right duck step_forward step_back step_left step_right pivot_left
//           pivot_right); the boxer becomes the player's (the second player's keys: "boxer": 1)
//   pad     {"pad": 0, "buttons": {"x": true, ...}, "axes": {"left_x": 0.8, ...}, "connected": true, "boxer": 1}
//           a gamepad's whole state from then on (gamepad.h: the names, the mapping); absent buttons are up, absent
//           axes at rest (sticks 0, triggers -1), "connected": false unplugs it; "boxer" pins it to a boxer (default:
//           the assignment rule, gamepad.h pad_boxer)
//   set     {"boxer": 0, "servo": "world" | "person" | "parent", "balance": "qp" | "pd", "omega_n": 15,
//            "root_spring": "on" | "off", "root_limit": 400, "control": "ai" | "player", "consciousness": 1.0}
//           (any subset): the panel's settings
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/result.h"
#include "game/interaction/gamepad.h"

namespace boxing {

// The fight keys' actions, in FightCommand's order (game/match/match.h: FightCommand(i + 1)).
inline constexpr const char* kKeyActions[] = {"jab",   "cross",     "lead_hook",  "rear_hook",   "lead_uppercut",
                                              "rear_uppercut", "block", "slip_left", "slip_right", "duck",
                                              "step_forward",  "step_back", "step_left",  "step_right",
                                              "pivot_left",    "pivot_right"};
inline constexpr int kKeyActionCount = sizeof(kKeyActions) / sizeof(kKeyActions[0]);

enum class InputKind : uint8_t { Drag, Grab, Move, Release, Throw, Clear, Push, Key, Set, Pad };
enum class ObjectKind : uint8_t { Ball, Crate };

struct InputEvent {
  double t = 0.0;
  InputKind kind = InputKind::Key;
  // drag / grab / push / key / set: whose (boxer index) and which bone; grab of a thrown object: object >= 0
  int boxer = 0;
  std::string bone;
  int object = -1;
  std::optional<Eigen::Vector3d> point;             // bone / object frame (drag, grab)
  Eigen::Vector3d vec = Eigen::Vector3d::Zero();    // drag: offset; move: target; push: force
  double duration = 0.0;                            // drag, push
  bool strong = false;                              // drag, grab: the modifier's strong spring
  // throw
  ObjectKind object_kind = ObjectKind::Ball;
  int at_boxer = -1;  // >= 0: aimed at that boxer's chest at `speed` from its side; else from / velocity
  double speed = 0.0;
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), velocity = Eigen::Vector3d::Zero();
  // key
  std::string action;
  // pad: which (0 .. kMaxPads - 1), its state, the boxer it is pinned to (-1: the assignment rule)
  int pad = -1;
  PadState pad_state;
  int pad_boxer = -1;
  // set (absent fields are left as they are)
  std::optional<std::string> servo, balance, root_spring, control;
  std::optional<double> omega_n, root_limit, consciousness;
};

const char* input_kind_name(InputKind k);
const char* object_kind_name(ObjectKind k);

// Parses one event / a file's text / a file. Errors name the event (index and time) and the field, e.g.
// "input 'in.json': event 3 (t = 2): drag.offset must be an array of 3 numbers".
eng::Result<InputEvent> parse_input_event(const nlohmann::json& j);
eng::Result<std::vector<InputEvent>> parse_input_events(const nlohmann::json& doc);
eng::Result<std::vector<InputEvent>> load_input_file(const std::string& path);

// The event in the file form (doubles written with round-trip precision: a parsed event is the same event).
nlohmann::json input_event_json(const InputEvent& e);
eng::Result<void> write_input_file(const std::string& path, const std::vector<InputEvent>& events);

}  // namespace boxing
