// stand: the two boxers on their stances, guard clip (or a drill clip with --clip), measured for falls.
#include "game/scenarios/scenario_hooks.h"

namespace boxing {

const ScenarioHooks kStandScenario = {
    .walks_graph = false,
    .setup = [](World& w, Rng&) { setup_boxers_on_stances(w, 2); },
    .place = place_boxers_on_stances,
    .caption = [](const World&) -> std::string {
      return "STAND (the hands-on lab): drag a boxer, throw balls (T) and crates (Y) at it";
    },
};

}  // namespace boxing
