// Per-tick dispatch over the servo spaces (paper sections IV-V).
#include "engine/control/servo/controller.h"

#include <cassert>

namespace eng::control {

void control_step(const anim::Skeleton& skel, ServoSpace space, const ServoGains& gains, const ControlBody& body,
                  const MeathookParams& hook, const anim::PoseSample& desired, double heading_yaw, double delta,
                  const ActualState& actual, ServoState& st, Wrench& root_help) {
  assert(actual.W_a && actual.omega_a);
  root_help = Wrench{};
  switch (space) {
    case ServoSpace::World:
    case ServoSpace::Person:
      inertial_servo_step(skel, space, gains, body.I_eff, desired, heading_yaw, delta, *actual.W_a,
                          *actual.omega_a, st);
      return;
    case ServoSpace::Parent:
    case ServoSpace::ParentMeathook: {
      st.resize(skel.size());
      parent_space_torques(skel, gains, body.I_eff, desired, *actual.W_a, *actual.omega_a, st.tau,
                           st.tau_limit.empty() ? nullptr : &st.tau_limit);
      if (space == ServoSpace::ParentMeathook && skel.size() > 0) {
        const Eigen::Vector3d w0 =
            desired.angular_velocity.empty() ? Eigen::Vector3d::Zero() : desired.angular_velocity[0];
        root_help = meathook(hook, body.total_mass, body.I_eff[0], desired.pose.root_position,
                             desired.root_velocity, desired.pose.rotation[0], w0, actual.root_position,
                             actual.root_velocity, (*actual.W_a)[0], (*actual.omega_a)[0]);
      }
      return;
    }
  }
}

}  // namespace eng::control
