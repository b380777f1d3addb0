#pragma once
// The classic parent-space PD servo (paper eq. 1 generalised to ball joints) -- the baseline the paper compares
// against -- and the "meathook", the artificial global support the paper gives the parent-space characters
// ("the parent space characters would otherwise fall over before any comparison could be made", section V).
//
// Per joint i > 0, in the PARENT frame:  tau_p = kp Delta(q_d, q_a) + kd (w_rel_d - w_rel_a)
// with q_a = W_a[parent]^-1 W_a[i] (actual relative rotation), q_d the clip's relative rotation, w_rel the
// relative angular velocity expressed in the parent frame. Converted to world (tau = R(W_a[parent]) tau_p) and
// applied exactly like the inertial servo: +tau on bone i, -tau on its parent. Gains from the same
// (omega_n, zeta) and I_eff rule (inertial_servo.h), so the two servos are compared at equal stiffness.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "engine/anim/skeleton.h"
#include "engine/control/servo/inertial_servo.h"
#include "engine/control/servo/wrench.h"

namespace eng::control {

// tau (world, per bone) for the parent-space servo; tau[0] = 0 (the root is not actuated; see meathook).
// desired.angular_velocity (parent-frame relative rates) may be empty (= 0).
// stable_pd in gains: the proportional term is evaluated on the relative rotations predicted one step ahead.
void parent_space_torques(const anim::Skeleton& skel, const ServoGains& gains, const std::vector<double>& I_eff,
                          const anim::PoseSample& desired, const std::vector<Eigen::Quaterniond>& W_a,
                          const std::vector<Eigen::Vector3d>& omega_a, std::vector<Eigen::Vector3d>& tau,
                          const std::vector<double>* tau_limit = nullptr);

struct MeathookParams {
  double omega_n = 8.0;   // rad/s, both the linear and the angular spring (k = M omega_n^2, d = 2 zeta M omega_n)
  double zeta = 1.0;
  bool gravity_compensation = true;  // add total_mass * g upward so the hook holds without sagging
  double gravity = 9.81;             // m/s^2 along -Z
  double max_force = 1e9;            // N
  double max_torque = 1e9;           // N m
};

// External spring-damper holding the root (pelvis) at its desired position and orientation. Returns a world
// force (at the pelvis com) + torque for the pelvis with no reaction. total_mass / I_body: whole body (the hook
// carries everything), I_body = composite_inertias()[0].
Wrench meathook(const MeathookParams& p, double total_mass, double I_body, const Eigen::Vector3d& x_d,
                const Eigen::Vector3d& v_d, const Eigen::Quaterniond& q_d, const Eigen::Vector3d& omega_d,
                const Eigen::Vector3d& x_a, const Eigen::Vector3d& v_a, const Eigen::Quaterniond& q_a,
                const Eigen::Vector3d& omega_a);

}  // namespace eng::control
