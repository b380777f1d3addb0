// Parent-space PD baseline (eq. 1 on ball joints) and the meathook support (paper section V).
#include "engine/control/servo/parent_space_servo.h"

#include <cassert>
#include <limits>

#include "engine/control/servo/inertial_servo.h"
#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/wrench.h"

namespace eng::control {


void parent_space_torques(const anim::Skeleton& skel, const ServoGains& g, const std::vector<double>& I_eff,
                          const anim::PoseSample& desired, const std::vector<Eigen::Quaterniond>& W_a,
                          const std::vector<Eigen::Vector3d>& omega_a, std::vector<Eigen::Vector3d>& tau,
                          const std::vector<double>* tau_limit) {
  const int n = skel.size();
  assert(static_cast<int>(desired.pose.rotation.size()) >= n && static_cast<int>(W_a.size()) >= n &&
         static_cast<int>(omega_a.size()) >= n && static_cast<int>(I_eff.size()) >= n);
  const bool have_rates = static_cast<int>(desired.angular_velocity.size()) >= n;
  tau.resize(n);
  if (n == 0) return;
  tau[0].setZero();
  for (int i = 1; i < n; ++i) {
    const int p = skel.parent[i];
    const Eigen::Quaterniond Wp_inv = W_a[p].normalized().conjugate();
    const Eigen::Quaterniond q_a = (Wp_inv * W_a[i]).normalized();                 // actual, parent frame
    const Eigen::Vector3d w_a = Wp_inv * (omega_a[i] - omega_a[p]);                 // relative, parent frame
    const Eigen::Vector3d w_d = have_rates ? desired.angular_velocity[i] : Eigen::Vector3d::Zero();
    const Eigen::Quaterniond& q_d = desired.pose.rotation[i];
    const double I = I_eff[i];
    // The same PD law as the world-space servo (stable-PD option included), on parent-frame quantities.
    const Eigen::Vector3d tau_p =
        servo_torque_one(g, I, q_d, w_d, q_a, w_a, std::numeric_limits<double>::infinity());
    double limit = std::numeric_limits<double>::infinity();
    if (tau_limit && static_cast<int>(tau_limit->size()) > i)
      limit = (*tau_limit)[i];
    else if (g.max_angular_accel > 0.0)
      limit = g.max_angular_accel * I;
    tau[i] = clamp_norm(W_a[p].normalized() * tau_p, limit);  // to world; applied +child / -parent
  }
}

Wrench meathook(const MeathookParams& p, double total_mass, double I_body, const Eigen::Vector3d& x_d,
                const Eigen::Vector3d& v_d, const Eigen::Quaterniond& q_d, const Eigen::Vector3d& omega_d,
                const Eigen::Vector3d& x_a, const Eigen::Vector3d& v_a, const Eigen::Quaterniond& q_a,
                const Eigen::Vector3d& omega_a) {
  Wrench w;
  const double w2 = p.omega_n * p.omega_n, dz = 2.0 * p.zeta * p.omega_n;
  Eigen::Vector3d f = total_mass * (w2 * (x_d - x_a) + dz * (v_d - v_a));
  if (p.gravity_compensation) f.z() += total_mass * p.gravity;
  w.force = clamp_norm(f, p.max_force);
  w.torque = clamp_norm(I_body * (w2 * orientation_error(q_d, q_a) + dz * (omega_d - omega_a)), p.max_torque);
  return w;
}

}  // namespace eng::control
