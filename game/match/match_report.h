#pragma once
// What the match shows and reports: the HUD's match panel (game/hud.h) and the report's "match" block.
#include <nlohmann/json.hpp>

#include "game/hud.h"

namespace boxing {

struct World;

// What the match panel shows now (game/hud.h).
MatchHud match_hud(const World& w);

// The finished bout for the result screen (game/hud.h).
BoutSummary bout_summary(const World& w);

// The report's "match" block (README: punches_thrown / landed, knockdowns, getups, falls_without_hit, result,
// events).
nlohmann::json match_report(const World& w);

}  // namespace boxing
