#include "engine/control/servo/joint_strength.h"

#include <algorithm>

namespace eng::control {

double strength_at_speed(double s, const TorqueVelocityLimit& limit) {
  if (s <= limit.full_speed) return 1.0;
  if (s >= limit.zero_speed) return 0.0;
  return (limit.zero_speed - s) / (limit.zero_speed - limit.full_speed);
}

void limit_torque_by_speed(Eigen::Ref<Eigen::VectorXd> tau, const Eigen::Ref<const Eigen::VectorXd>& v,
                           const TorqueVelocityLimit& limit) {
  const double s = v.norm();
  if (s <= limit.full_speed) return;
  const double along = tau.dot(v) / s;  // the torque's component along the motion
  if (along <= 0.0) return;             // braking: full strength
  tau -= (1.0 - strength_at_speed(s, limit)) * along * (v / s);
}

}  // namespace eng::control
