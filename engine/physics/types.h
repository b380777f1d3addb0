#pragma once
// Basic physics types shared by every physics file. Double precision throughout (render uses float).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

namespace eng::physics {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

// A rigid placement: x_world = R * x_local + p. (Featherstone's X transforms live in spatial.h.)
struct Pose {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
  Vec3 apply(const Vec3& x) const { return R * x + p; }
  Pose operator*(const Pose& b) const { return Pose{R * b.R, R * b.p + p}; }
  Pose inverse() const { return Pose{R.transpose(), -(R.transpose() * p)}; }
};

}  // namespace eng::physics
