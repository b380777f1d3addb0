#include "game/match/clinch.h"

#include <algorithm>

#include "game/match/fighter_view.h"
#include "game/match/match.h"
#include "game/match/match_internal.h"
#include "game/world.h"

namespace boxing {

void measure_clinch(World& w) {
  Match& mt = *w.match;
  ClinchMetrics& c = mt.clinch;
  const bool both_up = standing_state(w.boxers[0].ctl.state.state) && standing_state(w.boxers[1].ctl.state.state);
  const double near = std::min(reach_distance(w, 0), reach_distance(w, 1));
  if (both_up && near < mt.tuning.clinch_within) {
    c.current_s += kPhysicsDt;
    c.locked_s += kPhysicsDt;
    c.longest_s = std::max(c.longest_s, c.current_s);
  } else {
    c.current_s = 0.0;
  }
}

}  // namespace boxing
