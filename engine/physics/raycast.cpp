// Ray casts: each shape is tested in its own frame (the ray moved by the inverse pose), where every test is
// a quadratic or a slab test (Ericson, "Real-Time Collision Detection", 5.3.2 sphere, 5.3.3 slabs, 5.3.7
// cylinder); the normal is rotated back to the world.
#include "engine/physics/raycast.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/physics/broadphase.h"

namespace eng::physics {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A local-frame hit: t along the unit ray, local outward normal. inside = origin in (or on) the solid.
struct LocalHit {
  bool hit = false, inside = false;
  double t = kInf;
  Vec3 n = Vec3::Zero();
};

// Sphere of radius r centred at c: |o + t d - c|^2 = r^2, t = -b - sqrt(b^2 - cc) with b = (o - c).d,
// cc = |o - c|^2 - r^2 (Ericson 5.3.2; d unit so the quadratic's a = 1).
LocalHit ray_sphere(const Vec3& o, const Vec3& d, const Vec3& c, double r) {
  LocalHit h;
  const Vec3 oc = o - c;
  const double cc = oc.squaredNorm() - r * r;
  if (cc <= 0.0) {
    h.hit = h.inside = true;
    h.t = 0.0;
    return h;
  }
  const double b = oc.dot(d);
  const double disc = b * b - cc;
  if (b > 0.0 || disc < 0.0) return h;  // pointing away from an outside origin, or missing
  h.t = -b - std::sqrt(disc);
  h.n = (oc + h.t * d) / r;
  h.hit = true;
  return h;
}

// Capsule along local Z, cap centres at z = +-hl: the side (an infinite cylinder clipped to |z| <= hl) and
// the two cap spheres; the nearest of the three. Inside iff the distance to the segment is <= r.
LocalHit ray_capsule(const Vec3& o, const Vec3& d, double r, double hl) {
  const double oz = std::clamp(o.z(), -hl, hl);
  if ((o - Vec3(0, 0, oz)).squaredNorm() <= r * r) {
    LocalHit h;
    h.hit = h.inside = true;
    h.t = 0.0;
    return h;
  }
  LocalHit best;
  // side: (ox + t dx)^2 + (oy + t dy)^2 = r^2
  const double a = d.x() * d.x() + d.y() * d.y();
  if (a > 0.0) {
    const double b = o.x() * d.x() + o.y() * d.y();
    const double c = o.x() * o.x() + o.y() * o.y() - r * r;
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      const double t = (-b - std::sqrt(disc)) / a;  // entering root (the origin is outside the solid)
      const double z = o.z() + t * d.z();
      if (t >= 0.0 && std::abs(z) <= hl) {
        best.hit = true;
        best.t = t;
        best.n = Vec3(o.x() + t * d.x(), o.y() + t * d.y(), 0.0) / r;
      }
    }
  }
  for (double s : {-1.0, 1.0}) {
    const LocalHit cap = ray_sphere(o, d, Vec3(0, 0, s * hl), r);
    if (cap.hit && cap.t < best.t) best = cap;
  }
  return best;
}

// Box of half extents he: slab test; the normal is the face of the last slab entered.
LocalHit ray_box(const Vec3& o, const Vec3& d, const Vec3& he) {
  LocalHit h;
  if (std::abs(o.x()) <= he.x() && std::abs(o.y()) <= he.y() && std::abs(o.z()) <= he.z()) {
    h.hit = h.inside = true;
    h.t = 0.0;
    return h;
  }
  double t_enter = -kInf, t_exit = kInf;
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (std::abs(o[i]) > he[i]) return h;  // parallel to the slab and outside it
      continue;
    }
    double t1 = (-he[i] - o[i]) / d[i], t2 = (he[i] - o[i]) / d[i];
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > t_enter) {
      t_enter = t1;
      axis = i;
    }
    t_exit = std::min(t_exit, t2);
  }
  if (axis < 0 || t_enter > t_exit || t_enter < 0.0) return h;  // outside origin: entering must lie ahead
  h.hit = true;
  h.t = t_enter;
  h.n = Vec3::Zero();
  h.n[axis] = d[axis] > 0.0 ? -1.0 : 1.0;  // the entered face faces the ray
  return h;
}

// Plane: the half-space z <= 0, normal +Z.
LocalHit ray_plane(const Vec3& o, const Vec3& d) {
  LocalHit h;
  if (o.z() <= 0.0) {
    h.hit = h.inside = true;
    h.t = 0.0;
    return h;
  }
  if (d.z() >= 0.0) return h;
  h.hit = true;
  h.t = -o.z() / d.z();
  h.n = Vec3::UnitZ();
  return h;
}

// The ray against an AABB (slabs), origin inside counts: a cheap reject before the exact shape test.
bool ray_aabb(const Aabb& b, const Vec3& o, const Vec3& d, double max_distance) {
  double t0 = 0.0, t1 = max_distance;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (o[i] < b.lo[i] || o[i] > b.hi[i]) return false;
      continue;
    }
    const double inv = 1.0 / d[i];
    double ta = (b.lo[i] - o[i]) * inv, tb = (b.hi[i] - o[i]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

bool raycast_shape(const Shape& s, const Pose& x, const Vec3& origin, const Vec3& unit_dir, double max_distance,
                   double& distance, Vec3& normal) {
  const Vec3 o = x.R.transpose() * (origin - x.p);
  const Vec3 d = x.R.transpose() * unit_dir;
  LocalHit h;
  switch (s.type) {
    case ShapeType::Sphere: h = ray_sphere(o, d, Vec3::Zero(), s.radius); break;
    case ShapeType::Capsule: h = ray_capsule(o, d, s.radius, s.half_length); break;
    case ShapeType::Box: h = ray_box(o, d, s.half_extents); break;
    case ShapeType::Plane: h = ray_plane(o, d); break;
  }
  if (!h.hit || h.t > max_distance) return false;
  distance = h.t;
  normal = h.inside ? Vec3(-unit_dir) : Vec3(x.R * h.n);
  return true;
}

RayHit raycast(const Model& m, const Data& d, const Vec3& origin, const Vec3& dir, double max_distance,
               const RayFilter& filter) {
  RayHit best;
  const double len = dir.norm();
  if (!(len > 0.0) || !(max_distance >= 0.0)) return best;
  const Vec3 u = dir / len;
  double best_t = kInf;
  for (int g = 0; g < static_cast<int>(m.geoms.size()); ++g) {
    const Geom& G = m.geoms[g];
    if ((G.group & filter.mask) == 0u) continue;
    if (G.body == filter.skip_body) continue;
    if (filter.skip_root >= 0 && m.bodies[G.body].root == filter.skip_root) continue;
    const Pose x = d.x[G.body] * G.local;  // as collide() places it (d.geom_x is only filled by the step)
    const double reach = std::min(max_distance, best_t);
    // 1 nm of slack so a ray grazing the bounds is not lost to rounding before the exact test
    if (!ray_aabb(shape_aabb(G.shape, x, 1e-9), origin, u, reach)) continue;
    double t = 0.0;
    Vec3 n;
    if (!raycast_shape(G.shape, x, origin, u, reach, t, n) || t >= best_t) continue;
    best_t = t;
    best.hit = true;
    best.body = G.body;
    best.geom = g;
    best.distance = t;
    best.normal = n;
  }
  if (best.hit) best.point = origin + best.distance * u;
  return best;
}

}  // namespace eng::physics
