#pragma once
// The match's rules (match.h steps 3-4): the referee. Consciousness makes a boxer stunned and back; a heavy hit is a
// knockdown; a fall the match did not call is counted; a downed boxer lying still starts the stand-up, passing
// through its opponent; the standing boxer walks to a neutral corner meanwhile; up and settled, both fight on from
// where they stand (nobody is set anywhere: the boxers walk); not up within the count is a knock-out.
#include <Eigen/Core>

namespace boxing {

struct World;

// Boxer k knocked down: the fall clip by the push's direction (backward when it goes against the boxer's facing),
// limp, a GetUp opened for the count.
void knock_down(World& w, int k, const Eigen::Vector3d& push_dir, const char* reason);
// Each tick after the hits: stunned / recovered, falls the match did not call, the stand-up, up, the count.
void referee(World& w);

}  // namespace boxing
