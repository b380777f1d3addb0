#pragma once
// One entry point per tick for every ServoSpace, so the game (and the A/B comparison of the paper's section V)
// can switch servo with one enum:
//   World / Person   -> inertial_servo_step (eq. 2 + eq. 3), no root help
//   Parent           -> parent_space_torques (eq. 1 on ball joints), no root help (it will fall: the paper's
//                       point)
//   ParentMeathook   -> parent_space_torques + meathook wrench on the pelvis (the paper's usable baseline)
// Outputs: st.tau (world, per bone; +tau_i on bone i, -tau_i on its parent; tau[0] external on the pelvis) and
// root_help (external force/torque on the pelvis, no reaction). The root spring is separate (root_spring.h).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "engine/anim/skeleton.h"
#include "engine/control/servo/inertial_servo.h"
#include "engine/control/servo/parent_space_servo.h"
#include "engine/control/servo/wrench.h"

namespace eng::control {

struct ControlBody {
  std::vector<double> I_eff;  // composite_inertias(); [0] = whole body about the root
  double total_mass = 0.0;    // kg (meathook)
};

struct ActualState {
  const std::vector<Eigen::Quaterniond>* W_a = nullptr;  // world orientation per bone
  const std::vector<Eigen::Vector3d>* omega_a = nullptr;  // world angular velocity per bone
  Eigen::Vector3d root_position = Eigen::Vector3d::Zero();  // pelvis (same point as Pose::root_position)
  Eigen::Vector3d root_velocity = Eigen::Vector3d::Zero();
};

void control_step(const anim::Skeleton& skel, ServoSpace space, const ServoGains& gains, const ControlBody& body,
                  const MeathookParams& hook, const anim::PoseSample& desired, double heading_yaw, double delta,
                  const ActualState& actual, ServoState& st, Wrench& root_help);

}  // namespace eng::control
