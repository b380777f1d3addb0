#pragma once
// Ray casts against the collision geoms: picking a body under the mouse, line-of-sight and reach tests.
// A query, not part of the step: it reads the body poses d.x (forward_kinematics) and places each geom
// itself (d.x[body] * geom.local, as collide() does), so it is correct right after forward_kinematics
// without a step, and never writes to Data.
//
// CONVENTIONS
//  * `dir` need not be unit (it is normalised; it must be nonzero). `distance` is in metres along the
//    unit direction, so point = origin + distance * dir / |dir|.
//  * The normal is the unit outward normal of the shape's surface at the hit point (world frame).
//  * Shapes are solid. A ray whose origin is inside (or on) a shape hits that shape at distance 0 with
//    point = origin and normal = -dir (Jolt's default for casts starting inside). A plane is the solid
//    half-space below its local XY plane (as the narrowphase treats it). To cast out of a body, skip it
//    with the filter.
//  * Box edges and corners: the normal is that of the face whose slab the ray enters last (Williams et al.,
//    "An Efficient and Robust Ray-Box Intersection Algorithm", 2005); on an exact tie the lower local axis
//    (x, then y, then z) wins.
//  * The closest hit over all geoms wins; on an exact distance tie the lower geom index wins.
#include <cstdint>

#include "engine/physics/collision.h"
#include "engine/physics/data.h"
#include "engine/physics/model.h"
#include "engine/physics/types.h"

namespace eng::physics {

struct RayFilter {
  int skip_body = -1;               // geoms of this body are ignored (-1: none)
  int skip_root = -1;               // geoms of every body of this articulation (Body::root) are ignored
  uint32_t mask = 0xffffffffu;      // a geom is tested iff (geom.group & mask) != 0
};

struct RayHit {
  bool hit = false;
  int body = -1, geom = -1;
  Vec3 point = Vec3::Zero();   // world
  Vec3 normal = Vec3::Zero();  // world, unit, outward from the hit shape
  double distance = 0.0;       // m along the unit direction
};

// Closest hit within [0, max_distance] of the ray origin + t dir over the geoms passing `filter`.
// Requires forward_kinematics (d.x). No allocation.
RayHit raycast(const Model& m, const Data& d, const Vec3& origin, const Vec3& dir, double max_distance,
               const RayFilter& filter = {});

// One shape at a world pose. unit_dir must be unit. On a hit within [0, max_distance] writes the distance
// and the world outward normal (the conventions above) and returns true.
bool raycast_shape(const Shape& s, const Pose& x, const Vec3& origin, const Vec3& unit_dir, double max_distance,
                   double& distance, Vec3& normal);

}  // namespace eng::physics
