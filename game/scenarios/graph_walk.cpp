// graph-walk: one boxer tracking a seeded random walk of the motion graph alone (the servo's test against a 10-minute
// random walk).
#include "game/scenarios/scenario_hooks.h"

namespace boxing {

const ScenarioHooks kGraphWalkScenario = {
    .walks_graph = true,
    .setup = [](World& w, Rng&) { setup_boxers_on_stances(w, 1); },
    .place = place_boxers_on_stances,
};

}  // namespace boxing
