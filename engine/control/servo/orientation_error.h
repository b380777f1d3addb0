#pragma once
// Orientation error Delta(D, A) of Jenkins, Wrotek & McGuire, "Dynamic Humanoid Balance through Inertial
// Control", section IV: "Delta(D, A) = theta * v, where theta and v are the angle and axis of D * A^-1".
// Used by eq. 2 (desired world angular velocity) and eq. 3 (world-space servo torque).
//
// Conventions: Eigen quaternions, column vectors (q * v rotates v). D and A are world orientations of the
// same bone, so D * A^-1 is the world-frame rotation that takes A onto D and the returned vector is in world
// coordinates. For parent-space (relative) rotations the result is expressed in the parent frame.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace eng::control {

// Axis * angle of the unit quaternion q, shortest path (angle in [0, pi]).
//  * hemisphere: q and -q are the same rotation; we take the one with w >= 0 so the angle is <= pi.
//  * near 0: angle/|v| = 2 atan2(|v|, w)/|v| is evaluated by its series 2/w (1 - s^2/(3 w^2)) with s = |v|,
//    so there is no 0/0 and the result is exact to rounding.
//  * near pi: w -> 0, |v| -> 1; atan2 stays finite. At exactly w == 0 both hemispheres are valid, we pick the
//    sign that makes the largest-magnitude axis component positive, so q and -q give the same (consistent)
//    axis and the result is never NaN.
inline Eigen::Vector3d quaternion_log_vector(const Eigen::Quaterniond& q_in) {
  const double n = q_in.norm();
  if (!(n > 0.0) || !std::isfinite(n)) return Eigen::Vector3d::Zero();
  double w = q_in.w() / n;
  Eigen::Vector3d v = q_in.vec() / n;
  if (w < 0.0) {
    w = -w;
    v = -v;
  }
  if (w == 0.0) {  // exactly pi: canonical axis sign (independent of the input's sign)
    int k = 0;
    v.cwiseAbs().maxCoeff(&k);
    if (v[k] < 0.0) v = -v;
  }
  const double s2 = v.squaredNorm();
  const double s = std::sqrt(s2);
  if (s < 1e-6) {
    // small angle: theta/s = 2 atan(s/w)/s = (2/w) (1 - s^2/(3 w^2) + O(s^4)); w ~ 1 here.
    return (2.0 / w) * (1.0 - s2 / (3.0 * w * w)) * v;
  }
  const double theta = 2.0 * std::atan2(s, w);  // in [0, pi]
  return (theta / s) * v;
}

// Delta(D, A): axis*angle of D * A^-1 (paper, section IV). Inputs need not be exactly normalized.
inline Eigen::Vector3d orientation_error(const Eigen::Quaterniond& D, const Eigen::Quaterniond& A) {
  return quaternion_log_vector(D * A.conjugate());
}

// Inverse of quaternion_log_vector: the unit quaternion rotating by |r| about r/|r| (exponential map).
inline Eigen::Quaterniond rotation_from_vector(const Eigen::Vector3d& r) {
  const double theta = r.norm();
  const double h = 0.5 * theta;
  // sin(h)/theta with its series near 0 (1/2 - theta^2/48).
  const double k = theta < 1e-6 ? 0.5 - theta * theta / 48.0 : std::sin(h) / theta;
  return Eigen::Quaterniond(std::cos(h), k * r.x(), k * r.y(), k * r.z());
}

// Advance a world orientation by a constant world angular velocity omega over dt: exp(omega dt) * q.
// (Used by the look-ahead of eq. 2 and by the stable-PD prediction.)
inline Eigen::Quaterniond integrate_rotation(const Eigen::Quaterniond& q, const Eigen::Vector3d& omega,
                                             double dt) {
  return (rotation_from_vector(omega * dt) * q).normalized();
}

}  // namespace eng::control
