#pragma once
// An external force + torque on one body (world frame): what the root spring and the meathook return.
// The game applies it to the pelvis with NO reaction (it is artificial "external help", paper section V).
#include <Eigen/Core>

namespace eng::control {

struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, applied at the pelvis centre of mass
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // N m
};

}  // namespace eng::control
