#include "game/boxer.h"

#include <cmath>

#include "engine/control/orientation_error.h"
#include "engine/control/person_space.h"
#include "engine/control/world_pose.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"

namespace boxing {

using eng::control::ServoSpace;

ServoSpace servo_space_from_name(const std::string& name) {
  if (name == "person") return ServoSpace::Person;
  if (name == "parent") return ServoSpace::Parent;
  if (name == "parent-meathook") return ServoSpace::ParentMeathook;
  return ServoSpace::World;
}

const char* servo_space_name(ServoSpace s) {
  switch (s) {
    case ServoSpace::World: return "world";
    case ServoSpace::Person: return "person";
    case ServoSpace::Parent: return "parent";
    case ServoSpace::ParentMeathook: return "parent-meathook";
  }
  return "?";
}

void place_desired_pose(const eng::assets::CharacterDesc& desc, const Arena& arena, const Boxer& b,
                        eng::anim::PoseSample& out) {
  // Place the clip (authored facing +X on a flat floor at z = 0) on the stance: rotate by the heading, lift onto
  // the lower of the two crates under the feet; the legs are then fitted to the actual crate heights.
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(b.stance.heading, Eigen::Vector3d::UnitZ()));
  const double base = std::min(b.stance.lead_top, b.stance.rear_top);
  out.pose.root_position = Eigen::Vector3d(b.stance.position.x(), b.stance.position.y(), base) +
                           yaw * out.pose.root_position;
  out.pose.rotation[0] = yaw * out.pose.rotation[0];
  out.root_velocity = yaw * out.root_velocity;
  out.angular_velocity[0] = yaw * out.angular_velocity[0];
  const auto& s = desc.skeleton;
  const LegBones legs[2] = {{s.find("thigh_l"), s.find("shank_l"), s.find("foot_l")},
                            {s.find("thigh_r"), s.find("shank_r"), s.find("foot_r")}};
  fit_legs_to_ground(s, legs, base, [&](double x, double y) { return arena.top_at(x, y); }, out.pose);
}

