// Narrowphase pair tests. References: Ericson, "Real-Time Collision Detection" (RTCD): closest points 5.1.2
// (point-box), 5.1.9 (segment-segment), SAT for OBBs 4.4.1; Box2D-style face clipping (Sutherland-Hodgman) for
// box-box manifolds; Gottschalk's 15-axis OBB test with a bias toward face axes so the chosen reference face is
// stable frame to frame (no flip-flopping between a face and an edge axis of nearly equal depth).
#include "engine/physics/narrowphase.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace eng::physics {
namespace {

constexpr double kEps = 1e-12;

// Contact between two spheres (also the core of every capsule test: a capsule is a swept sphere).
bool sphere_sphere(const Vec3& ca, double ra, const Vec3& cb, double rb, double margin, uint32_t feature,
                   ContactPoint& out) {
  const Vec3 d = cb - ca;
  const double dist = d.norm();
  const double depth = ra + rb - dist;
  if (depth < -margin) return false;
  out.normal = dist > kEps ? Vec3(d / dist) : Vec3::UnitZ();
  // Midway between the two surface points ca + n ra and cb - n rb.
  out.position = 0.5 * ((ca + out.normal * ra) + (cb - out.normal * rb));
  out.depth = depth;
  out.feature = feature;
  return true;
}

Vec3 closest_on_segment(const Vec3& p, const Vec3& s0, const Vec3& s1, double* t_out = nullptr) {
  const Vec3 d = s1 - s0;
  const double dd = d.squaredNorm();
  double t = dd > kEps ? std::clamp((p - s0).dot(d) / dd, 0.0, 1.0) : 0.0;
  if (t_out) *t_out = t;
  return s0 + t * d;
}

// RTCD 5.1.9: closest points between segments p1q1 and p2q2.
void closest_segment_segment(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2, Vec3& c1, Vec3& c2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= kEps && e <= kEps) {
    s = t = 0;
  } else if (a <= kEps) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kEps) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > kEps * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  c1 = p1 + d1 * s;
  c2 = p2 + d2 * t;
}

void capsule_segment(const Shape& s, const Pose& x, Vec3& p0, Vec3& p1) {
  const Vec3 axis = x.R.col(2) * s.half_length;
  p0 = x.p - axis;
  p1 = x.p + axis;
}

// Signed distance from a point (box-local) to a box, with the closest surface point and outward normal.
double box_point_query(const Vec3& h, const Vec3& p, Vec3& surface, Vec3& outward) {
  const Vec3 q = p.cwiseMax(-h).cwiseMin(h);
  const Vec3 d = p - q;
  const double dist = d.norm();
  if (dist > kEps) {
    surface = q;
    outward = d / dist;
    return dist;
  }
  // Inside: the face of least penetration.
  int axis = 0;
  double best = h.x() - std::abs(p.x());
  for (int i = 1; i < 3; ++i) {
    const double pen = h[i] - std::abs(p[i]);
    if (pen < best) best = pen, axis = i;
  }
  outward = Vec3::Zero();
  outward[axis] = p[axis] >= 0 ? 1.0 : -1.0;
  surface = p;
  surface[axis] = outward[axis] * h[axis];
  return -best;
}

// Sphere (centre c, radius r, world) against a box: normal from the sphere to the box.
bool sphere_box(const Vec3& c, double r, const Shape& box, const Pose& xb, double margin, uint32_t feature,
                ContactPoint& out) {
  const Vec3 pl = xb.R.transpose() * (c - xb.p);
  Vec3 surface, outward;
  const double sd = box_point_query(box.half_extents, pl, surface, outward);
  const double depth = r - sd;
  if (depth < -margin) return false;
  out.normal = -(xb.R * outward);
  const Vec3 surf_w = xb.apply(surface);
  out.position = 0.5 * (surf_w + (c + out.normal * r));
  out.depth = depth;
  out.feature = feature;
  return true;
}

