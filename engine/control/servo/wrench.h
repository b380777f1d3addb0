#pragma once
// An external force + torque on one body (world frame): what the root spring and the meathook return.
// The game applies it to the pelvis with NO reaction (it is artificial "external help", paper section V).
#include <Eigen/Core>

namespace eng::control {

struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, applied at the pelvis centre of mass
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // N m
};

// v scaled down to length `limit` when longer (torque and force limits keep the direction).
inline Eigen::Vector3d clamp_norm(const Eigen::Vector3d& v, double limit) {
  const double n = v.norm();
  return (n > limit && n > 0.0) ? Eigen::Vector3d(v * (limit / n)) : v;
}

}  // namespace eng::control
