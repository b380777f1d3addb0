#include "game/segment_distance.h"

#include <algorithm>
#include <cmath>

#include "engine/physics/collision.h"

namespace boxing {

SegmentClosest segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                                const Eigen::Vector3d& q1) {
  constexpr double kEps = 1e-12;
  const Eigen::Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= kEps && e <= kEps) {
    s = t = 0.0;
  } else if (a <= kEps) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= kEps) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      // Not parallel: the closest point on the first line, clamped; parallel: any s, 0 picked.
      s = denom > kEps ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  SegmentClosest out;
  out.s = s, out.t = t;
  out.p = p0 + s * d1;
  out.q = q0 + t * d2;
  out.distance = (out.p - out.q).norm();
  return out;
}

SweptSegment swept_segment(const eng::physics::Shape& s, const eng::physics::Pose& x) {
  using eng::physics::ShapeType;
  SweptSegment g;
  g.a = g.b = x.p;
  switch (s.type) {
    case ShapeType::Sphere: g.radius = s.radius; break;
    case ShapeType::Capsule: {
      const Eigen::Vector3d h = s.half_length * x.R.col(2);
      g.a = x.p - h, g.b = x.p + h, g.radius = s.radius;
      break;
    }
    case ShapeType::Box: {
      int i = 0;
      s.half_extents.maxCoeff(&i);
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      g.radius = std::min(s.half_extents[j], s.half_extents[k]);
      const Eigen::Vector3d h = std::max(0.0, s.half_extents[i] - g.radius) * x.R.col(i);
      g.a = x.p - h, g.b = x.p + h;
      break;
    }
    case ShapeType::Plane: break;
  }
  return g;
}

double swept_distance(const SweptSegment& u, const SweptSegment& v) {
  return segment_distance(u.a, u.b, v.a, v.b).distance - u.radius - v.radius;
}

}  // namespace boxing
