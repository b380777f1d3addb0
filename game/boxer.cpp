#include "game/boxer.h"

#include <algorithm>
#include <cmath>

#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/person_space.h"
#include "engine/control/biped/support_polygon.h"
#include "engine/control/servo/world_pose.h"
#include "engine/control/biped/capture_point.h"
#include "game/balance/com_support.h"
#include "engine/control/biped/foothold.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"

namespace boxing {

using eng::control::LegBones;
using eng::control::ServoSpace;
using eng::control::pose_fk;


namespace {
bool plans_steps(const Boxer& b) {
  return std::visit([](const auto& c) { return plans_steps(c); }, b.ctl.balance);
}
}  // namespace

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
  // the lower of the two crates under the feet (plus the controller's rise, less its drop), move it clip_forward
  // along the heading; the legs are then fitted to the actual crate heights. Why: docs/decisions/stance-placement.md.
  const bool steps = plans_steps(b);
  const double rise = std::visit([&b](const auto& c) { return stance_rise(c, b); }, b.ctl.balance);
  // Balance QP: once the feet have moved (a walk's steps), the crates under the actual feet (boxer_control).
  const double base = steps && b.ctl.have_support_base ? b.ctl.support_base
                                                          : std::min(b.stance.lead_top, b.stance.rear_top) + rise;
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(b.stance.heading, Eigen::Vector3d::UnitZ()));
  const double drop = std::visit([&b](const auto& c) { return stance_drop(c, b); }, b.ctl.balance);
  out.pose.root_position = Eigen::Vector3d(b.stance.position.x(), b.stance.position.y(), base - drop) +
                           yaw * (out.pose.root_position + Eigen::Vector3d(b.settings.tuning.stance.clip_forward, 0.0, 0.0));
  out.pose.root_position.head<2>() += b.ctl.anchor;
  out.pose.rotation[0] = yaw * out.pose.rotation[0];
  out.root_velocity = yaw * out.root_velocity;
  out.angular_velocity[0] = yaw * out.angular_velocity[0];
  const auto& s = desc.skeleton;
  const LegBones* legs = b.bones.leg;
  fit_legs_to_ground(s, legs, base - drop, ground_of(arena), out.pose);
}

namespace {
// Where and when the clip puts foot k down again (step_planner.h), from the pose source's preview.
eng::control::Touchdown touchdown_of(const eng::anim::Skeleton& skel, Boxer& b, int k) {
  const auto preview = [&b](double ahead) { return b.source.preview(ahead); };
  return eng::control::find_touchdown(skel, preview, b.bones.foot[k], b.settings.tuning.foot, b.settings.tuning.step, b.scratch.fk_W, b.scratch.fk_P);
}

// LIFT-OFF GATING (balance QP, lift_off_gate.h): the capture point over the other foot's touching contacts decides
// whether a foot the clip lifts may leave the ground. Measurements: docs/decisions/lift-off-gate.md.
void gate_lift_off(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   Boxer& b, bool swing[2], double dt) {
  const auto& skel = desc.skeleton;
  const int pelvis = b.bodies.body[0];
  for (int k = 0; k < 2; ++k) {
    if (!eng::control::lift_off_gate_due(b.ctl.gate[k], swing[k], !b.ctl.state.fallen())) continue;
    // The other (stance) foot's ground contacts and the capture point.
    const std::vector<Eigen::Vector2d>& stance = b.ctl.contacts.ground_points[1 - k];
    Eigen::Vector2d xi = Eigen::Vector2d::Zero();
    if (stance.size() >= 2) {
      const Eigen::Vector3d com = eng::physics::subtree_com(m, d, pelvis);
      const eng::physics::Vec6 h = eng::physics::spatial_momentum(m, d, pelvis);
      const Eigen::Vector3d vcom = h.tail<3>() / b.control_body.total_mass;
      const double z = std::max(0.3, com.z() - b.ctl.support_base);
      xi = eng::control::capture_point(com.head<2>(), vcom.head<2>(), z);
    }
    const double swing_left = touchdown_of(skel, b, k).ahead;
    const eng::control::GateEvent e =
        eng::control::lift_off_gate_decide(b.ctl.gate[k], swing[k], stance, xi, swing_left, dt, b.settings.tuning.gate, b.scratch.hull);
    if (e == eng::control::GateEvent::StepTaken) ++b.metrics.steps_taken;
    if (e == eng::control::GateEvent::StepSkipped) ++b.metrics.steps_skipped;
  }
}

// STEPS ON THE CRATES (balance QP, step_planner.h): a foot the clip just lifted starts a step toward a foothold on
// the crates; every swinging foot's ankle target advances.
void plan_steps(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, const Arena& arena, Boxer& b,
                const bool swing[2], double dt) {
  const auto& skel = desc.skeleton;
  const int* feet = b.bones.foot;
  std::vector<Eigen::Quaterniond>& W = b.scratch.fk_W;
  std::vector<Eigen::Vector3d>& P = b.scratch.fk_P;
  // A foot the clip just lifted: where (clip floor frame) and when the clip puts it down again.
  bool starts[2] = {false, false};
  eng::control::Touchdown td[2];
  for (int k = 0; k < 2; ++k) {
    if (!swing[k]) b.ctl.step[k].active = false;
    if (!swing[k] || b.ctl.step[k].active) continue;
    starts[k] = true;
    td[k] = touchdown_of(skel, b, k);
  }
  if (!swing[0] && !swing[1]) return;
  pose_fk(skel, b.desired.pose, W, P);  // the placed pose of this tick
  const eng::control::GroundHeight ground = ground_of(arena);
  for (int k = 0; k < 2; ++k) {
    if (!swing[k]) continue;
    eng::control::StepPlan& st = b.ctl.step[k];
    if (starts[k]) {
      const int fb = b.bodies.body[feet[k]];
      const Eigen::Vector3d from = d.x[fb].p + d.x[fb].R * b.settings.tuning.foot.centre;
      eng::control::start_step(st, td[k], P[feet[k]], b.stance.heading, from, ground, b.settings.tuning.foot, b.settings.tuning.step, dt);
    }
    eng::control::advance_step(st, P[feet[k]], W[feet[k]], ground, b.settings.tuning.foot, b.settings.tuning.step, dt);
  }
}
}  // namespace