bool sphere_plane(const Vec3& c, double r, const Pose& xp, double margin, uint32_t feature, ContactPoint& out) {
  const Vec3 n = xp.R.col(2);
  const double d = n.dot(c - xp.p);
  const double depth = r - d;
  if (depth < -margin) return false;
  out.normal = -n;
  out.position = c - n * (0.5 * (r + d));
  out.depth = depth;
  out.feature = feature;
  return true;
}

int capsule_capsule(const Shape& a, const Pose& xa, const Shape& b, const Pose& xb, double margin, ContactPoint* out,
                    int max_out) {
  Vec3 a0, a1, b0, b1;
  capsule_segment(a, xa, a0, a1);
  capsule_segment(b, xb, b0, b1);
  const Vec3 da = a1 - a0, db = b1 - b0;
  int n = 0;
  // Nearly parallel segments lying along each other: two points at the ends of the overlap, so one limb resting
  // along another does not pivot about a single point.
  const double la = da.norm(), lb = db.norm();
  if (la > 1e-6 && lb > 1e-6 && da.cross(db).norm() < 0.05 * la * lb && max_out >= 2) {
    const Vec3 u = db / lb;
    const double s0 = (a0 - b0).dot(u), s1 = (a1 - b0).dot(u);
    const double lo = std::max(std::min(s0, s1), 0.0), hi = std::min(std::max(s0, s1), lb);
    if (hi - lo > 1e-4) {
      for (int k = 0; k < 2; ++k) {
        const Vec3 pb = b0 + u * (k == 0 ? lo : hi);
        const Vec3 pa = closest_on_segment(pb, a0, a1);
        if (sphere_sphere(pa, a.radius, pb, b.radius, margin, uint32_t(k), out[n])) ++n;
      }
      return n;
    }
  }
  Vec3 ca, cb;
  closest_segment_segment(a0, a1, b0, b1, ca, cb);
  return sphere_sphere(ca, a.radius, cb, b.radius, margin, 2, out[0]) ? 1 : 0;
}

// Deepest point of a segment against a box: the signed distance to a convex set is convex along a line, so a
// golden-section search finds its minimum.
double segment_box_deepest(const Vec3& s0, const Vec3& s1, const Shape& box, const Pose& xb) {
  auto f = [&](double t) {
    const Vec3 p = xb.R.transpose() * (s0 + t * (s1 - s0) - xb.p);
    Vec3 s, o;
    return box_point_query(box.half_extents, p, s, o);
  };
  constexpr double g = 0.6180339887498949;
  double lo = 0, hi = 1, x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 40; ++i) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  return 0.5 * (lo + hi);
}

int capsule_box(const Shape& c, const Pose& xc, const Shape& box, const Pose& xb, double margin, ContactPoint* out,
                int max_out) {
  Vec3 s0, s1;
  capsule_segment(c, xc, s0, s1);
  int n = 0;
  // The two cap centres (a capsule lying on a face gets two points) plus the deepest interior point when it is
  // distinct from both ends (a shin across a crate edge).
  if (n < max_out && sphere_box(s0, c.radius, box, xb, margin, 0, out[n])) ++n;
  if (n < max_out && sphere_box(s1, c.radius, box, xb, margin, 1, out[n])) ++n;
  const double t = segment_box_deepest(s0, s1, box, xb);
  if (n < max_out && t > 0.05 && t < 0.95) {
    ContactPoint mid;
    if (sphere_box(s0 + t * (s1 - s0), c.radius, box, xb, margin, 2, mid)) {
      double deepest_end = -1e9;
      for (int k = 0; k < n; ++k) deepest_end = std::max(deepest_end, out[k].depth);
      if (mid.depth > deepest_end + 1e-4) out[n++] = mid;
    }
  }
  return n;
}

