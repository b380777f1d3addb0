// Torque-limited root spring with consciousness (paper section V, Fig. 7).
#include "engine/control/servo/root_spring.h"

#include <algorithm>

#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/wrench.h"
#include "engine/control/servo/person_space.h"

namespace eng::control {


Eigen::Quaterniond upright_target(const Eigen::Quaterniond& pelvis_world) {
  return yaw_rotation(heading_of(pelvis_world));
}

void RootSpring::hit(const RootSpringParams& p, double severity) {
  if (severity <= 0.0) return;
  since_hit_ = 0.0;
  if (severity >= p.knockout_threshold)
    consciousness_ = 0.0;
  else
    consciousness_ = std::max(0.0, consciousness_ - severity);
}

void RootSpring::update(const RootSpringParams& p, double dt) {
  since_hit_ += dt;
  if (since_hit_ >= p.stun_time) consciousness_ = std::min(1.0, consciousness_ + p.recovery_rate * dt);
}

void RootSpring::set_consciousness(double c) { consciousness_ = std::clamp(c, 0.0, 1.0); }

Wrench RootSpring::compute(const RootSpringParams& p, double I_body, double mass, const Eigen::Quaterniond& q_target,
                           const Eigen::Quaterniond& q_actual, const Eigen::Vector3d& omega_actual,
                           const Eigen::Vector3d& x_target, const Eigen::Vector3d& x_actual,
                           const Eigen::Vector3d& v_actual) const {
  Wrench w;
  if (!p.enabled || consciousness_ <= 0.0) return w;
  const double c = consciousness_;
  // Eq. 3 on the root toward the upright target (target at rest: omega_d = 0).
  const double k1 = c * I_body * p.omega_n * p.omega_n;
  const double k2 = c * 2.0 * p.zeta * I_body * p.omega_n;
  w.torque = clamp_norm(k1 * orientation_error(q_target, q_actual) - k2 * omega_actual, p.max_torque);
  if (p.position_spring) {
    const double kp = c * mass * p.pos_omega_n * p.pos_omega_n;
    const double kd = c * 2.0 * p.pos_zeta * mass * p.pos_omega_n;
    w.force = clamp_norm(kp * (x_target - x_actual) - kd * v_actual, p.max_force);
  }
  return w;
}

}  // namespace eng::control