void boxer_control(const eng::physics::Model& m, eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   const Arena& arena, Boxer& b, double dt) {
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  b.W_a.resize(n);
  b.omega_a.resize(n);
  for (int i = 0; i < n; ++i) {
    const int body = b.bodies.body[i];
    b.W_a[i] = Eigen::Quaterniond(d.x[body].R).normalized();
    b.omega_a[i] = d.v_body[body].head<3>();
  }
  b.desired = b.source.tick(dt);
  place_desired_pose(desc, arena, b, b.desired);
  if (b.limp) return;
  const bool parent_space = b.space == ServoSpace::Parent || b.space == ServoSpace::ParentMeathook;
  if (!b.joints.empty() && !parent_space) {
    // Implicit world-space servo rooted at the feet: aim the leg targets at the ankles where they actually are
    // (closed-loop consistency, stance_ik.h); the legs then carry the pelvis to the clip's root.
    const LegBones legs[2] = {{skel.find("thigh_l"), skel.find("shank_l"), skel.find("foot_l")},
                              {skel.find("thigh_r"), skel.find("shank_r"), skel.find("foot_r")}};
    // A leg is on the support path only while its foot touches something (contacts of the last step); a lifted
    // leg is servoed from the pelvis like an arm and aims at the ground-fitted desired ankle.
    bool loaded[2] = {d.time == 0.0, d.time == 0.0};  // placed on the crates: planted at the start
    for (const auto& c : d.contacts) {
      if (c.point.depth < -0.02) continue;  // speculative and more than 2 cm away (margin against flicker)
      for (int k = 0; k < 2; ++k) {
        const int fb = b.bodies.body[legs[k].foot];
        if (c.body_a == fb || c.body_b == fb) loaded[k] = true;
      }
    }
    std::vector<Eigen::Quaterniond>& Wtmp = b.W_d_metric;  // scratch
    std::vector<Eigen::Vector3d> P;
    pose_fk(skel, b.desired.pose, Wtmp, P);
    Eigen::Vector3d ankles[2];
    for (int k = 0; k < 2; ++k) {
      ankles[k] = loaded[k] ? Eigen::Vector3d(d.x[b.bodies.body[legs[k].foot]].p) : P[legs[k].foot];
      for (int bone : {legs[k].thigh, legs[k].shank, legs[k].foot}) {
        b.joints[bone].support = loaded[k];
        b.joints[bone].planted = loaded[k] && bone == legs[k].foot;
      }
    }
    fit_legs_to_ankles(skel, legs, ankles, b.desired.pose);
  }

  eng::control::ActualState actual;
  actual.W_a = &b.W_a;
  actual.omega_a = &b.omega_a;
  const int pelvis = b.bodies.body[0];
  actual.root_position = d.x[pelvis].p;
  actual.root_velocity = d.v_body[pelvis].tail<3>() + d.v_body[pelvis].head<3>().cross(d.x[pelvis].p);
  eng::control::Wrench help{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // Look ahead one servo tick (the paper's delta) for omega_d.
  // Person (egocentric) space leaves the root's heading free: the desired root takes the pelvis's actual heading
  // (the game steers by changing the clip's placement); world space keeps the placed clip's heading.
  const double heading = b.space == eng::control::ServoSpace::Person ? eng::control::heading_of(b.W_a[0])
                                                                      : b.stance.heading;
  eng::control::control_step(skel, b.space, b.gains, b.control_body, b.hook, b.desired, heading, dt, actual, b.servo,
                             help);
  const bool implicit = !b.joints.empty();
  if (implicit) {
    // Parent space: the same implicit springs with every joint referenced to the DESIRED parent (planted mode:
    // the classic joint-space PD), the meathook (if any) from control_step; W_d / omega_d lifted as in world space.
    if (parent_space)
      eng::control::inertial_servo_step(skel, ServoSpace::World, b.gains, b.control_body.I_eff, b.desired, heading,
                                        dt, b.W_a, b.omega_a, b.servo);
    // Eq. 3 as implicit joint springs: the references go to the engine, no explicit torques (tau[0] = 0 too:
    // no root help).
    b.q_joint.resize(n);
    for (int i = 0; i < n; ++i) {
      const auto& body = m.bodies[b.bodies.body[i]];
      b.q_joint[i].setZero();
      if (i == 0) continue;
      if (body.joint == eng::physics::JointType::Ball) {
        const double* q = d.q.data() + body.q_index;
        b.q_joint[i] = eng::control::quaternion_log_vector(Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized());
      } else if (body.joint == eng::physics::JointType::Hinge) {
        b.q_joint[i].x() = d.q[body.q_index];
      }
    }
    eng::control::implicit_servo_refs(skel, b.joints, b.servo.W_d, b.servo.omega_d, b.W_a, b.omega_a, b.q_joint,
                                      m.dt, b.spring_ref);
    for (int i = 1; i < n; ++i) {
      const auto& body = m.bodies[b.bodies.body[i]];
      for (int k = 0; k < body.nv; ++k) d.spring_ref[body.v_index + k] = b.spring_ref[i][k];
    }
    for (auto& t : b.servo.tau) t.setZero();
    eng::physics::apply_world_torque(d, pelvis, help.torque);
    if (help.force.squaredNorm() > 0) eng::physics::apply_force_at_point(m, d, pelvis, help.force, d.x[pelvis].p);
    return;
  }
  for (int i = 1; i < n; ++i) eng::physics::apply_world_torque_with_reaction(m, d, b.bodies.body[i], b.servo.tau[i]);
  eng::physics::apply_world_torque(d, pelvis, b.servo.tau[0] + help.torque);
  if (help.force.squaredNorm() > 0) eng::physics::apply_force_at_point(m, d, pelvis, help.force, d.x[pelvis].p);
}

void boxer_measure(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   Boxer& b, double dt) {
  BoxerMetrics& mt = b.metrics;
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  const int pelvis = b.bodies.body[0];
  const double support = std::min(b.stance.lead_top, b.stance.rear_top);
  if (mt.err_sq_sum.empty()) {
    mt.err_sq_sum.assign(n, 0.0);
    mt.standing_height = d.x[pelvis].p.z() - support;
  }
  // Tracking error in world orientation, against the desired pose lifted with the desired root.
  eng::control::lift_to_world(skel, b.desired.pose, b.desired.pose.rotation[0], b.W_d_metric);
  for (int i = 0; i < n; ++i) {
    const Eigen::Quaterniond Wa(d.x[b.bodies.body[i]].R);
    mt.err_sq_sum[i] += eng::control::orientation_error(b.W_d_metric[i], Wa).squaredNorm();
  }
  ++mt.samples;

  const Eigen::Vector3d com = eng::physics::subtree_com(m, d, pelvis);
  if (mt.have_com) mt.max_com_speed = std::max(mt.max_com_speed, (com - mt.last_com).norm() / dt);
  mt.last_com = com;
  mt.have_com = true;

  // Fell: pelvis below half its standing height above the support, or a link other than feet and shanks
  // touching the crates or floor for more than 0.2 s.
  bool touching = false;
  for (const auto& c : d.contacts) {
    if (c.point.depth < -0.005) continue;  // speculative contact, not touching yet
    const int other = c.body_a == 0 ? c.body_b : (c.body_b == 0 ? c.body_a : -1);
    if (other < 0) continue;
    for (int i = 0; i < n; ++i) {
      if (b.bodies.body[i] != other) continue;
      const std::string& nm = skel.name[i];
      if (nm.rfind("foot", 0) != 0 && nm.rfind("shank", 0) != 0) touching = true;
    }
  }
  mt.ground_contact_time = touching ? mt.ground_contact_time + dt : 0.0;
  if (!mt.fell) {
    if (d.x[pelvis].p.z() - support < 0.5 * mt.standing_height) {
      mt.fell = true;
      mt.fell_reason = "pelvis below half its standing height";
    } else if (mt.ground_contact_time > 0.2) {
      mt.fell = true;
      mt.fell_reason = "a link other than feet and shanks touched the ground for 0.2 s";
    }
    if (mt.fell) mt.fell_at = d.time;
    else mt.time_upright += dt;
  }
}

}  // namespace boxing
