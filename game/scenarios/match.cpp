// match: the paper's two boxers, each on a seeded random walk of the motion graph.
#include "game/scenarios/scenario_hooks.h"

namespace boxing {

const ScenarioHooks kMatchScenario = {
    .walks_graph = true,
    .setup = [](World& w, Rng&) { setup_boxers_on_stances(w, 2); },
    .place = place_boxers_on_stances,
};

}  // namespace boxing
