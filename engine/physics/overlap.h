#pragma once
// Overlap query: how deep two sets of geoms interpenetrate at the body poses d.x. A measure, not part of the step:
// collision filters are ignored (most of a boxer's own geoms do not collide, Geom::self_collide, and this is how a
// report sees its legs pass through each other). Each geom is placed as the step places it (d.x[body] * geom.local).
#include <vector>

#include "engine/physics/data.h"
#include "engine/physics/model.h"

namespace eng::physics {

// The deepest penetration (m) of any geom of `a` into any geom of `b`, 0 when none touch. No allocation.
double deepest_overlap(const Model& m, const Data& d, const std::vector<int>& a, const std::vector<int>& b);

}  // namespace eng::physics