int capsule_plane(const Shape& c, const Pose& xc, const Pose& xp, double margin, ContactPoint* out, int max_out) {
  Vec3 s0, s1;
  capsule_segment(c, xc, s0, s1);
  int n = 0;
  if (n < max_out && sphere_plane(s0, c.radius, xp, margin, 0, out[n])) ++n;
  if (n < max_out && sphere_plane(s1, c.radius, xp, margin, 1, out[n])) ++n;
  return n;
}

Vec3 box_corner(const Vec3& h, int k) {
  return Vec3((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(), (k & 4) ? h.z() : -h.z());
}

// Keeps the 4 most useful of n candidate points: the deepest, then greedily the one farthest from those kept
// (spreads the manifold over the contact patch, as Box2D and Bullet do).
int reduce_to_four(ContactPoint* pts, int n) {
  if (n <= 4) return n;
  int best = 0;
  for (int i = 1; i < n; ++i)
    if (pts[i].depth > pts[best].depth) best = i;
  std::swap(pts[0], pts[best]);
  for (int k = 1; k < 4; ++k) {
    int pick = k;
    double pick_d = -1;
    for (int i = k; i < n; ++i) {
      double dmin = 1e300;
      for (int j = 0; j < k; ++j) dmin = std::min(dmin, (pts[i].position - pts[j].position).squaredNorm());
      if (dmin > pick_d) pick_d = dmin, pick = i;
    }
    std::swap(pts[k], pts[pick]);
  }
  return 4;
}

int box_plane(const Shape& box, const Pose& xb, const Pose& xp, double margin, ContactPoint* out, int max_out) {
  const Vec3 n = xp.R.col(2);
  ContactPoint tmp[8];
  int count = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec3 v = xb.apply(box_corner(box.half_extents, k));
    const double d = n.dot(v - xp.p);
    if (-d < -margin) continue;
    ContactPoint& c = tmp[count++];
    c.normal = -n;
    c.depth = -d;
    c.position = v - n * (0.5 * d);
    c.feature = uint32_t(k);
  }
  count = reduce_to_four(tmp, count);
  count = std::min(count, max_out);
  for (int i = 0; i < count; ++i) out[i] = tmp[i];
  return count;
}

// Clips polygon `in` (n points) by the half-space dot(normal, p) <= offset (Sutherland-Hodgman).
int clip_polygon(const Vec3* in, int n, const Vec3& normal, double offset, Vec3* out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3& a = in[i];
    const Vec3& b = in[(i + 1) % n];
    const double da = normal.dot(a) - offset, db = normal.dot(b) - offset;
    if (da <= 0) out[m++] = a;
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) out[m++] = a + (b - a) * (da / (da - db));
  }
  return m;
}

