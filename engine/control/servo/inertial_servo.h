#pragma once
// World-space ("inertial") servo of Jenkins, Wrotek & McGuire, eq. 3:
//   tau_b = k1 Delta(W_d, W_a) + k2 (omega_d - omega_a)        (world frame, per bone b != root)
// W_d is lifted from the desired parent-space pose with only the root taken from outside (world_pose.h),
// omega_d comes from the look-ahead of eq. 2. The game applies +tau_i to bone i and -tau_i to its parent, so
// the servo is purely internal (net torque zero); tau[0] is external help on the pelvis (zero by default).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "engine/anim/skeleton.h"
#include "engine/control/servo/composite_inertia.h"
#include "engine/control/servo/person_space.h"
#include "engine/control/servo/world_pose.h"

namespace eng::control {

enum class ServoSpace {
  World,           // eq. 3, desired root = the clip's root orientation as is (absolute world space)
  Person,          // eq. 3, desired root = person_space_root(clip root, game heading) (egocentric)
  Parent,          // classic parent-space PD (baseline, parent_space_servo.h), no support
  ParentMeathook,  // parent-space PD + the paper's artificial "meathook" support on the root
};

// ONE pair of numbers for the whole body. Per bone: k1_i = I_i omega_n^2, k2_i = 2 zeta I_i omega_n with I_i
// the bone's effective inertia (composite_inertias: subtree about the joint, rest pose), so every joint responds
// like a unit-mass oscillator with natural frequency omega_n and damping ratio zeta.
struct ServoGains {
  double omega_n = 12.0;  // rad/s natural frequency
  double zeta = 1.0;      // damping ratio (1 = critical)
  // Root term of eq. 3 applied to the pelvis as EXTERNAL help (no reaction), scaled by this factor of the
  // whole-body rule (I_0 = whole-body inertia). 0 (default): tau[0] = 0 -- the boxers stand unaided.
  double root_k_scale = 0.0;
  // Torque limits: |tau_i| <= min(torque_limit_per_kg * subtree_mass_i, max_angular_accel * I_i), a zero
  // entry meaning "no limit from this rule". max_angular_accel needs only I_eff; torque_limit_per_kg needs the
  // subtree masses (servo_torque_limits()).
  double torque_limit_per_kg = 0.0;  // N m per kg of subtree mass
  double max_angular_accel = 0.0;    // rad/s^2
  // Stable PD (Tan, Liu & Turk 2011): evaluate the spring on the state predicted one step ahead
  // (W_a advanced by omega_a dt, W_d by omega_d dt) and treat the damper implicitly. For one body this gives
  //   tau = (k1 Delta(W_d', W_a') + k2 (omega_d - omega_a)) / (1 + k2 dt / I) = (...) / (1 + 2 zeta omega_n dt)
  // which stays stable for any gain at the physics step dt (explicit PD diverges once omega_n dt ~ 1).
  bool stable_pd = false;
  double dt = 1.0 / 240.0;  // physics step, used by stable_pd
};

// Per-bone stiffness/damping from the gain rule.
inline double servo_k1(const ServoGains& g, double I) { return I * g.omega_n * g.omega_n; }
inline double servo_k2(const ServoGains& g, double I) { return 2.0 * g.zeta * I * g.omega_n; }

// Per-bone absolute torque limits (N m; +inf = none) from the gains' limit rules.
std::vector<double> servo_torque_limits(const ServoGains& g, const std::vector<double>& I_eff,
                                        const std::vector<double>& subtree_mass);

// Eq. 3 for every bone. All vectors are per bone, world frame. tau is resized to skel.size().
// tau[0] = root_k_scale * (eq. 3 on the root) -- 0 by default (world/person space need no root help).
// tau_limit: optional per-bone limits (servo_torque_limits); if null, only max_angular_accel * I_i applies.
void inertial_servo_torques(const anim::Skeleton& skel, const ServoGains& gains, const std::vector<double>& I_eff,
                            const std::vector<Eigen::Quaterniond>& W_d, const std::vector<Eigen::Vector3d>& omega_d,
                            const std::vector<Eigen::Quaterniond>& W_a, const std::vector<Eigen::Vector3d>& omega_a,
                            std::vector<Eigen::Vector3d>& tau, const std::vector<double>* tau_limit = nullptr);

// Eq. 3 for one body (also used by the root spring / meathook). I: effective inertia of that body.
Eigen::Vector3d servo_torque_one(const ServoGains& gains, double I, const Eigen::Quaterniond& W_d,
                                 const Eigen::Vector3d& omega_d, const Eigen::Quaterniond& W_a,
                                 const Eigen::Vector3d& omega_a, double limit);

// Desired root orientation for a space: World/Parent*: the clip root; Person: person_space_root(clip, heading).
Eigen::Quaterniond desired_root(ServoSpace space, const Eigen::Quaterniond& clip_root, double heading_yaw);

// Preallocated per-character state: size once with resize(), then inertial_servo_step allocates nothing.
struct ServoState {
  std::vector<Eigen::Quaterniond> W_d;
  std::vector<Eigen::Vector3d> omega_d;
  std::vector<Eigen::Vector3d> tau;
  std::vector<double> tau_limit;  // optional; empty = use max_angular_accel only
  WorldPoseScratch scratch;
  void resize(int n);
};

// One control tick in World or Person space (Parent* spaces: use control_step, controller.h): desired root (space), lift (section IV), omega_d by look-ahead
// (eq. 2, delta > 0) and torques (eq. 3) into state.tau.
void inertial_servo_step(const anim::Skeleton& skel, ServoSpace space, const ServoGains& gains,
                         const std::vector<double>& I_eff, const anim::PoseSample& desired, double heading_yaw,
                         double delta, const std::vector<Eigen::Quaterniond>& W_a,
                         const std::vector<Eigen::Vector3d>& omega_a, ServoState& state);

}  // namespace eng::control
