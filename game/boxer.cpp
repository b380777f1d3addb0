// The boxer's control tick as a pipeline of stages (boxer_control), the clip's placement on the crates.
#include "game/boxer.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "engine/control/servo/person_space.h"
#include "engine/control/servo/world_pose.h"
#include "engine/core/stage_laps.h"
#include "engine/physics/dynamics.h"
#include "game/boxer_stepping.h"

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

double root_assist_limit(const Boxer& b) {
  return b.settings.root_params.enabled ? b.settings.root_params.max_torque * b.ctl.root_spring.consciousness() : 0.0;
}

double assist_reach(const eng::physics::Model& m, const Boxer& b) {
  return root_assist_limit(b) / (b.control_body.total_mass * m.gravity.norm());
}

void list_leg_geoms(const Boxer& b, std::vector<int> (&out)[2]) {
  for (int k = 0; k < 2; ++k) {
    const eng::control::LegBones& leg = b.bones.leg[k];
    for (int i : {leg.thigh, leg.shank, leg.foot})
      for (int g = 0; i >= 0 && g < b.bodies.geom_count[i]; ++g) out[k].push_back(b.bodies.first_geom[i] + g);
  }
}

void boxer_joint_speed_limits(eng::physics::Model& m, const Boxer& b, double time) {
  const bool limp = b.ctl.state.fallen() || b.ctl.state.state == BoxerState::GettingUp || time < b.ctl.handled_until;
  for (int body : b.bodies.body) m.bodies[body].max_speed = limp ? kLimpJointMaxSpeed : 0.0;
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
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(b.stance.heading + b.ctl.yaw_offset, Eigen::Vector3d::UnitZ()));
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

// The actual world orientation and angular velocity of every bone.
void read_actual_state(const eng::physics::Data& d, Boxer& b, int n) {
  b.scratch.W_a.resize(n);
  b.scratch.omega_a.resize(n);
  for (int i = 0; i < n; ++i) {
    const int body = b.bodies.body[i];
    b.scratch.W_a[i] = Eigen::Quaterniond(d.x[body].R).normalized();
    b.scratch.omega_a[i] = d.v_body[body].head<3>();
  }
}

