// Support polygon (see support_polygon.h).
#include "engine/control/biped/support_polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eng::control {

namespace {
double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

Eigen::Vector2d closest_on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}
}  // namespace

void convex_hull_2d_in_place(std::vector<Eigen::Vector2d>& pts, std::vector<Eigen::Vector2d>& hull) {
  std::sort(pts.begin(), pts.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  hull.clear();
  if (pts.size() < 3) {
    hull = pts;
    return;
  }
  // Andrew's monotone chain, built in `hull` itself (its capacity is kept between calls: no allocation per tick).
  std::vector<Eigen::Vector2d>& h = hull;
  h.resize(2 * pts.size());
  size_t k = 0;
  for (const auto& p : pts) {  // lower hull
    while (k >= 2 && cross(h[k - 2], h[k - 1], p) <= 0.0) --k;
    h[k++] = p;
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {  // upper hull
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0.0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);  // the last point repeats the first
}

void convex_hull_2d(const std::vector<Eigen::Vector2d>& pts, std::vector<Eigen::Vector2d>& hull) {
  thread_local std::vector<Eigen::Vector2d> scratch;  // capacity kept: no allocation once warm
  scratch = pts;
  convex_hull_2d_in_place(scratch, hull);
}

Eigen::Vector2d clamp_to_polygon(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector2d& p, double margin) {
  const size_t n = hull.size();
  if (n == 0) return p;
  if (n == 1) return hull[0];
  if (n == 2) return closest_on_segment(hull[0], hull[1], p);
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& v : hull) c += v;
  c /= static_cast<double>(n);
  // Shrink toward the centroid by `margin`, but never past half the vertex's distance to it (each shrunk vertex
  // computed where it is needed: no buffer, no allocation).
  auto s = [&](size_t i) -> Eigen::Vector2d {
    const Eigen::Vector2d d = hull[i] - c;
    const double len = d.norm();
    return len > 0.0 ? Eigen::Vector2d(c + d * std::max(0.5, 1.0 - margin / len)) : c;
  };
  bool inside = true;
  for (size_t i = 0; i < n && inside; ++i) inside = cross(s(i), s((i + 1) % n), p) >= 0.0;
  if (inside) return p;
  Eigen::Vector2d best = s(0);
  double best_d2 = INFINITY;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d q = closest_on_segment(s(i), s((i + 1) % n), p);
    const double d2 = (q - p).squaredNorm();
    if (d2 < best_d2) best_d2 = d2, best = q;
  }
  return best;
}

double share_inside(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector2d& from, const Eigen::Vector2d& delta,
                    double margin) {
  const size_t n = hull.size();
  if (n < 3) return 1.0;
  // Counter-clockwise: inside is to the left of every edge. For edge a -> b (unit direction u) the point x's inward
  // distance is u x (x - a); along the move it changes by s (u x delta), so an edge the move heads for bounds s.
  double share = 1.0;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d e = hull[(i + 1) % n] - a;
    const double len = e.norm();
    if (len < 1e-12) continue;
    const double inside = (e.x() * (from.y() - a.y()) - e.y() * (from.x() - a.x())) / len - margin;
    if (inside < 0.0) return 0.0;
    const double rate = (e.x() * delta.y() - e.y() * delta.x()) / len;
    if (rate < 0.0) share = std::min(share, inside / -rate);
  }
  return share;
}

double outside_distance(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector2d& x) {
  if (hull.empty()) return std::numeric_limits<double>::infinity();
  if (hull.size() < 3) return (clamp_to_polygon(hull, x, 0.0) - x).norm();
  // Counter-clockwise: inside is to the left of every edge. Outside: the distance to the nearest point of the
  // polygon; inside: minus the distance to the nearest edge.
  double worst = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d a = hull[i], e = hull[(i + 1) % hull.size()] - a;
    const double len = e.norm();
    if (len < 1e-12) continue;
    worst = std::max(worst, (e.x() * (x.y() - a.y()) - e.y() * (x.x() - a.x())) / -len);
  }
  if (worst <= 0.0) return worst;
  return (clamp_to_polygon(hull, x, 0.0) - x).norm();
}

Eigen::Vector3d ground_com_acceleration(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector3d& com,
                                        const Eigen::Vector3d& acc, double z, double margin, double ramp, double g) {
  if (hull.size() < 3 || z <= 0.0) return acc;
  const Eigen::Vector2d c = com.head<2>();
  Eigen::Vector3d out = acc;
  const double inside = -outside_distance(hull, c);
  if (inside < margin) {  // the com near or past an edge: the caller buys what is handed over
    if (ramp > 0.0) out.head<2>() *= std::clamp((margin - inside) / ramp, 0.0, 1.0);
    return out;
  }
  const double support = g + acc.z();  // the vertical ground force per unit mass
  if (support <= 0.0) return acc;      // falling faster than gravity: no pressure to place
  out.head<2>() *= share_inside(hull, c, -z / support * acc.head<2>(), margin);
  return out;
}

}  // namespace eng::control
