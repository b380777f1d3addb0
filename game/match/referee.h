#pragma once
// The match's rules (match.h steps 3-4): the referee. Consciousness makes a boxer stunned and back; a heavy hit is a
// knockdown; a fall the match did not call is counted; a downed boxer lying still starts the stand-up, passing
// through its opponent; up and settled, both go back to their marks; not up within the count is a knock-out. Boxers
// out of reach of each other too long are brought back to their marks too.
#include <Eigen/Core>

namespace boxing {

struct World;

// The referee's reset: boxer `only` (-1: both) set at rest on its mark in guard, its walk and control started over.
void back_to_marks(World& w, int only = -1);
// Boxer k knocked down: the fall clip by the push's direction (backward when it goes against the boxer's facing),
// limp, a GetUp opened for the count.
void knock_down(World& w, int k, const Eigen::Vector3d& push_dir, const char* reason);
// Both standing and out of reach for MatchTuning::apart_time (and neither pressing a rocked opponent): back to marks.
void bring_together(World& w);
// Each tick after the hits: stunned / recovered, falls the match did not call, the stand-up, up, the count.
void referee(World& w);

}  // namespace boxing
