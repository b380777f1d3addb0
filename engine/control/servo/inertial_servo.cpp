// World-space inertial servo, eq. 3 of Jenkins, Wrotek & McGuire (with the optional stable-PD evaluation).
#include "engine/control/servo/inertial_servo.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/wrench.h"

namespace eng::control {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

std::vector<double> servo_torque_limits(const ServoGains& g, const std::vector<double>& I_eff,
                                        const std::vector<double>& subtree_mass) {
  std::vector<double> lim(I_eff.size(), kInf);
  for (size_t i = 0; i < I_eff.size(); ++i) {
    if (g.max_angular_accel > 0.0) lim[i] = std::min(lim[i], g.max_angular_accel * I_eff[i]);
    if (g.torque_limit_per_kg > 0.0 && i < subtree_mass.size())
      lim[i] = std::min(lim[i], g.torque_limit_per_kg * subtree_mass[i]);
  }
  return lim;
}

Eigen::Vector3d servo_torque_one(const ServoGains& g, double I, const Eigen::Quaterniond& W_d,
                                 const Eigen::Vector3d& omega_d, const Eigen::Quaterniond& W_a,
                                 const Eigen::Vector3d& omega_a, double limit) {
  const double k1 = servo_k1(g, I);
  const double k2 = servo_k2(g, I);
  Eigen::Vector3d tau;
  if (g.stable_pd && g.dt > 0.0) {
    // Stable PD (Tan et al. 2011): proportional term on the predicted orientations, implicit damping.
    const Eigen::Quaterniond Wd1 = integrate_rotation(W_d, omega_d, g.dt);
    const Eigen::Quaterniond Wa1 = integrate_rotation(W_a, omega_a, g.dt);
    tau = (k1 * orientation_error(Wd1, Wa1) + k2 * (omega_d - omega_a)) / (1.0 + 2.0 * g.zeta * g.omega_n * g.dt);
  } else {
    tau = k1 * orientation_error(W_d, W_a) + k2 * (omega_d - omega_a);  // eq. 3
  }
  return clamp_norm(tau, limit);
}

void inertial_servo_torques(const anim::Skeleton& skel, const ServoGains& gains, const std::vector<double>& I_eff,
                            const std::vector<Eigen::Quaterniond>& W_d, const std::vector<Eigen::Vector3d>& omega_d,
                            const std::vector<Eigen::Quaterniond>& W_a, const std::vector<Eigen::Vector3d>& omega_a,
                            std::vector<Eigen::Vector3d>& tau, const std::vector<double>* tau_limit) {
  const int n = skel.size();
  assert(static_cast<int>(I_eff.size()) >= n && static_cast<int>(W_d.size()) >= n &&
         static_cast<int>(omega_d.size()) >= n && static_cast<int>(W_a.size()) >= n &&
         static_cast<int>(omega_a.size()) >= n);
  tau.resize(n);
  auto limit_of = [&](int i) {
    if (tau_limit && static_cast<int>(tau_limit->size()) > i) return (*tau_limit)[i];
    return gains.max_angular_accel > 0.0 ? gains.max_angular_accel * I_eff[i] : kInf;
  };
  if (n == 0) return;
  // Root: external help only when asked for (root_k_scale > 0), otherwise zero (paper: world-space control
  // needs no artificial help for static balance).
  if (gains.root_k_scale > 0.0) {
    tau[0] = servo_torque_one(gains, gains.root_k_scale * I_eff[0], W_d[0], omega_d[0], W_a[0], omega_a[0],
                              limit_of(0));
  } else {
    tau[0].setZero();
  }
  for (int i = 1; i < n; ++i)  // eq. 3, b != root
    tau[i] = servo_torque_one(gains, I_eff[i], W_d[i], omega_d[i], W_a[i], omega_a[i], limit_of(i));
}

Eigen::Quaterniond desired_root(ServoSpace space, const Eigen::Quaterniond& clip_root, double heading_yaw) {
  if (space == ServoSpace::Person) return person_space_root(clip_root, heading_yaw);
  return clip_root.normalized();
}

void ServoState::resize(int n) {
  W_d.resize(n);
  omega_d.resize(n);
  tau.resize(n);
  scratch.ahead.rotation.resize(n);
  scratch.W_now.resize(n);
  scratch.W_ahead.resize(n);
}

void inertial_servo_step(const anim::Skeleton& skel, ServoSpace space, const ServoGains& gains,
                         const std::vector<double>& I_eff, const anim::PoseSample& desired, double heading_yaw,
                         double delta, const std::vector<Eigen::Quaterniond>& W_a,
                         const std::vector<Eigen::Vector3d>& omega_a, ServoState& st) {
  const int n = skel.size();
  st.resize(n);
  const Eigen::Quaterniond& clip_root = desired.pose.rotation[0];
  const Eigen::Vector3d w0 = desired.angular_velocity.empty() ? Eigen::Vector3d::Zero()
                                                              : desired.angular_velocity[0];
  const Eigen::Quaterniond root_now = desired_root(space, clip_root, heading_yaw);
  const double d = delta > 0.0 ? delta : gains.dt;  // eq. 2 needs a look-ahead of at least one step
  const Eigen::Quaterniond root_ahead = desired_root(space, integrate_rotation(clip_root, w0, d), heading_yaw);
  lift_to_world(skel, desired.pose, root_now, st.W_d);
  desired_world_velocity(skel, desired, root_now, root_ahead, d, DesiredVelocityMode::LookAhead, st.scratch,
                         st.omega_d);
  inertial_servo_torques(skel, gains, I_eff, st.W_d, st.omega_d, W_a, omega_a, st.tau,
                         st.tau_limit.empty() ? nullptr : &st.tau_limit);
}

}  // namespace eng::control
