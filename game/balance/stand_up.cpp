#include "game/balance/stand_up.h"

#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"
#include "game/balance/balance_controller.h"
#include "game/boxer.h"

namespace boxing {

void actuate_stand_up(BalanceTick& tick, const StandUpTuning& t) {
  const eng::physics::Model& m = tick.m;
  eng::physics::Data& d = tick.d;
  Boxer& b = tick.b;
  const int n = tick.desc.skeleton.size();
  const int pelvis = b.bodies.body[0];
  // Every joint: eq. 3's world torque toward the get-up clip, on the bone and (reaction) on its parent, within the
  // joint's strength (StandUpTuning::joint_torque_limit).
  for (int i = 1; i < n; ++i) {
    Eigen::Vector3d tau = b.ctl.servo.tau[i];
    if (tau.norm() > t.joint_torque_limit) tau *= t.joint_torque_limit / tau.norm();
    eng::physics::apply_world_torque_with_reaction(m, d, b.bodies.body[i], tau);
  }
  // The root assist toward the clip's root, at full strength whatever the consciousness (a stand-up is the moment the
  // boxer pulls itself together; the servo's gains stay scaled).
  const eng::control::RootSpring full;
  const eng::control::Wrench w = full.compute(
      t.assist, b.control_body.I_eff[0], b.control_body.total_mass, b.desired.pose.rotation[0], b.scratch.W_a[0],
      b.scratch.omega_a[0], b.desired.pose.root_position, d.x[pelvis].p,
      eng::physics::point_velocity(d, pelvis, d.x[pelvis].p));
  b.ctl.root_torque = w.torque;
  b.ctl.root_force = w.force + Eigen::Vector3d(0.0, 0.0, t.weight_share * b.control_body.total_mass * 9.81);
  if (b.ctl.root_force.norm() > t.assist.max_force) b.ctl.root_force *= t.assist.max_force / b.ctl.root_force.norm();
  eng::physics::apply_world_torque(d, pelvis, w.torque);
  eng::physics::apply_force_at_point(m, d, pelvis, b.ctl.root_force, d.x[pelvis].p);
}

}  // namespace boxing