// Box-box: SAT over 15 axes (RTCD 4.4.1), then a clipped face manifold or a single edge-edge point.
int box_box(const Shape& A, const Pose& xa, const Shape& B, const Pose& xb, double margin, ContactPoint* out,
            int max_out) {
  const Vec3& ha = A.half_extents;
  const Vec3& hb = B.half_extents;
  const Mat3 R = xa.R.transpose() * xb.R;  // B's axes in A's frame
  const Vec3 d = xb.p - xa.p;
  const Vec3 t = xa.R.transpose() * d;     // centre offset in A's frame
  Mat3 absR = R.cwiseAbs();
  absR.array() += 1e-9;                    // robust for parallel edges (RTCD 4.4.1)

  // Face axes of A (0-2) and B (3-5): separation = |projected distance| - projected radii.
  double best_face_sep = -1e300;
  int best_face = -1;
  for (int i = 0; i < 3; ++i) {
    const double sep = std::abs(t[i]) - (ha[i] + absR.row(i).dot(hb));
    if (sep > margin) return 0;
    if (sep > best_face_sep) best_face_sep = sep, best_face = i;
  }
  for (int j = 0; j < 3; ++j) {
    const double sep = std::abs(t.dot(R.col(j))) - (absR.col(j).dot(ha) + hb[j]);
    if (sep > margin) return 0;
    // Prefer A's faces on near-ties so the reference face does not flip between the two boxes.
    if (sep > best_face_sep + 1e-5) best_face_sep = sep, best_face = 3 + j;
  }
  // Edge axes cross(Ai, Bj), normalised.
  double best_edge_sep = -1e300;
  int best_i = -1, best_j = -1;
  Vec3 best_edge_axis = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Vec3 axis_a = Vec3::Unit(i).cross(R.col(j));  // in A's frame
      const double len = axis_a.norm();
      if (len < 1e-6) continue;                          // parallel edges: covered by face axes
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = ha[i1] * absR(i2, j) + ha[i2] * absR(i1, j);
      const double rb = hb[j1] * absR(i, j2) + hb[j2] * absR(i, j1);
      const double dist = std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j));
      const double sep = (dist - (ra + rb)) / len;
      if (sep > margin) return 0;
      if (sep > best_edge_sep) best_edge_sep = sep, best_i = i, best_j = j, best_edge_axis = axis_a / len;
    }
  }

  // Face contact unless an edge axis separates clearly more (bias for stable manifolds).
  if (best_i >= 0 && best_edge_sep > 0.95 * best_face_sep + 0.002 && best_edge_sep > best_face_sep + 1e-4) {
    Vec3 n = xa.R * best_edge_axis;
    if (n.dot(d) < 0) n = -n;  // from A to B
    // Supporting edges: A's edge along axis i furthest toward B, B's edge along axis j furthest toward A.
    Vec3 ca = xa.p, cb = xb.p;
    for (int k = 0; k < 3; ++k) {
      if (k != best_i) ca += xa.R.col(k) * (xa.R.col(k).dot(n) > 0 ? ha[k] : -ha[k]);
      if (k != best_j) cb += xb.R.col(k) * (xb.R.col(k).dot(n) > 0 ? -hb[k] : hb[k]);
    }
    const Vec3 ea = xa.R.col(best_i) * ha[best_i], eb = xb.R.col(best_j) * hb[best_j];
    Vec3 pa, pb;
    closest_segment_segment(ca - ea, ca + ea, cb - eb, cb + eb, pa, pb);
    out[0].normal = n;
    out[0].depth = -best_edge_sep;
    out[0].position = 0.5 * (pa + pb);
    out[0].feature = (1u << 20) | uint32_t(best_i * 3 + best_j);
    return 1;
  }

  // Reference face on box `ref`, incident face on the other box.
  const bool ref_is_a = best_face < 3;
  const int axis = ref_is_a ? best_face : best_face - 3;
  const Pose& xr = ref_is_a ? xa : xb;
  const Pose& xi = ref_is_a ? xb : xa;
  const Vec3& hr = ref_is_a ? ha : hb;
  const Vec3& hi = ref_is_a ? hb : ha;
  Vec3 nr = xr.R.col(axis);  // reference face normal, pointing toward the incident box
  if (nr.dot(xi.p - xr.p) < 0) nr = -nr;
  // Incident face: the face of the other box most anti-parallel to nr.
  int inc_axis = 0;
  double most = 0;
  for (int k = 0; k < 3; ++k) {
    const double c = xi.R.col(k).dot(nr);
    if (std::abs(c) > std::abs(most)) most = c, inc_axis = k;
  }
  const double inc_sign = most > 0 ? -1.0 : 1.0;
  const Vec3 inc_n = xi.R.col(inc_axis) * inc_sign;
  const int u = (inc_axis + 1) % 3, v = (inc_axis + 2) % 3;
  const Vec3 fc = xi.p + inc_n * hi[inc_axis];
  const Vec3 du = xi.R.col(u) * hi[u], dv = xi.R.col(v) * hi[v];
  Vec3 poly[16], tmp[16];
  poly[0] = fc - du - dv, poly[1] = fc + du - dv, poly[2] = fc + du + dv, poly[3] = fc - du + dv;
  int n = 4;
  // Clip against the reference face's four side planes.
  for (int k = 0; k < 3 && n > 0; ++k) {
    if (k == axis) continue;
    const Vec3 s = xr.R.col(k);
    const double off = s.dot(xr.p);
    n = clip_polygon(poly, n, s, off + hr[k], tmp);
    n = clip_polygon(tmp, n, -s, -off + hr[k], poly);
  }
  const double ref_offset = nr.dot(xr.p) + hr[axis];
  const uint32_t ref_face = uint32_t(axis * 2 + (nr.dot(xr.R.col(axis)) > 0 ? 0 : 1));
  const uint32_t inc_face = uint32_t(inc_axis * 2 + (inc_sign > 0 ? 0 : 1));
  ContactPoint cand[16];
  int count = 0;
  for (int k = 0; k < n; ++k) {
    const double sep = nr.dot(poly[k]) - ref_offset;
    if (-sep < -margin) continue;
    ContactPoint& c = cand[count++];
    c.depth = -sep;
    c.position = poly[k] - nr * (0.5 * sep);
    c.normal = ref_is_a ? nr : Vec3(-nr);
    c.feature = (ref_is_a ? 0u : (1u << 16)) | (ref_face << 12) | (inc_face << 8) | uint32_t(k);
  }
  count = reduce_to_four(cand, count);
  count = std::min(count, max_out);
  for (int k = 0; k < count; ++k) out[k] = cand[k];
  return count;
}

