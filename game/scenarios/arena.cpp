// arena: the two boxers on their stances, guard clip (the default scene).
#include "game/scenarios/scenario_hooks.h"

namespace boxing {

const ScenarioHooks kArenaScenario = {
    .walks_graph = false,
    .setup = [](World& w, Rng&) { setup_boxers_on_stances(w, 2); },
    .place = place_boxers_on_stances,
    .caption = [](const World&) -> std::string {
      return "ARENA: two boxers in guard on uneven crates. Drag them, T throws a ball, Y a crate";
    },
};

}  // namespace boxing
