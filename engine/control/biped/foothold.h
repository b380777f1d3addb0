#pragma once
// Footholds on uneven ground (the game: its crates): where a stepping foot can land so its sole rests flat on one top.
//
// WHY. The crates are 0.5 m cells whose tops differ by up to 24 cm, the sole is 26 cm long, and the motion graph's
// steps are authored on a flat floor. Landed where the clip says, a sole often straddles a seam: its heel or toe
// rests on the edge of a higher crate, the foot tilts over that edge and the support shrinks to a line, which the
// centre of mass soon drifts out of. A person looks where they step; the foot placement here does the same: the
// smallest shift of the landing spot that puts the sole's core on the highest crate top under the sole.
#include <Eigen/Core>

#include "engine/control/biped/ground.h"

namespace eng::control {

// The sole in the foot frame (origin at the ankle, +X toward the toe), metres; matches the content's foot box.
struct SoleShape {
  double heel = -0.08, toe = 0.18, half_width = 0.05;
};

struct FootholdParams {
  double end_margin = 0.04;   // the core: the sole less this much at the heel and at the toe (m) ...
  double side_margin = 0.015;  // ... and at each side (m)
  double level_tol = 0.005;   // core samples within this of the highest top under the sole count as on it (m)
  double max_shift = 0.20;    // search radius (m)
  double grid = 0.01;         // search resolution (m)
  double lateral_cost = 2.0;  // a sideways shift (across frame_yaw) costs this much more than one along it
  double back_cost = 1.0;     // a shift against frame_yaw costs this much more than one along it (1: symmetric)
  // m, the highest top is looked for this far around the sole too: a landing beside a higher top (a crate's side, the
  // platform's edge from the floor) keeps this clear of it, so a landing that misses by a few cm does not come down on
  // that edge (0: the sole alone, the clips' steps)
  double clearance = 0.0;
  SoleShape sole;
};

// True when the sole placed with its ankle over `ankle` (world x, y) and toes pointing along `yaw` rests well: every
// sample of its core lies on the highest crate top found under the whole sole, widened by p.clearance (an overhang
// over a LOWER crate is fine, the foot stands flat on the higher one; an edge of a HIGHER crate under the heel or toe,
// or within the clearance, is not).
bool foothold_ok(GroundHeight ground, const Eigen::Vector2d& ankle, double yaw, const FootholdParams& p = {});

struct Foothold {
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // add to the ankle (world, m)
  bool found = false;                               // false: nothing within max_shift (shift stays zero)
};

// Sorts the search's candidate order for this shape now (per thread; a few shapes are kept): searches with it then
// allocate nothing. For a caller whose step must not allocate (the game's world step), at setup.
void prepare_foothold_search(const FootholdParams& p);

// The cheapest shift (|along|^2, times back_cost against frame_yaw, + lateral_cost |across|^2, along = the direction
// frame_yaw) on the search grid that makes foothold_ok true; zero when the spot is already good.
Foothold find_foothold(GroundHeight ground, const Eigen::Vector2d& ankle, double yaw, double frame_yaw,
                       const FootholdParams& p = {});

}  // namespace eng::control
