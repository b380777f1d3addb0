#pragma once
// The instantaneous capture point of the linear inverted pendulum (Pratt, Carff, Drakunov, Goswami 2006, "Capture
// Point: A Step toward Humanoid Push Recovery", eq. 7): where the foot must be for the body to come to rest over it,
//   xi = x + v / omega0,   omega0 = sqrt(g / z),
// x, v the centre of mass's floor position and velocity, z its height above the support.
#include <Eigen/Core>
#include <cmath>

namespace eng::control {

inline Eigen::Vector2d capture_point(const Eigen::Vector2d& com, const Eigen::Vector2d& vcom, double z,
                                     double g = 9.81) {
  return com + vcom / std::sqrt(g / z);
}

}  // namespace eng::control
