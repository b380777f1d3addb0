#pragma once
// A scenario's hooks into the world (game/world.cpp calls them; no scenario strings compared there):
//   setup        adds the boxers / bodies to the model (before Model::finalize); rng: the world's layout stream
//   place        their initial poses in the Data (after make_data)
//   before_control each tick after the step's first half, before the boxers' control (the match's AI and aim)
//   before_step  each tick after the boxers' control, before the physics step (external forces)
//   after_step   each tick after the physics step and the measurements
//   report       adds the scenario's own block to the report
//   caption      what the scenario is and does, one line, shown in the window (issue 64: every scenario names itself)
// One file per scenario in game/scenarios/.
#include <nlohmann/json.hpp>
#include <string>

#include "game/scenario.h"

namespace boxing {

struct World;
class Rng;

struct ScenarioHooks {
  bool walks_graph = false;  // the motion graph is built, boxers walk it, the root spring is on under --root-spring auto
  void (*setup)(World& w, Rng& rng) = nullptr;
  void (*place)(World& w, Rng& rng) = nullptr;
  void (*before_control)(World& w) = nullptr;
  void (*before_step)(World& w) = nullptr;
  void (*after_step)(World& w) = nullptr;
  void (*report)(const World& w, nlohmann::json& r) = nullptr;
  std::string (*caption)(const World& w) = nullptr;
};

// The window's caption for the world's scenario ("" for none: the match has its broadcast HUD).
std::string scenario_caption(const World& w);

const ScenarioHooks& scenario_hooks(Scenario s);

// Shared by the scenarios of boxers on their stances (arena, stand, push, match; graph-walk has one boxer).
void setup_boxers_on_stances(World& w, int count);
void place_boxers_on_stances(World& w, Rng& rng);

extern const ScenarioHooks kArenaScenario, kRagdollsScenario, kStandScenario, kPushScenario, kGraphWalkScenario,
    kMatchScenario, kImpactsScenario;

}  // namespace boxing
