#pragma once
// Broadphase: axis-aligned bounds per geom and sort-and-sweep pair finding (Ericson, "Real-Time Collision
// Detection", 7.5.2). Filtering (same body, parent/child, groups) is the caller's job.
#include <utility>
#include <vector>

#include "engine/physics/collision.h"
#include "engine/physics/types.h"

namespace eng::physics {

struct Aabb {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
  bool overlaps(const Aabb& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y() &&
           lo.z() <= o.hi.z() && o.lo.z() <= hi.z();
  }
};

// Bounds of a shape at a pose, grown by margin. Planes get a huge box (they are infinite).
Aabb shape_aabb(const Shape& s, const Pose& x, double margin);

// Every overlapping pair (i < j), in a deterministic sorted order. `pairs` is cleared and refilled; its capacity
// (and the internal sort buffer's) is reused, so a warm call does not allocate.
void broadphase_pairs(const Aabb* boxes, int n, std::vector<std::pair<int, int>>& pairs);
// The same, leaving out the pairs of two boxes marked in `fixed` (nonzero: a static geom, which never collides with
// another static one). The output is the first overload's less those pairs.
void broadphase_pairs(const Aabb* boxes, const unsigned char* fixed, int n, std::vector<std::pair<int, int>>& pairs);

}  // namespace eng::physics
