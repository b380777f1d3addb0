// The PD balance controller (pd_balance.h).
#include "game/balance/pd_balance.h"

#include <algorithm>
#include <cmath>

#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/person_space.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"
#include "game/balance/balance_controller.h"
#include "game/balance/com_support.h"
#include "game/boxer.h"

namespace boxing {

using eng::control::ServoSpace;

double stance_rise(const PdBalance&, const Boxer& b) {
  const PdBalanceTuning& tp = b.settings.tuning.pd;
  return std::min(tp.max_rise, tp.rear_rise * std::max(0.0, b.stance.rear_top - b.stance.lead_top));
}

void adjust_desired(PdBalance&, BalanceTick& tick) {
  const eng::physics::Data& d = tick.d;
  const eng::assets::CharacterDesc& desc = tick.desc;
  Boxer& b = tick.b;
  const bool* loaded = tick.loaded;
  const PdBalanceTuning& tp = b.settings.tuning.pd;
  // BALANCE LAYER (on top of eq. 3; Kudoh's "PD near the centre"): keep the centre of mass over the support.
  // The desired com offset from the support centre is the clip's own (desired pose, desired feet); the error of
  // the actual com against it, and the com velocity, shift the desired root horizontally the other way
  //   root_d += -(kp e + kd v)   (clamped), e = (com_a - centre_a) - (com_d - centre_d)
  // The legs are re-fitted below from the shifted root to the actual ankles, so the support servo (ankles,
  // knees, hips) pushes the body back over the feet. Only while a foot is planted.
  if (!(loaded[0] || loaded[1])) return;
  const ComAndSupport cs = com_and_support(d, desc, b, *tick.Wd, *tick.Pd, b.bones.foot, loaded);
  const Eigen::Vector3d &com_a = cs.com_a, &com_d = cs.com_d, &centre_a = cs.centre_a, &centre_d = cs.centre_d;
  Eigen::Vector3d vcom = cs.vcom;
  Eigen::Vector3d e = (com_a - centre_a) - (com_d - centre_d);
  e.z() = 0, vcom.z() = 0;
  Eigen::Vector3d shift = -(tp.kp * e + tp.kd * vcom);
  if (shift.norm() > tp.max_shift) shift *= tp.max_shift / shift.norm();
  b.desired.pose.root_position += shift;
}

void actuate(PdBalance&, BalanceTick& tick) {
  const eng::physics::Model& m = tick.m;
  eng::physics::Data& d = tick.d;
  const auto& skel = tick.desc.skeleton;
  Boxer& b = tick.b;
  const double dt = tick.dt, heading = tick.heading;
  const int n = skel.size();
  const int pelvis = b.bodies.body[0];
  const bool parent_space =
      b.settings.space == ServoSpace::Parent || b.settings.space == ServoSpace::ParentMeathook;
  // Root spring (paper section V): a torque-limited spring on the pelvis TILT toward the desired root's tilt, the
  // heading left free (no yaw torque), so it helps dynamic balance without steering. External: no reaction.
  b.ctl.root_spring.update(b.settings.root_params, dt);
  {
    const Eigen::Quaterniond& Wd0 = b.desired.pose.rotation[0];
    const double h_a = eng::control::heading_of(b.scratch.W_a[0]), h_d = eng::control::heading_of(Wd0);
    const Eigen::Quaterniond target = eng::control::yaw_rotation(h_a - h_d) * Wd0;
    Eigen::Vector3d w = b.scratch.omega_a[0];
    w.z() = 0.0;  // damp tilt rates only
    b.ctl.root_torque = b.ctl.root_spring.compute(b.settings.root_params, b.control_body.I_eff[0], b.control_body.total_mass,
                                          target.normalized(), b.scratch.W_a[0], w).torque;
    b.ctl.root_torque.z() = 0.0;
    tick.help.torque += b.ctl.root_torque;
  }
  const bool implicit = !b.ctl.joints.empty();
  if (implicit) {
    // Parent space: the same implicit springs with every joint referenced to the DESIRED parent (planted mode:
    // the classic joint-space PD), the meathook (if any) from control_step; W_d / omega_d lifted as in world space.
    if (parent_space)
      eng::control::inertial_servo_step(skel, ServoSpace::World, b.settings.gains, b.control_body.I_eff, b.desired, heading,
                                        dt, b.scratch.W_a, b.scratch.omega_a, b.ctl.servo);
    // Eq. 3 as implicit joint springs: the references go to the engine, no explicit torques (tau[0] = 0 too:
    // no root help).
    b.scratch.q_joint.resize(n);
    for (int i = 0; i < n; ++i) {
      const auto& body = m.bodies[b.bodies.body[i]];
      b.scratch.q_joint[i].setZero();
      if (i == 0) continue;
      if (body.joint == eng::physics::JointType::Ball) {
        const double* q = d.q.data() + body.q_index;
        b.scratch.q_joint[i] = eng::control::quaternion_log_vector(Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized());
      } else if (body.joint == eng::physics::JointType::Hinge) {
        b.scratch.q_joint[i].x() = d.q[body.q_index];
      }
    }
    eng::control::implicit_servo_refs(skel, b.ctl.joints, b.ctl.servo.W_d, b.ctl.servo.omega_d, b.scratch.W_a, b.scratch.omega_a, b.scratch.q_joint,
                                      m.dt, b.scratch.spring_ref);
    for (int i = 1; i < n; ++i) {
      const auto& body = m.bodies[b.bodies.body[i]];
      for (int k = 0; k < body.nv; ++k) d.spring_ref[body.v_index + k] = b.scratch.spring_ref[i][k];
    }
    for (auto& t : b.ctl.servo.tau) t.setZero();
    eng::physics::apply_world_torque(d, pelvis, tick.help.torque);
    if (tick.help.force.squaredNorm() > 0) eng::physics::apply_force_at_point(m, d, pelvis, tick.help.force, d.x[pelvis].p);
    return;
  }
  for (int i = 1; i < n; ++i) eng::physics::apply_world_torque_with_reaction(m, d, b.bodies.body[i], b.ctl.servo.tau[i]);
  eng::physics::apply_world_torque(d, pelvis, b.ctl.servo.tau[0] + tick.help.torque);
  if (tick.help.force.squaredNorm() > 0) eng::physics::apply_force_at_point(m, d, pelvis, tick.help.force, d.x[pelvis].p);
}

}  // namespace boxing