void boxer_control(const eng::physics::Model& m, eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   const Arena& arena, Boxer& b, double dt) {
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  b.scratch.W_a.resize(n);
  b.scratch.omega_a.resize(n);
  for (int i = 0; i < n; ++i) {
    const int body = b.bodies.body[i];
    b.scratch.W_a[i] = Eigen::Quaterniond(d.x[body].R).normalized();
    b.scratch.omega_a[i] = d.v_body[body].head<3>();
  }
  b.desired = b.source.tick(dt, Eigen::Rotation2Dd(-b.stance.heading) * b.ctl.anchor);
  bool swing[2];          // the clip has this foot in the air (a step)
  double clip_ankle_h[2];  // the clip's ankle above its sole's lowest end (m), for the tiptoe test below
  {
    // Swing feet: the clip (authored on a flat floor at z = 0) has the sole's lowest end more than StepTuning::swing_lift above
    // its floor. Judged on the clip itself, not after fitting to the crates, where a leg too short for a low crate
    // leaves a planted foot hanging. A raised heel (the cross's pivot) keeps the toe down: not a swing.
    std::vector<Eigen::Quaterniond>& W0 = b.scratch.fk_W;
    std::vector<Eigen::Vector3d>& P0 = b.scratch.fk_P;
    pose_fk(desc.skeleton, b.desired.pose, W0, P0);
    const int* feet = b.bones.foot;
    for (int k = 0; k < 2; ++k) {
      const double gap = eng::control::clip_sole_gap(W0, P0, feet[k], b.settings.tuning.foot);
      swing[k] = gap > b.settings.tuning.step.swing_lift;
      clip_ankle_h[k] = P0[feet[k]].z() - gap;
    }
  }
  const bool steps = plans_steps(b);
  if (steps && d.time > 0.0) {
    // The clip's floor: the lower of the crate tops under the two feet where they actually are, low-passed
    // (StanceTuning::base_tau) so a swing foot passing over another crate does not jerk the desired root up or down. The stance's
    // crates only hold until the first step: after one the root was placed for crates the feet had left (a leg
    // over-stretched above a lower crate, or crouched on a higher one).
    double lowest = 1e9;
    for (int f : b.bones.foot) {
      const int fb = b.bodies.body[f];
      const Eigen::Vector3d c = d.x[fb].p + d.x[fb].R * b.settings.tuning.foot.centre;
      lowest = std::min(lowest, arena.top_at(c.x(), c.y()));
    }
    if (!b.ctl.have_support_base) b.ctl.support_base = std::min(b.stance.lead_top, b.stance.rear_top), b.ctl.have_support_base = true;
    b.ctl.support_base += (1.0 - std::exp(-dt / b.settings.tuning.stance.base_tau)) * (lowest - b.ctl.support_base);
  }
  if (steps && d.time > 0.0) gate_lift_off(m, d, desc, b, swing, dt);
  place_desired_pose(desc, arena, b, b.desired);
  if (steps) plan_steps(d, desc, arena, b, swing, dt);
  if (b.limp) return;
  const bool parent_space = b.settings.space == ServoSpace::Parent || b.settings.space == ServoSpace::ParentMeathook;
  bool loaded[2] = {d.time == 0.0, d.time == 0.0};  // placed on the crates: planted at the start
  if (!b.ctl.joints.empty() && !parent_space) {
    // Implicit world-space servo rooted at the feet: aim the leg targets at the ankles where they actually are
    // (closed-loop consistency, leg_ik.h); the legs then carry the pelvis to the clip's root.
    const LegBones* legs = b.bones.leg;
    // A leg is on the support path only while its foot touches something (contacts of the last step); a lifted
    // leg is servoed from the pelvis like an arm and aims at the ground-fitted desired ankle.
    // (FootContacts::support: within 2 cm, a margin against flicker.)
    const double* fn = b.ctl.contacts.normal_force;  // normal (z) force on each foot from the last solve (N)
    for (int k = 0; k < 2; ++k) loaded[k] = loaded[k] || b.ctl.contacts.support[k];
    // STEPPING AND ANCHORING. A swing foot (the clip lifts it; see the top of boxer_control) takes its leg off the
    // support path and the leg aims at the clip's ankle, so the physical foot steps. The feet the clip keeps
    // planted and that touch the crates anchor the desired motion: the desired root moves by their mean horizontal
    // error, so the clip's planted feet sit on the physical ones (a step the walk takes, or a foot that slipped,
    // carries the whole desired body with it instead of leaving the root reaching away from the feet).
    {
      std::vector<Eigen::Quaterniond>& W0 = b.scratch.fk_W;
      std::vector<Eigen::Vector3d>& P0 = b.scratch.fk_P;
      pose_fk(skel, b.desired.pose, W0, P0);
      Eigen::Vector2d err = Eigen::Vector2d::Zero();
      int planted = 0;
      for (int k = 0; k < 2; ++k) {
        if (swing[k]) loaded[k] = false;
        if (!loaded[k]) continue;
        err += (d.x[b.bodies.body[legs[k].foot]].p - P0[legs[k].foot]).head<2>();
        ++planted;
      }
      if (planted > 0 && !b.ctl.state.fallen()) {  // a fallen body's feet anchor nothing (the walk goes on as authored)
        err /= planted;
        b.ctl.anchor += err;
        b.desired.pose.root_position.head<2>() += err;
      }
    }
    // Ankle torque within what the sole can take: |tau| <= Fn * lever (centre of pressure inside the foot), so the
    // ankle gives way instead of tipping the foot over its heel / edge. Before the first solve: the static share.
    const StanceTuning& ts = b.settings.tuning.stance;
    if (ts.ankle_lever > 0.0)
      for (int k = 0; k < 2; ++k) {
        const double f = d.time == 0.0 ? 0.5 * desc.total_mass() * 9.81 : std::max(0.0, fn[k]);
        b.ctl.joints[legs[k].foot].limit = std::max(ts.ankle_min_torque, ts.ankle_lever * f);
      }
    std::vector<Eigen::Quaterniond>& Wtmp = b.scratch.W_d_metric;  // scratch
    std::vector<Eigen::Vector3d>& P = b.scratch.fk_P;
    pose_fk(skel, b.desired.pose, Wtmp, P);
    Eigen::Vector3d ankles[2];
    for (int k = 0; k < 2; ++k) {
      // A planted leg aims at its actual ankle (closed-loop consistency: the legs agree through the ground), lowered
      // by however much higher the ankle stands over its sole's lowest end than the clip's does: a foot left up on
      // its toes (seed 1's rear foot after a cross: heel 40 deg up, no load, for seconds) is pressed back down flat
      // instead of being held there; a flat foot is aimed exactly where it is.
      ankles[k] = P[legs[k].foot];
      // A stepping leg aims at its step's target (the bones' orientation tasks then agree with the ankle's).
      if (!loaded[k] && b.ctl.step[k].active) ankles[k] = b.ctl.step[k].target;
      if (loaded[k]) {
        const int fb = b.bodies.body[legs[k].foot];
        const Eigen::Vector3d a = d.x[fb].p;
        double h = -1e9;
        for (const Eigen::Vector3d& end : {b.settings.tuning.foot.heel, b.settings.tuning.foot.toe}) h = std::max(h, -(d.x[fb].R * end).z());
        ankles[k] = a - Eigen::Vector3d(0.0, 0.0, std::max(0.0, h - clip_ankle_h[k] - b.settings.tuning.stance.tiptoe_deadband));
      }
      for (int bone : {legs[k].thigh, legs[k].shank, legs[k].foot}) {
        b.ctl.joints[bone].support = loaded[k];
        b.ctl.joints[bone].planted = loaded[k] && bone == legs[k].foot;
      }
    }
    // The balance controller's turn before the legs are fitted (the PD layer shifts the desired root).
    BalanceTick tick{m, d, desc, b, loaded, dt};
    tick.Wd = &Wtmp, tick.Pd = &P;
    std::visit([&tick](auto& c) { adjust_desired(c, tick); }, b.ctl.balance);
    fit_legs_to_ankles(skel, legs, ankles, b.desired.pose);
  }

  eng::control::ActualState actual;
  actual.W_a = &b.scratch.W_a;
  actual.omega_a = &b.scratch.omega_a;
  const int pelvis = b.bodies.body[0];
  actual.root_position = d.x[pelvis].p;
  actual.root_velocity = d.v_body[pelvis].tail<3>() + d.v_body[pelvis].head<3>().cross(d.x[pelvis].p);
  eng::control::Wrench help{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // Look ahead one servo tick (the paper's delta) for omega_d.
  // Person (egocentric) space leaves the root's heading free: the desired root takes the pelvis's actual heading
  // (the game steers by changing the clip's placement); world space keeps the placed clip's heading.
  // Person space: the heading is the pelvis's, LOW-PASSED (a push's twist does not turn the desired pose), and
  // steered slowly toward facing the opponent: docs/decisions/person-space-heading.md.
  double heading = b.stance.heading;
  if (b.settings.space == eng::control::ServoSpace::Person) {
    const double h = eng::control::heading_of(b.scratch.W_a[0]);
    if (!b.ctl.have_person_heading) b.ctl.person_heading = h, b.ctl.have_person_heading = true;
    b.ctl.person_heading += (1.0 - std::exp(-dt / b.settings.tuning.person.heading_tau)) * std::remainder(h - b.ctl.person_heading, 2.0 * M_PI);
    // The game steers the free heading slowly toward facing the opponent (the "turn to face each other").
    b.ctl.person_heading += (1.0 - std::exp(-dt * b.settings.tuning.person.face_gain)) * std::remainder(b.stance.heading - b.ctl.person_heading, 2.0 * M_PI);
    heading = b.ctl.person_heading;
  }
  eng::control::control_step(skel, b.settings.space, b.settings.gains, b.control_body, b.settings.hook, b.desired, heading, dt, actual, b.ctl.servo,
                             help);
  // The balance controller writes the torques (QP) or the servo's springs and torques (PD).
  BalanceTick tick{m, d, desc, b, loaded, dt};
  tick.heading = heading;
  tick.help = help;
  std::visit([&tick](auto& c) { actuate(c, tick); }, b.ctl.balance);
}

void boxer_sense_contacts(const eng::physics::Data& d, Boxer& b) {
  eng::control::find_foot_contacts(d.contacts, b.bodies.body, b.bones, b.settings.tuning.contact, b.ctl.contacts);
}

void boxer_measure(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   Boxer& b, double dt) {
  BoxerMetrics& mt = b.metrics;
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  const int pelvis = b.bodies.body[0];
  const double support = std::min(b.stance.lead_top, b.stance.rear_top);
  if (mt.err_sq_sum.empty()) mt.err_sq_sum.assign(n, 0.0);
  // Tracking error in world orientation, against the desired pose lifted with the desired root.
  eng::control::lift_to_world(skel, b.desired.pose, b.desired.pose.rotation[0], b.scratch.W_d_metric);
  if (mt.err_sq_upright.empty()) mt.err_sq_upright.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const Eigen::Quaterniond Wa(d.x[b.bodies.body[i]].R);
    const double e2 = eng::control::orientation_error(b.scratch.W_d_metric[i], Wa).squaredNorm();
    mt.err_sq_sum[i] += e2;
    if (!mt.fell) mt.err_sq_upright[i] += e2;
  }
  ++mt.samples;
  if (!mt.fell) ++mt.samples_upright;

  if (!mt.fell) {
    const double t = b.ctl.root_torque.norm();
    mt.root_torque_sq_dt += t * t * dt;
    mt.root_torque_peak = std::max(mt.root_torque_peak, t);
    if (b.settings.root_params.enabled && t >= 0.999 * b.settings.root_params.max_torque) mt.root_saturated_time += dt;
  }
  const Eigen::Vector3d com = eng::physics::subtree_com(m, d, pelvis);
  if (mt.have_com) mt.max_com_speed = std::max(mt.max_com_speed, (com - mt.last_com).norm() / dt);
  mt.last_com = com;
  mt.have_com = true;


  {  // diagnostic trace
    const int* feet = b.bones.foot;
    if (mt.samples == 1)
      for (int k = 0; k < 2; ++k) mt.foot0[k] = d.x[b.bodies.body[feet[k]]].p;
    const long every = std::lround(0.05 / dt);
    const bool fall_now = mt.fell && !mt.traced_fall;
    if ((d.time < 4.0 && mt.samples % every == 0) || fall_now) {
      if (fall_now) mt.traced_fall = true;
      std::vector<Eigen::Quaterniond> Wd;
      std::vector<Eigen::Vector3d> Pd;
      pose_fk(skel, b.desired.pose, Wd, Pd);
      std::array<double, 12> r{};
      r[0] = d.time;
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      double fz = 0;
      Eigen::Vector3d cop = Eigen::Vector3d::Zero();
      for (int k = 0; k < 2; ++k) {
        const int fb = b.bodies.body[feet[k]];
        const Eigen::Matrix3d R = d.x[fb].R;
        const Eigen::Vector3d fa = R.col(0), fd = Wd[feet[k]] * Eigen::Vector3d::UnitX();
        r[1 + k] = std::remainder(std::atan2(fa.y(), fa.x()) - std::atan2(fd.y(), fd.x()), 2 * M_PI) * 180 / M_PI;
        r[3 + k] = std::acos(std::clamp((R * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0)) * 180 / M_PI;
        // rear (right) foot: sole normal's lean forward / left (heading frame, deg) in the slip columns
        const Eigen::Vector2d up = Eigen::Rotation2Dd(-b.stance.heading) * (R * Eigen::Vector3d::UnitZ()).head<2>();
        if (k == 1) r[5] = std::asin(std::clamp(up.x(), -1.0, 1.0)) * 180 / M_PI, r[6] = std::asin(std::clamp(up.y(), -1.0, 1.0)) * 180 / M_PI;
        centre += 0.5 * (d.x[fb].p + R * Eigen::Vector3d(0.05, 0, 0));
        for (const auto& c : d.contacts) {
          const double f = c.body_b == fb ? c.force.z() : (c.body_a == fb ? -c.force.z() : 0.0);
          if (f == 0.0) continue;
          cop += f * c.point.position;
          fz += f;
        }
      }
      const Eigen::Rotation2Dd toh(-b.stance.heading);
      const Eigen::Vector2d ce = toh * (com - centre).head<2>();
      r[7] = ce.x(), r[8] = ce.y();
      if (fz > 1e-6) {
        const Eigen::Vector2d cp = toh * (cop / fz - centre).head<2>();
        r[9] = cp.x(), r[10] = cp.y();
      }
      r[11] = d.x[pelvis].p.z() - support;
      mt.trace.push_back(r);
    }
  }
  // The state machine (a fall: pelvis below half its standing height above the support, or a link other than feet
  // and shanks on the crates or floor for more than 0.2 s), then the metrics record what it decided.
  const bool went_down = boxer_state_update(b.ctl.state, b.settings.tuning.fall, d.x[pelvis].p.z() - support,
                                            b.ctl.contacts.other_link_on_ground, d.time, dt);
  if (went_down) {
    mt.fell = true;
    mt.fell_reason = b.ctl.state.reason;
    mt.fell_at = d.time, mt.fell_pelvis = d.x[pelvis].p;
  } else if (!mt.fell) {
    mt.time_upright += dt;
  }
}

}  // namespace boxing