// Swing feet: the clip (authored on a flat floor at z = 0) has the sole's lowest end more than StepTuning::swing_lift
// above its floor. Judged on the clip itself, not after fitting to the crates, where a leg too short for a low crate
// leaves a planted foot hanging. A raised heel (the cross's pivot) keeps the toe down: not a swing.
void clip_feet(const eng::assets::CharacterDesc& desc, Boxer& b, bool swing[2], double clip_ankle_h[2]) {

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

// A servo rooted at the feet (world / person space): which legs support, the desired motion anchored on the planted
// feet, the ankles aimed at (actual, tiptoe pressed down, a step's target), the balance controller's adjustment of
// the desired pose, and the legs fitted to those ankles.
void fit_support_legs(const eng::physics::Model& m, eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                      Boxer& b, const bool swing[2], const double clip_ankle_h[2], bool loaded[2], double dt) {
  const auto& skel = desc.skeleton;
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
    if (b.ctl.balance_steps.step.active && !b.ctl.balance_steps.step.quick) {
      // A balance step under way: the desired body goes where the pelvis is (the push carried it; the legs' targets
      // then reach from there, and the QP's com task does the balancing) instead of hauling it back over its feet.
      // Not a footwork step (quick): nothing pushed, its stance foot anchors the body (following the pelvis, the
      // desired body and the pelvis ran off together, 0.35 m in a swing).
      const Eigen::Vector2d e = (d.x[b.bodies.body[0]].p - b.desired.pose.root_position).head<2>();
      b.ctl.anchor += e;
      b.desired.pose.root_position.head<2>() += e;
    } else if (planted > 0 && !b.ctl.state.fallen()) {  // a fallen body's feet anchor nothing (the walk goes on as authored)
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
    // its toes (a rear foot after a cross-over: heel up, no load, for seconds) is pressed back down flat
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

// The servo's heading: the stance's (world space), or person space's free heading, the pelvis's low-passed and
// steered toward facing the opponent (docs/decisions/person-space-heading.md).
double servo_heading(Boxer& b, double dt) {
  double heading = b.stance.heading;
  if (b.settings.space == eng::control::ServoSpace::Person) {
    const double h = eng::control::heading_of(b.scratch.W_a[0]);
    if (!b.ctl.have_person_heading) b.ctl.person_heading = h, b.ctl.have_person_heading = true;
    b.ctl.person_heading += (1.0 - std::exp(-dt / b.settings.tuning.person.heading_tau)) * std::remainder(h - b.ctl.person_heading, 2.0 * M_PI);
    // The game steers the free heading slowly toward facing the opponent (the "turn to face each other").
    b.ctl.person_heading += (1.0 - std::exp(-dt * b.settings.tuning.person.face_gain)) * std::remainder(b.stance.heading - b.ctl.person_heading, 2.0 * M_PI);
    heading = b.ctl.person_heading;
  }
  return heading;
}

}  // namespace

void boxer_control(const eng::physics::Model& m, eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   const Arena& arena, Boxer& b, double dt, ControlStageTimes* profile) {
  eng::core::StageLaps<ControlStageTimes> laps(profile);  // each stage's lap (boxer.h); no clock when null
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  read_actual_state(d, b, n);
  laps.lap(&ControlStageTimes::pose);
  // A carried step's foot in the air holds the walk in its clip (GraphWalker::hold_transitions).
  if (eng::anim::GraphWalker* walker = b.source.walker())
    walker->hold_transitions = (b.ctl.step[0].active && b.ctl.step[0].carried) ||
                               (b.ctl.step[1].active && b.ctl.step[1].carried);
  b.source.tick(dt * b.ctl.clip_rate, Eigen::Rotation2Dd(-b.stance.heading) * b.ctl.anchor, &b.desired);
  laps.lap(&ControlStageTimes::graph);
  bool swing[2];          // the clip has this foot in the air (a step)
  double clip_ankle_h[2];  // the clip's ankle above its sole's lowest end (m), for the tiptoe test
  clip_feet(desc, b, swing, clip_ankle_h);
  laps.lap(&ControlStageTimes::pose);
  const bool steps = plans_steps(b);
  if (steps && d.time > 0.0) update_support_base(d, arena, b, dt);
  if (steps && d.time > 0.0) gate_lift_off(m, d, desc, arena, b, swing, dt);
  laps.lap(&ControlStageTimes::stepping);
  footwork_turn(b, dt);
  place_desired_pose(desc, arena, b, b.desired);
  laps.lap(&ControlStageTimes::pose);
  if (steps) plan_steps(d, desc, arena, b, swing, dt);
  if (steps && d.time > 0.0) take_balance_steps(m, d, desc, arena, b, swing, dt);
  laps.lap(&ControlStageTimes::stepping);
  if (b.limp) return;
  const bool parent_space = b.settings.space == ServoSpace::Parent || b.settings.space == ServoSpace::ParentMeathook;
  bool loaded[2] = {d.time == 0.0, d.time == 0.0};  // placed on the crates: planted at the start
  if (!b.ctl.joints.empty() && !parent_space) fit_support_legs(m, d, desc, b, swing, clip_ankle_h, loaded, dt);
  // A punch of the match goes for the opponent (game/match/punch_aim.h): its arm bent onto the target.
  apply_punch_aim(desc, b.ctl.aim, b.desired.pose, b.scratch.fk_W, b.scratch.fk_P);
  laps.lap(&ControlStageTimes::pose);

  eng::control::ActualState actual;
  actual.W_a = &b.scratch.W_a;
  actual.omega_a = &b.scratch.omega_a;
  const int pelvis = b.bodies.body[0];
  actual.root_position = d.x[pelvis].p;
  actual.root_velocity = eng::physics::point_velocity(d, pelvis, d.x[pelvis].p);
  eng::control::Wrench help{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // Look ahead one servo tick (the paper's delta) for omega_d.
  // Person (egocentric) space leaves the root's heading free: the desired root takes the pelvis's actual heading
  // (the game steers by changing the clip's placement); world space keeps the placed clip's heading.
  // Person space: the heading is the pelvis's, LOW-PASSED (a push's twist does not turn the desired pose), and
  // steered slowly toward facing the opponent: docs/decisions/person-space-heading.md.
  const double heading = servo_heading(b, dt);
  // A stunned or knocked-down boxer's servo is weaker (the match's gain_scale; 1 otherwise).
  eng::control::ServoGains gains = b.settings.gains;
  gains.omega_n *= b.ctl.gain_scale;
  eng::control::control_step(skel, b.settings.space, gains, b.control_body, b.settings.hook, b.desired, heading, dt, actual, b.ctl.servo,
                             help);
  laps.lap(&ControlStageTimes::servo);
  // The balance controller writes the torques (QP) or the servo's springs and torques (PD).
  BalanceTick tick{m, d, desc, b, loaded, dt};
  tick.heading = heading;
  tick.help = help;
  std::visit([&tick](auto& c) { actuate(c, tick); }, b.ctl.balance);
  laps.lap(&ControlStageTimes::qp);
}

}  // namespace boxing
