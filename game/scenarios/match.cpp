// match: the paper's two boxers fight (game/match/match.h): each walks the motion graph, steered by its AI (or the
// player's keys), punches land through the solver's hit events, hurt, stun, knock down; the downed get up.
#include "game/match/match.h"
#include "game/scenarios/scenario_hooks.h"
#include "game/world.h"

namespace boxing {

const ScenarioHooks kMatchScenario = {
    .walks_graph = true,
    .setup = [](World& w, Rng&) { setup_boxers_on_stances(w, 2); },
    .place =
        [](World& w, Rng& rng) {
          place_boxers_on_stances(w, rng);
          match_setup(w);
        },
    .before_control = match_before_control,
    .after_step = match_after_step,
    .report = [](const World& w, nlohmann::json& r) { r["match"] = match_report(w); },
};

}  // namespace boxing
