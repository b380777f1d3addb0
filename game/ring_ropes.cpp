#include "game/ring_ropes.h"

#include <algorithm>
#include <cmath>

#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"
#include "game/world.h"

namespace boxing {

Eigen::Vector3d rope_force(const Ring& ring, const RopeTuning& t, const Eigen::Vector3d& p, const Eigen::Vector3d& v,
                           double mass, double* depth_out) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  double deepest = -1e9;
  if (!ring.present) {
    if (depth_out) *depth_out = deepest;
    return f;
  }
  const double z = p.z() - ring.top_mean;
  const bool in_band = z >= ring.rope_heights.front() - t.below && z <= ring.rope_heights.back() + t.above;
  for (int s = 0; s < 4; ++s) {
    const Eigen::Vector2d n = rope_side_normal(s);
    const double depth = n.dot(p.head<2>()) - ring.half_inside;
    deepest = std::max(deepest, depth);
    if (depth <= 0.0 || !in_band) continue;
    const double push = std::max(0.0, mass * (t.stiffness * depth + t.damping * n.dot(v.head<2>())));
    f.head<2>() -= push * n;
  }
  if (depth_out) *depth_out = deepest;
  return f;
}

Eigen::Vector3d geom_support(const eng::physics::Shape& s, const eng::physics::Pose& x, const Eigen::Vector3d& n) {
  using eng::physics::ShapeType;
  switch (s.type) {
    case ShapeType::Sphere: return x.p + s.radius * n;
    case ShapeType::Capsule: {
      const Eigen::Vector3d axis = x.R.col(2);
      return x.p + (axis.dot(n) >= 0.0 ? 1.0 : -1.0) * s.half_length * axis + s.radius * n;
    }
    case ShapeType::Box: {
      Eigen::Vector3d p = x.p;
      for (int i = 0; i < 3; ++i) p += (x.R.col(i).dot(n) >= 0.0 ? 1.0 : -1.0) * s.half_extents[i] * x.R.col(i);
      return p;
    }
    case ShapeType::Plane: break;
  }
  return x.p;
}

void ring_ropes_apply(World& w, double dt) {
  RingRopesState& st = w.ropes;
  st.side = {};
  const Ring& ring = w.arena.ring;
  if (!ring.present) return;
  for (Boxer& b : w.boxers) {
    if (b.index < 0 || b.index >= static_cast<int>(st.touching.size())) continue;
    bool touching = false;
    for (size_t bone = 0; bone < b.bodies.body.size(); ++bone) {
      const int body = b.bodies.body[bone], n_geoms = b.bodies.geom_count[bone];
      if (n_geoms <= 0) continue;
      const double mass = w.model.bodies[body].mass / n_geoms;
      for (int g = b.bodies.first_geom[bone]; g < b.bodies.first_geom[bone] + n_geoms; ++g) {
        const eng::physics::Pose& x = w.data.geom_x[g];
        const eng::physics::Shape& shape = w.model.geoms[g].shape;
        // The side the geom reaches farthest past (its support point along that side's normal).
        for (int s = 0; s < 4; ++s) {
          const Eigen::Vector2d n2 = rope_side_normal(s);
          const Eigen::Vector3d n(n2.x(), n2.y(), 0.0);
          const Eigen::Vector3d p = geom_support(shape, x, n);
          if (n.dot(p) <= ring.half_inside) continue;
          const Eigen::Vector3d v = eng::physics::point_velocity(w.data, body, p);
          double depth = 0.0;
          // This side's force only (the point's depth past the other sides is theirs, from their own support points).
          Eigen::Vector3d f = rope_force(ring, st.tuning, p, v, mass, &depth);
          f = n * std::min(0.0, n.dot(f));
          if (f.squaredNorm() <= 0.0) continue;
          eng::physics::apply_force_at_point(w.model, w.data, body, f, p);
          touching = true;
          const double d = n.dot(p) - ring.half_inside;
          if (d > st.side[s].depth) st.side[s] = {d, s < 2 ? p.y() : p.x(), p.z()};
        }
      }
    }
    st.touching[b.index] = touching;
    if (touching) st.contact_s[b.index] += dt;
  }
}

}  // namespace boxing
