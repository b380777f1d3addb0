// Person (egocentric) space helpers, paper section IV ("person coordinates").
#include "engine/control/servo/person_space.h"

#include <cmath>
#include <numbers>

namespace eng::control {

double heading_of(const Eigen::Quaterniond& q_in) {
  const Eigen::Quaterniond q = q_in.normalized();
  const Eigen::Vector3d f = q * Eigen::Vector3d::UnitX();
  const double horiz = std::hypot(f.x(), f.y());
  if (horiz > 1e-6) return std::atan2(f.y(), f.x());
  // +X points straight up/down: use the twist about Z (swing-twist decomposition).
  if (std::abs(q.z()) < 1e-12 && std::abs(q.w()) < 1e-12) return 0.0;
  double yaw = 2.0 * std::atan2(q.z(), q.w());
  if (yaw > std::numbers::pi) yaw -= 2.0 * std::numbers::pi;
  if (yaw <= -std::numbers::pi) yaw += 2.0 * std::numbers::pi;
  return yaw;
}

Eigen::Quaterniond yaw_rotation(double yaw) {
  return Eigen::Quaterniond(std::cos(0.5 * yaw), 0.0, 0.0, std::sin(0.5 * yaw));
}

Eigen::Quaterniond remove_heading(const Eigen::Quaterniond& q) {
  return (yaw_rotation(-heading_of(q)) * q.normalized()).normalized();
}

Eigen::Quaterniond person_space_root(const Eigen::Quaterniond& clip_root, double heading_yaw) {
  return (yaw_rotation(heading_yaw) * remove_heading(clip_root)).normalized();
}

}  // namespace eng::control