// Dispatch for a.type <= b.type.
int collide_ordered(const Shape& a, const Pose& xa, const Shape& b, const Pose& xb, double margin, ContactPoint* out,
                    int max_out) {
  using T = ShapeType;
  switch (a.type) {
    case T::Sphere:
      switch (b.type) {
        case T::Sphere:
          return sphere_sphere(xa.p, a.radius, xb.p, b.radius, margin, 0, out[0]) ? 1 : 0;
        case T::Capsule: {
          Vec3 b0, b1;
          capsule_segment(b, xb, b0, b1);
          return sphere_sphere(xa.p, a.radius, closest_on_segment(xa.p, b0, b1), b.radius, margin, 0, out[0]) ? 1 : 0;
        }
        case T::Box:
          return sphere_box(xa.p, a.radius, b, xb, margin, 0, out[0]) ? 1 : 0;
        case T::Plane:
          return sphere_plane(xa.p, a.radius, xb, margin, 0, out[0]) ? 1 : 0;
      }
      break;
    case T::Capsule:
      switch (b.type) {
        case T::Capsule:
          return capsule_capsule(a, xa, b, xb, margin, out, max_out);
        case T::Box:
          return capsule_box(a, xa, b, xb, margin, out, max_out);
        case T::Plane:
          return capsule_plane(a, xa, xb, margin, out, max_out);
        default:
          break;
      }
      break;
    case T::Box:
      if (b.type == T::Box) return box_box(a, xa, b, xb, margin, out, max_out);
      if (b.type == T::Plane) return box_plane(a, xa, xb, margin, out, max_out);
      break;
    case T::Plane:
      break;  // plane-plane: static, never collides
  }
  return 0;
}

}  // namespace

int collide_shapes(const Shape& a, const Pose& xa, const Shape& b, const Pose& xb, double margin, ContactPoint* out,
                   int max_out) {
  max_out = std::min(max_out, kMaxContactsPerPair);
  if (max_out <= 0) return 0;
  if (static_cast<int>(a.type) <= static_cast<int>(b.type)) return collide_ordered(a, xa, b, xb, margin, out, max_out);
  const int n = collide_ordered(b, xb, a, xa, margin, out, max_out);
  for (int i = 0; i < n; ++i) out[i].normal = -out[i].normal;
  return n;
}

}  // namespace eng::physics
