#pragma once
// Narrowphase: contact points between two shapes at given poses, for every pair the game needs (sphere, capsule,
// box, plane in any order). Points are reported while the surfaces are closer than `margin` (speculative contacts,
// depth < 0), normals point from a to b, positions lie midway between the surfaces, and `feature` ids stay the
// same while the touching features stay the same, so the solver can warm start across steps. No allocation.
#include "engine/physics/collision.h"
#include "engine/physics/types.h"

namespace eng::physics {

inline constexpr int kMaxContactsPerPair = 4;

// Returns the number of points written to out (at most min(max_out, 4)); geom ids are left for the caller.
int collide_shapes(const Shape& a, const Pose& xa, const Shape& b, const Pose& xb, double margin, ContactPoint* out,
                   int max_out);

}  // namespace eng::physics
