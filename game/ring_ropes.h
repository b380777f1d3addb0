#pragma once
// The ring's ropes (Arena::ring, arena.h) as a soft boundary: each physics tick, before the step, every boxer geom
// reaching past a rope line within the ropes' height band is pushed back in by a spring-damper on its mass share
// (ring_ropes_apply, from step_world). The ropes only push inward, never pull; nothing happens without a ring.
// The force per kilogram keeps the push a uniform field over the body (no limb is torn off the rest): a boxer walking
// in at 1 m/s stops about v / sqrt(k) = 5 cm past the line, one thrown in at 3 m/s about 15 cm, and comes back off it
// (damping ratio c / (2 sqrt(k)) = 0.3: a visible rebound).
#include <Eigen/Core>
#include <array>

#include "game/arena.h"

namespace eng::physics {
struct Shape;
struct Pose;
}  // namespace eng::physics

namespace boxing {

struct World;

struct RopeTuning {
  double stiffness = 400.0;  // N / m per kg (1/s^2): omega = 20 rad/s
  double damping = 12.0;     // N s / m per kg (1/s), on the outward speed
  // m: the band acts from the bottom rope less below to the top rope plus above (above the ring's mean top); a point
  // below it (a foot under the bottom rope) or above it is free.
  double below = 0.35, above = 0.15;
};

// The four sides: outward normals +X, -X, +Y, -Y.
inline Eigen::Vector2d rope_side_normal(int side) {
  static const Eigen::Vector2d n[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  return n[side];
}

// The force (N, world) the ropes put on a point of mass `mass` (kg) at p (world, m) moving at v (m/s): per side, with
// depth = n . p - half_inside > 0 and p.z within the band, -n mass (stiffness depth + damping n . v), clamped at zero
// (never a pull); zero inside, above and below the band, and without a ring. depth_out: the deepest side's depth (m,
// <= 0 when inside).
Eigen::Vector3d rope_force(const Ring& ring, const RopeTuning& t, const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                           double mass, double* depth_out = nullptr);

// The point of a geom farthest along the world direction n (its support point): a capsule's or sphere's surface, a
// box's corner. (A plane has none: its origin.)
Eigen::Vector3d geom_support(const eng::physics::Shape& s, const eng::physics::Pose& x, const Eigen::Vector3d& n);

// Where the ropes are pushed out this tick (for drawing them deflected): per side the deepest point past the line.
struct RopeSideDeflection {
  double depth = 0.0;   // m past the rope line (0: straight)
  double along = 0.0;   // m along the side (the other floor axis)
  double z = 0.0;       // m, the pushing point's height
};

struct RingRopesState {
  RopeTuning tuning;
  std::array<double, 4> contact_s{};  // per boxer (up to 4), s touching the ropes (any geom pushed)
  std::array<bool, 4> touching{};     // per boxer, this tick
  std::array<RopeSideDeflection, 4> side{};
};

// Every boxer geom past a rope line gets its rope force at its support point (before the physics step; no allocation).
void ring_ropes_apply(World& w, double dt);

}  // namespace boxing
