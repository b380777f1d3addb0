// graph-walk: one boxer tracking a seeded random walk of the motion graph alone (the servo's test against a 10-minute
// random walk).
#include <string>

#include "game/scenarios/scenario_hooks.h"
#include "game/world.h"

namespace boxing {

const ScenarioHooks kGraphWalkScenario = {
    .walks_graph = true,
    .setup = [](World& w, Rng&) { setup_boxers_on_stances(w, 1); },
    .place = place_boxers_on_stances,
    .caption = [](const World& w) -> std::string {  // the clip the walk is in, named as it changes
      const std::string clip = w.boxers.empty() ? std::string() : w.boxers[0].source.current_clip();
      return "GRAPH-WALK: a random walk of the motion graph, tracked. Now: " + clip;
    },
};

}  // namespace boxing
