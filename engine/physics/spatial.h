#pragma once
// Spatial (6D) algebra, Featherstone "Rigid Body Dynamics Algorithms" (RBDA, 2008), Ch. 2.
// Ordering: motion m = [angular w; linear v], force f = [moment n; force F] (RBDA eq. 2.1-2.6).
// All inline, fixed-size, allocation free.
//
// The dynamics code works with spatial vectors expressed in WORLD-aligned coordinates at the WORLD
// ORIGIN (RBDA Sec. 2.11 "absolute coordinates", the same choice as MuJoCo's cdof/cinert but at the
// origin): then X_parent is the identity in every recursion and no per-body 6x6 transforms are needed.
// SpatialTransform below is still provided (and used by tests / API users) for frame changes.
#include "engine/physics/types.h"

namespace eng::physics {

inline Mat3 skew(const Vec3& a) {
  Mat3 s;
  s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return s;
}

inline Vec3 ang(const Vec6& m) { return m.head<3>(); }
inline Vec3 lin(const Vec6& m) { return m.tail<3>(); }
inline Vec6 spatial(const Vec3& top, const Vec3& bottom) {
  Vec6 r;
  r << top, bottom;
  return r;
}

// crm(v) m = v x m (motion cross product, RBDA eq. 2.31).
inline Vec6 cross_motion(const Vec6& v, const Vec6& m) {
  const Vec3 w = ang(v), vo = lin(v), mw = ang(m), mv = lin(m);
  return spatial(w.cross(mw), w.cross(mv) + vo.cross(mw));
}
// crf(v) f = v x* f (force cross product, RBDA eq. 2.32). crf(v) = -crm(v)^T.
inline Vec6 cross_force(const Vec6& v, const Vec6& f) {
  const Vec3 w = ang(v), vo = lin(v), fn = ang(f), ff = lin(f);
  return spatial(w.cross(fn) + vo.cross(ff), w.cross(ff));
}
inline Mat6 crm(const Vec6& v) {
  Mat6 X = Mat6::Zero();
  const Mat3 W = skew(ang(v));
  X.topLeftCorner<3, 3>() = W;
  X.bottomRightCorner<3, 3>() = W;
  X.bottomLeftCorner<3, 3>() = skew(lin(v));
  return X;
}
inline Mat6 crf(const Vec6& v) { return -crm(v).transpose(); }

// Plucker transform from frame A to frame B (RBDA eq. 2.24): B's origin at r (in A coords), B's axes
// E (rotation taking A coordinates to B coordinates). X = [E 0; -E rx E].
struct SpatialTransform {
  Mat3 E = Mat3::Identity();
  Vec3 r = Vec3::Zero();
  Vec6 apply_motion(const Vec6& m) const {  // X m
    const Vec3 w = ang(m);
    return spatial(E * w, E * (lin(m) - r.cross(w)));
  }
  Vec6 apply_force(const Vec6& f) const {  // X* f
    const Vec3 F = lin(f);
    return spatial(E * (ang(f) - r.cross(F)), E * F);
  }
  Vec6 inverse_motion(const Vec6& m) const {  // X^-1 m
    const Vec3 w = E.transpose() * ang(m);
    return spatial(w, E.transpose() * lin(m) + r.cross(w));
  }
  Vec6 transpose_force(const Vec6& f) const {  // X^T f  (= (X^-1)* f)
    const Vec3 F = E.transpose() * lin(f);
    return spatial(E.transpose() * ang(f) + r.cross(F), F);
  }
  SpatialTransform inverse() const { return SpatialTransform{E.transpose(), -(E * r)}; }
  SpatialTransform operator*(const SpatialTransform& b) const {  // this * b (b applied first)
    return SpatialTransform{E * b.E, b.r + b.E.transpose() * r};
  }
  Mat6 matrix() const {
    Mat6 X = Mat6::Zero();
    X.topLeftCorner<3, 3>() = E;
    X.bottomRightCorner<3, 3>() = E;
    X.bottomLeftCorner<3, 3>() = -E * skew(r);
    return X;
  }
};

// Transform from a Pose (child expressed in parent: x_parent = R x_child + p) to the Plucker
// transform parent->child coordinates (E = R^T, r = p).
inline SpatialTransform to_spatial(const Pose& parent_from_child) {
  return SpatialTransform{parent_from_child.R.transpose(), parent_from_child.p};
}

// Spatial inertia about the frame origin, given mass m, centre of mass c and rotational inertia Ic about
// the com, all in that frame (RBDA eq. 2.63): I = [Ic + m cx cx^T, m cx; m cx^T, m 1].
inline Mat6 spatial_inertia(double m, const Vec3& c, const Mat3& Ic) {
  Mat6 I;
  const Mat3 C = skew(c);
  I.topLeftCorner<3, 3>() = Ic + m * C * C.transpose();
  I.topRightCorner<3, 3>() = m * C;
  I.bottomLeftCorner<3, 3>() = m * C.transpose();
  I.bottomRightCorner<3, 3>() = m * Mat3::Identity();
  return I;
}

// Quaternion helpers (w,x,y,z storage in q vectors).
inline Quat quat_from(const double* q) { return Quat(q[0], q[1], q[2], q[3]); }
inline void quat_store(const Quat& r, double* q) {
  q[0] = r.w(); q[1] = r.x(); q[2] = r.y(); q[3] = r.z();
}
// exp map of a rotation vector (angle * axis) to a unit quaternion.
inline Quat quat_exp(const Vec3& rv) {
  const double th = rv.norm();
  if (th < 1e-12) return Quat(1.0, 0.5 * rv.x(), 0.5 * rv.y(), 0.5 * rv.z()).normalized();
  const double s = std::sin(0.5 * th) / th;
  return Quat(std::cos(0.5 * th), s * rv.x(), s * rv.y(), s * rv.z());
}
// log map: unit quaternion -> rotation vector (shortest rotation).
inline Vec3 quat_log(Quat q) {
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Vec3 v(q.x(), q.y(), q.z());
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v;
  return (2.0 * std::atan2(s, q.w()) / s) * v;
}

}  // namespace eng::physics
