#include "game/scenarios/scenario_hooks.h"

#include "game/world.h"
#include "game/world_build.h"

namespace boxing {

const ScenarioHooks& scenario_hooks(Scenario s) {
  switch (s) {
    case Scenario::Arena: return kArenaScenario;
    case Scenario::Ragdolls: return kRagdollsScenario;
    case Scenario::Stand: return kStandScenario;
    case Scenario::Push: return kPushScenario;
    case Scenario::GraphWalk: return kGraphWalkScenario;
    case Scenario::Match: return kMatchScenario;
    case Scenario::Impacts: return kImpactsScenario;
  }
  return kArenaScenario;
}

std::string scenario_caption(const World& w) {
  const ScenarioHooks& h = scenario_hooks(w.options.scenario_id);
  return h.caption ? h.caption(w) : std::string();
}

void setup_boxers_on_stances(World& w, int count) {
  add_boxer(w, 0, Eigen::Vector3f(0.75f, 0.08f, 0.06f), false, w.arena.stances[0]);
  if (count > 1) add_boxer(w, 1, Eigen::Vector3f(0.06f, 0.18f, 0.75f), false, w.arena.stances[1]);
}

void place_boxers_on_stances(World& w, Rng&) {
  for (Boxer& b : w.boxers) place_boxer(w, b);
}

}  // namespace boxing
