#pragma once
// Root spring (paper section V): "For some dynamic balance situations a root spring applies torques at the
// root, however these are torque limited" and (Fig. 7) "the root spring humanoid is artificially balanced and
// lowers its motor gains when knocked out". A torque-limited spring-damper on the pelvis orientation toward an
// upright target (optionally also a position spring), with gains scaled by consciousness in [0, 1].
// Default OFF: the boxers must stand on the world/person-space servo alone.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "engine/control/servo/wrench.h"

namespace eng::control {

struct RootSpringParams {
  bool enabled = false;         // default OFF
  double omega_n = 6.0;         // rad/s, orientation spring: k = c I omega_n^2, d = c 2 zeta I omega_n
  double zeta = 1.0;
  double max_torque = 400.0;    // N m (torque limited, paper section V)
  bool position_spring = false;  // optional: also hold the pelvis position
  double pos_omega_n = 4.0;      // rad/s: k = c m omega^2
  double pos_zeta = 1.0;
  double max_force = 800.0;      // N
  // Consciousness dynamics.
  double knockout_threshold = 1.0;  // hit severity (>=) that knocks out outright
  double stun_time = 1.5;           // s after the last hit before recovery starts
  double recovery_rate = 0.5;       // consciousness per second once recovering
};

// Upright target that keeps the current heading: Rz(heading_of(q)) (tilt removed).
Eigen::Quaterniond upright_target(const Eigen::Quaterniond& pelvis_world);

class RootSpring {
 public:
  // severity in [0, inf): consciousness -= severity; >= knockout_threshold -> 0 (unconscious, gains 0).
  void hit(const RootSpringParams& p, double severity);
  // Advance the recovery clock.
  void update(const RootSpringParams& p, double dt);
  double consciousness() const { return consciousness_; }
  void set_consciousness(double c);

  // The wrench on the pelvis. I_body: whole-body inertia about the root (composite_inertias()[0]); mass: total.
  // Returns zero when !p.enabled. The orientation term is the world-space servo (eq. 3) on the root.
  Wrench compute(const RootSpringParams& p, double I_body, double mass, const Eigen::Quaterniond& q_target,
                 const Eigen::Quaterniond& q_actual, const Eigen::Vector3d& omega_actual,
                 const Eigen::Vector3d& x_target = Eigen::Vector3d::Zero(),
                 const Eigen::Vector3d& x_actual = Eigen::Vector3d::Zero(),
                 const Eigen::Vector3d& v_actual = Eigen::Vector3d::Zero()) const;

 private:
  double consciousness_ = 1.0;
  double since_hit_ = 1e9;
};

}  // namespace eng::control
