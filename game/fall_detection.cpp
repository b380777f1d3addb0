// The fall detection after each physics step: the boxer's state machine (BoxerStateMachine, game/boxer_state.h) that
// control reads on the next tick, and the metrics' record of the first fall.
#include <algorithm>

#include "game/boxer.h"

namespace boxing {

void detect_fall(const eng::physics::Data& d, Boxer& b, double dt) {
  BoxerMetrics& mt = b.metrics;
  const int pelvis = b.bodies.body[0];
  const double support = std::min(b.stance.lead_top, b.stance.rear_top);
  // A fall: the pelvis below half its standing height above the support, or a link other than feet and shanks on the
  // crates or floor for more than 0.2 s (FallTuning; docs/decisions/fall-detection.md).
  const bool went_down = boxer_state_update(b.ctl.state, b.settings.tuning.fall, d.x[pelvis].p.z() - support,
                                            b.ctl.contacts.other_link_on_ground, d.time, dt);
  if (went_down && !mt.fell) {  // the first fall (a match boxer may go down again after getting up)
    mt.fell = true;
    mt.fell_reason = b.ctl.state.reason;
    mt.fell_at = d.time, mt.fell_pelvis = d.x[pelvis].p;
  } else if (!mt.fell) {
    mt.time_upright += dt;
  }
}

}  // namespace boxing
