#include "game/boxer.h"

#include <algorithm>
#include <cmath>

#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/person_space.h"
#include "engine/control/biped/support_polygon.h"
#include "engine/control/servo/world_pose.h"
#include "engine/control/biped/capture_point.h"
#include "engine/control/biped/foothold.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"

namespace boxing {

using eng::control::LegBones;
using eng::control::ServoSpace;
using eng::control::pose_fk;

namespace {
// Balance layer gains (boxer_control): desired-root shift per metre of com error (-) and per m/s of com speed (s).
// Measured (world, seeds 1-5 stand + seed 3 pushes): 0 / 0 -> 5/10 stand, 270 and 315 pushes fall; 1.0 / 0.3 ->
// 315 falls; 2.0 / 0.5 -> 10/10, all 8 pushes; 3.0 / 0.7 -> no better for person 315.
constexpr double kBalanceKp = 2.0;
constexpr double kBalanceKd = 0.5;
constexpr double kBalanceMaxShift = 0.15;  // m
// CoP ankle limit |tau| <= kAnkleLever * Fn: tried 0.10 m -> all 10 boxers fell (2.6-18 s), all pushes fell: off.
constexpr double kAnkleLever = 0.0;      // m, see boxer_control (0 = no CoP limit)
constexpr double kAnkleMinTorque = 10.0;  // N m
constexpr double kPersonHeadingTau = 1.0;  // s, see boxer_control
// Person space: the game turns the heading toward the opponent (the stance's heading) at this rate (1/s). Measured
// (stand 60 s, seeds 1-20): 0 -> 39/40 person (seed 9 creeps round on its feet and falls at 58 s); 0.1 -> 40/40 and
// every 150 N push on seeds 1-8 survived; 1.0 -> pushes at 270 / 315 / 0 deg fall on seeds 3, 5, 6.
constexpr double kFaceGain = 0.1;
constexpr double kClipForward = 0.05;  // m, see place_desired_pose
constexpr double kRearRise = 0.75;  // see place_desired_pose
constexpr double kMaxRise = 0.09;  // m
constexpr double kBaseTau = 0.3;   // s, see boxer_control (the clip's floor under the actual feet)
// Balance QP: the boxer's stance and steps, measured on the graph walk (60 s, seeds 1-24, mean / median time to the
// first fall, README) and the stand (60 s, seeds 1-20, both boxers, world / person space):
//  * kQpStanceDrop: the desired root this much lower than the clip's, the legs fitted to the crates (knees bent
//    deeper). On a stance with the lead crate 16 cm higher the rear knee stood at 0.23 rad against the clip's 0.47
//    (leg nearly straight, heel lifting, no range left to move the com).
//  * swing_press (StepTuning): a stepping ankle aimed this much below the clip's, so the sole slides along its crate (a boxer's
//    shuffle) instead of lifting: the body is never on one foot alone. Not when stepping up onto a higher crate.
// Neither alone helps the walk: drop 0.08 -> 14.8 / 10.7 s, press 0.08 -> 8.4 / 7.3 s, none -> 12.4 / 8.7 s. With
// press 0.10: drop 0.04 -> 23.6 / 16.2 s, 0.06 -> 27.0 / 22.1 s, 0.10 -> 30.4 / 29.0 s; but the deeper stances cost
// the stand: 0.06 -> person 39/40, 0.10 -> world 39/40, person 34/40 (falls at 44-60 s: a planted foot's yaw creeps,
// the rear foot 79 deg off at the fall); 0.04 -> 40/40, 40/40.
constexpr double kQpStanceDrop = 0.04;  // m
// (The press is StepTuning::swing_press, the foot's points Boxer::biped.foot.)
// A planted ankle standing more than this above its sole's lowest end than the clip's is pressed back down (m).
// Measured without the deadband: person stand seed 9 fell at 55 s; with 1 cm: 40/40 (with kFaceGain).
constexpr double kTiptoeDeadband = 0.01;
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
  // the lower of the two crates under the feet, plus kRearRise of the step (at most kMaxRise) when the REAR crate
  // is the higher one; the legs are then fitted to the actual crate heights. Why: at the old base (the lower crate)
  // every boxer with the rear crate higher (12-17 cm) fell at 1.4-2.2 s, rear heel lifting and the rear sole rolling
  // onto its outer edge (trace in the report), every lead-higher boxer stood. Measured rise: 0.5 x step -> the
  // 12 cm steps fall, 0.75 x step -> the 16 cm steps fall (lead leg over-extended); 0.75 x step capped at 9 cm ->
  // all stand. Lead-higher: any rise makes them fall (0.25 x step: s5 at 5.5 s; 0.5: three of five).
  // Balance QP: no rise. The clip stands on the lower crate and the rear leg bends up to the higher one. Measured
  // (stand 30 s seeds 1-12, drills seeds 1-4): rise 0.5 x step -> seed 2's lead foot hangs above its crate and the
  // boxer tips over before it lands; 0.25 -> 24/24 stand, cross and rear uppercut drills 7/8; 0 -> 24/24, every
  // punch and defence drill 8/8.
  const double rise = b.balance_qp ? 0.0 : std::min(kMaxRise, kRearRise * std::max(0.0, b.stance.rear_top - b.stance.lead_top));
  // Balance QP: once the feet have moved (a walk's steps), the crates under the actual feet (boxer_control).
  const double base = b.balance_qp && b.have_support_base ? b.support_base
                                                          : std::min(b.stance.lead_top, b.stance.rear_top) + rise;
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(b.stance.heading, Eigen::Vector3d::UnitZ()));
  // The guard clip's feet are not centred on the stance point (ankles at +0.17 / -0.24 m): placed as authored the
  // lead heel hangs ~1 cm over the seam onto the rear foot's crate, and when that crate is the higher one the heel
  // sits against its side (every seed that fell at HEAD had the rear crate higher). kClipForward moves the clip
  // along the heading so both soles lie inside their own crates (lead heel ~4 cm clear of the seam).
  // Balance QP: the stance kQpStanceDrop deeper than the clip's (below).
  const double drop = b.balance_qp ? kQpStanceDrop : 0.0;
  out.pose.root_position = Eigen::Vector3d(b.stance.position.x(), b.stance.position.y(), base - drop) +
                           yaw * (out.pose.root_position + Eigen::Vector3d(kClipForward, 0.0, 0.0));
  out.pose.root_position.head<2>() += b.anchor;
  out.pose.rotation[0] = yaw * out.pose.rotation[0];
  out.root_velocity = yaw * out.root_velocity;
  out.angular_velocity[0] = yaw * out.angular_velocity[0];
  const auto& s = desc.skeleton;
  const LegBones* legs = b.bones.leg;
  fit_legs_to_ground(s, legs, base - drop, ground_of(arena), out.pose);
}

namespace {
// Centre of mass of the actual body (position, velocity) and of the desired pose (its forward kinematics Wd / Pd),
// and the support centres: the mean of the sole centres of the feet in `feet_on` (actual, desired).
struct ComAndSupport {
  Eigen::Vector3d com_a = Eigen::Vector3d::Zero(), vcom = Eigen::Vector3d::Zero(), com_d = Eigen::Vector3d::Zero();
  Eigen::Vector3d centre_a = Eigen::Vector3d::Zero(), centre_d = Eigen::Vector3d::Zero();
  int feet = 0;  // how many feet the centres average
};

ComAndSupport com_and_support(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, const Boxer& b,
                              const std::vector<Eigen::Quaterniond>& Wd, const std::vector<Eigen::Vector3d>& Pd,
                              const int foot_bones[2], const bool feet_on[2]) {
  ComAndSupport r;
  const double M = desc.total_mass();
  for (int i = 0; i < desc.skeleton.size(); ++i) {
    const int body = b.bodies.body[i];
    const double mi = desc.bones[i].mass;
    const Eigen::Vector3d c = d.com_world[body];
    r.com_a += mi * c;
    r.vcom += mi * (d.v_body[body].tail<3>() + d.v_body[body].head<3>().cross(c));
    r.com_d += mi * (Pd[i] + Wd[i] * desc.bones[i].com);
  }
  r.com_a /= M, r.vcom /= M, r.com_d /= M;
  for (int k = 0; k < 2; ++k) {
    if (!feet_on[k]) continue;
    const int fb = b.bodies.body[foot_bones[k]];
    r.centre_a += d.x[fb].p + d.x[fb].R * b.biped.foot.centre;
    r.centre_d += Pd[foot_bones[k]] + Wd[foot_bones[k]] * b.biped.foot.centre;
    ++r.feet;
  }
  if (r.feet > 0) r.centre_a /= r.feet, r.centre_d /= r.feet;
  return r;
}

// The balance QP's inputs for one boxer (balance_qp.h), solved, and its joint torques written to d.tau.
//  * Contacts: the touching contact points (gap < kQpTouchGap) with the crates, from the last step: of the feet
//    the clip plants and of any other link (a knee, a hand).
//  * Com: PD toward the desired pose's com, measured against the support (desired com - desired feet centre,
//    put on the actual feet centre), with the clip's com velocity over its feet as feed-forward: Kudoh's com
//    acceleration as a PD target (thesis sec. 2.5.1). The target is clamped into the contacts' support polygon.
//  * Angular momentum about the com damped toward zero.
//  * Every bone: eq. 3 as an acceleration, alpha = omega_n^2 Delta(W_d, W_a) + 2 zeta omega_n (omega_d - omega_a),
//    weighted by the bone's servo inertia (heavy subtrees matter most, as eq. 3's gains scale with them).
//  * Touching feet: their contact points held (balance_qp.h) and a strong orientation task (clip's tilt, own
//    heading); swing feet: the ankle toward its step's target (PD, plan_steps); a planted foot that hovers is lowered.
// Measured against the PD balance layer (README): stand and 150 N pushes as good, larger pushes, every punch and
// defence drill, tracking and the walk better.
// Com PD natural frequency (critically damped). Walk 60 s seeds 1-12, mean time to the first fall: 4 -> 12.6 s,
// 6 -> 14.6 s, 9 -> 14.3 s.
constexpr double kQpComOmega = 6.0;  // rad/s
constexpr double kQpMomentumDamping = 4.0;  // 1/s
constexpr double kQpMu = 0.6;           // friction used in the plan (the crates and soles have 0.9)
// Weight of a touching foot's orientation task (kg m^2 like the bones' servo inertias; the pelvis has 8.3). Measured
// (walk 40 s, seeds 1-6): 1 / 10 / 50 / 500 -> first falls at 6.9-24 / 8.0-21 / 7.5-23 / 5.9-22 s: little effect.
constexpr double kQpPlantedFootWeight = 50.0;
constexpr double kQpTouchGap = 0.002;  // m, a contact closer than this carries load in the plan
constexpr double kQpLand = 0.03;        // m
constexpr double kQpSupportMargin = 0.03;  // m, see the com target below
constexpr double kQpShiftMargin = 0.03;    // m, a weight shift's target inside the stance foot (gate_lift_off)
constexpr double kQpMaxComSpeed = 1.0;  // m/s, the desired com velocity's bound
// Swing foot: weight per kg of foot of its ankle task. At 10 the leg's orientation tasks (aimed from where the
// pelvis actually is) won and a step_back's foot landed 10-16 cm off its target; at 1000 (with the velocity
// feed-forward) 6-7 cm. Walk 60 s seeds 1-12: mean first fall 14.6 s (the PD layer: 1.7-6 s on seeds 1-3).
constexpr double kQpSwingWeight = 1000.0;
constexpr double kQpMaxSwingSpeed = 3.0;  // m/s, the swing foot's feed-forward velocity bound
constexpr double kQpMaxComAcc = 6.0;    // m/s^2, the desired com acceleration's bound

void boxer_balance_qp(const eng::physics::Model& m, eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                      Boxer& b, const bool loaded[2], double dt) {
  namespace ph = eng::physics;
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  const int pelvis = b.bodies.body[0];
  eng::control::BalanceQpInput& in = b.qp_in;
  in.clear();
  in.root_body = pelvis;
  in.dof_begin = m.bodies[pelvis].v_index;
  in.dof_end = in.dof_begin;
  for (size_t i = 1; i < m.bodies.size(); ++i)
    if (m.bodies[i].root == pelvis) in.dof_end = std::max(in.dof_end, m.bodies[i].v_index + m.bodies[i].nv);
  const int* feet = b.bones.foot;
  if (b.metrics.fell) {
    // DOWN: the QP stands a boxer, it does not yet move one lying on the crates (the stand-ups are the match's
    // work). Its torques on a lying body, its links pressed on the ground, made the limbs flail at 30-80 rad/s and
    // the simulation diverge within 1-4 s (walk seed 3, even with every ground contact in the plan, accelerations
    // capped at 200 rad/s^2 or torques at 400 N m). So a fallen boxer goes limp (the passive joint damping stays).
    for (int k = in.dof_begin; k < in.dof_end; ++k) d.tau[k] = 0.0;
    return;
  }

  // Contacts of the planted feet. A foot is held (planted) only while it actually touches (FootContacts::on_ground):
  // a foot the clip plants but that hovers a little above its crate is lowered onto it instead (below).
  const bool touching[2] = {loaded[0] && b.contacts.on_ground[0], loaded[1] && b.contacts.on_ground[1]};
  for (const auto& c : d.contacts) {
    if (c.point.depth < -kQpTouchGap) continue;  // speculative, not touching
    if (c.body_a != 0 && c.body_b != 0) continue;  // only the crates and floor (static) carry the body
    const int body = c.body_a == 0 ? c.body_b : c.body_a;
    if (m.bodies[body].root != pelvis) continue;
    int foot = -1;
    for (int k = 0; k < 2; ++k)
      if (body == b.bodies.body[feet[k]]) foot = k;
    // Every other link touching the ground (a knee, a hand) is a contact of the plan too: left out, the plan
    // would assume that link moves freely and push it into the crate.
    if (foot >= 0 && !loaded[foot]) continue;  // a swing foot brushing the crate carries nothing
    eng::control::QpContact qc;
    qc.body = body;
    qc.point = c.point.position;
    qc.normal = c.body_b == body ? c.point.normal : Eigen::Vector3d(-c.point.normal);
    qc.mu = kQpMu;
    in.contacts.push_back(qc);
  }

  // Desired pose FK (after anchoring / leg fitting): com and feet.
  std::vector<Eigen::Quaterniond>& Wd = b.fk_W;
  std::vector<Eigen::Vector3d>& Pd = b.fk_P;
  pose_fk(skel, b.desired.pose, Wd, Pd);
  const ComAndSupport cs = com_and_support(d, desc, b, Wd, Pd, feet, loaded);
  const Eigen::Vector3d &com_a = cs.com_a, &vcom = cs.vcom, &com_d = cs.com_d, &centre_a = cs.centre_a,
                        &centre_d = cs.centre_d;
  const int nl = cs.feet;
  Eigen::Vector3d rel_d = com_d - centre_d;  // the clip's com over its feet
  if (nl == 0) rel_d.setZero();
  // The clip's com velocity over its feet, differenced tick to tick; not across a change of the planted feet
  // (the support centre jumps) and at most kQpMaxComSpeed.
  const int support_set = (loaded[0] ? 1 : 0) | (loaded[1] ? 2 : 0);
  Eigen::Vector3d v_d = Eigen::Vector3d::Zero();
  if (b.have_com_d && support_set == b.qp_support_set) v_d = (rel_d - b.com_d_rel_last) / dt;
  if (v_d.norm() > kQpMaxComSpeed) v_d *= kQpMaxComSpeed / v_d.norm();
  b.com_d_rel_last = rel_d;
  b.qp_support_set = support_set;
  b.have_com_d = true;
  if (nl > 0) {
    Eigen::Vector3d e = (com_a - centre_a) - rel_d;
    e.z() = com_a.z() - com_d.z();
    // The target's floor projection clamped into the support polygon of the touching contacts (less a margin):
    // a target the ground reaction cannot reach (after a step that landed short, say) is not chased over the edge.
    if (!in.contacts.empty()) {
      b.qp_pts.clear();
      for (const auto& c : in.contacts) b.qp_pts.push_back(c.point.head<2>());
      eng::control::convex_hull_2d(b.qp_pts, b.qp_hull);
      Eigen::Vector2d target = eng::control::clamp_to_polygon(b.qp_hull, com_a.head<2>() - e.head<2>(), kQpSupportMargin);
      // A step held for its weight shift (gate_lift_off): the target goes over the other foot's contacts.
      for (int k = 0; k < 2; ++k) {
        if (!b.gate[k].holding) continue;
        const int other = b.bodies.body[feet[1 - k]];
        b.qp_pts.clear();
        for (const auto& c : in.contacts)
          if (c.body == other) b.qp_pts.push_back(c.point.head<2>());
        if (b.qp_pts.empty()) continue;
        eng::control::convex_hull_2d(b.qp_pts, b.qp_hull);
        target = eng::control::clamp_to_polygon(b.qp_hull, target, kQpShiftMargin);
      }
      e.head<2>() = com_a.head<2>() - target;
    }
    const double kp = kQpComOmega * kQpComOmega, kd = 2.0 * kQpComOmega;
    in.com_acc = -kp * e - kd * (vcom - v_d);
    if (in.com_acc.norm() > kQpMaxComAcc) in.com_acc *= kQpMaxComAcc / in.com_acc.norm();
    const ph::Vec6 h = ph::spatial_momentum(m, d, pelvis);
    const Eigen::Vector3d k_com = h.head<3>() - com_a.cross(h.tail<3>());
    in.momentum_rate = -kQpMomentumDamping * k_com;
  } else {
    in.com_acc = m.gravity;  // airborne: nothing to plan with
  }

  // Bone orientation tasks (eq. 3 as accelerations).
  const double wn = b.gains.omega_n, kp = wn * wn, kd = 2.0 * b.gains.zeta * wn;
  for (int i = 0; i < n; ++i) {
    eng::control::QpAngularTask t;
    t.body = b.bodies.body[i];
    t.alpha = kp * eng::control::orientation_error(b.servo.W_d[i], b.W_a[i]) + kd * (b.servo.omega_d[i] - b.omega_a[i]);
    t.weight = b.control_body.I_eff[i];
    in.angular.push_back(t);
  }
  for (int k = 0; k < 2; ++k) {
    const int fb = b.bodies.body[feet[k]];
    if (touching[k]) {
      // Held through its contact points (balance_qp.h); the foot's orientation task rolls a foot standing on an
      // edge or corner flat about it, strongly (the sole is the support).
      // The target keeps the clip's tilt of the foot but takes the foot's actual heading: the contacts have no
      // torsional friction, so a planted foot is not twisted toward the clip's yaw (the body turns above it).
      const Eigen::Quaterniond& Wd_foot = b.servo.W_d[feet[k]];
      const Eigen::Quaterniond target =
          eng::control::yaw_rotation(eng::control::heading_of(b.W_a[feet[k]]) - eng::control::heading_of(Wd_foot)) *
          Wd_foot;
      in.angular[feet[k]].alpha = kp * eng::control::orientation_error(target, b.W_a[feet[k]]) - kd * b.omega_a[feet[k]];
      in.angular[feet[k]].weight = kQpPlantedFootWeight;
    } else {
      eng::control::QpPointTask t;
      t.body = fb;
      t.point = d.x[fb].p;
      const Eigen::Vector3d v = d.v_body[fb].tail<3>() + d.v_body[fb].head<3>().cross(t.point);
      // A planted-but-hovering foot aims kQpLand below where it is (it comes down onto the crate).
      // A swing foot aims at its step's target (plan_steps: the clip's ankle, moved onto a good foothold).
      const eng::control::StepPlan& step = b.step[k];
      const Eigen::Vector3d swing_target = step.active ? step.target : Pd[feet[k]];
      const Eigen::Vector3d target = loaded[k] ? Eigen::Vector3d(t.point - Eigen::Vector3d(0, 0, kQpLand)) : swing_target;
      // The target's velocity as feed-forward (a step's swing moves at 1-2 m/s: PD alone lags ~2 zeta v / wn,
      // 10-20 cm). Differenced tick to tick, the height from the clip's own (the crate under the foot changes in
      // jumps); zero on the tick a foot leaves the support.
      const Eigen::Vector3d ff_point(swing_target.x(), swing_target.y(), step.active ? step.clip_z : swing_target.z());
      Eigen::Vector3d v_ff = Eigen::Vector3d::Zero();
      if (!loaded[k] && b.swing_prev[k]) v_ff = (ff_point - b.swing_target_prev[k]) / dt;
      if (v_ff.norm() > kQpMaxSwingSpeed) v_ff *= kQpMaxSwingSpeed / v_ff.norm();
      b.swing_target_prev[k] = ff_point;
      t.acc = kp * (target - t.point) + kd * ((loaded[k] ? Eigen::Vector3d::Zero() : v_ff) - v);
      t.weight = kQpSwingWeight * desc.bones[feet[k]].mass;
      in.points.push_back(t);
    }
  }
  for (int k = 0; k < 2; ++k) b.swing_prev[k] = !loaded[k] && !touching[k];
  eng::control::balance_qp_solve(m, d, in, b.qp_params, b.qp_ws, b.qp_out);
  // A non-finite solve (never seen standing; a guard) leaves the joints limp for the tick instead of poisoning the
  // whole simulation.
  const bool finite = b.qp_out.tau.allFinite();
  // The root rows: the root assist's generalised force (zero when it is off).
  for (int k = 0; k < in.dof_end - in.dof_begin; ++k) d.tau[in.dof_begin + k] = finite ? b.qp_out.tau[k] : 0.0;
  b.root_torque = finite ? b.qp_out.root_assist : Eigen::Vector3d::Zero();
}

// Where and when the clip puts foot k down again (step_planner.h), from the pose source's preview.
eng::control::Touchdown touchdown_of(const eng::anim::Skeleton& skel, Boxer& b, int k) {
  const auto preview = [&b](double ahead) { return b.source.preview(ahead); };
  return eng::control::find_touchdown(skel, preview, b.bones.foot[k], b.biped.foot, b.biped.step, b.fk_W, b.fk_P);
}

// LIFT-OFF GATING (balance QP, lift_off_gate.h): the capture point over the other foot's touching contacts decides
// whether a foot the clip lifts may leave the ground. Measurements: docs/decisions/lift-off-gate.md.
void gate_lift_off(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   Boxer& b, bool swing[2], double dt) {
  const auto& skel = desc.skeleton;
  const int pelvis = b.bodies.body[0];
  for (int k = 0; k < 2; ++k) {
    if (!eng::control::lift_off_gate_due(b.gate[k], swing[k], !b.metrics.fell)) continue;
    // The other (stance) foot's ground contacts and the capture point.
    const std::vector<Eigen::Vector2d>& stance = b.contacts.ground_points[1 - k];
    Eigen::Vector2d xi = Eigen::Vector2d::Zero();
    if (stance.size() >= 2) {
      const Eigen::Vector3d com = eng::physics::subtree_com(m, d, pelvis);
      const eng::physics::Vec6 h = eng::physics::spatial_momentum(m, d, pelvis);
      const Eigen::Vector3d vcom = h.tail<3>() / b.control_body.total_mass;
      const double z = std::max(0.3, com.z() - b.support_base);
      xi = eng::control::capture_point(com.head<2>(), vcom.head<2>(), z);
    }
    const double swing_left = touchdown_of(skel, b, k).ahead;
    const eng::control::GateEvent e =
        eng::control::lift_off_gate_decide(b.gate[k], swing[k], stance, xi, swing_left, dt, b.biped.gate, b.qp_hull);
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
  std::vector<Eigen::Quaterniond>& W = b.fk_W;
  std::vector<Eigen::Vector3d>& P = b.fk_P;
  // A foot the clip just lifted: where (clip floor frame) and when the clip puts it down again.
  bool starts[2] = {false, false};
  eng::control::Touchdown td[2];
  for (int k = 0; k < 2; ++k) {
    if (!swing[k]) b.step[k].active = false;
    if (!swing[k] || b.step[k].active) continue;
    starts[k] = true;
    td[k] = touchdown_of(skel, b, k);
  }
  if (!swing[0] && !swing[1]) return;
  pose_fk(skel, b.desired.pose, W, P);  // the placed pose of this tick
  const eng::control::GroundHeight ground = ground_of(arena);
  for (int k = 0; k < 2; ++k) {
    if (!swing[k]) continue;
    eng::control::StepPlan& st = b.step[k];
    if (starts[k]) {
      const int fb = b.bodies.body[feet[k]];
      const Eigen::Vector3d from = d.x[fb].p + d.x[fb].R * b.biped.foot.centre;
      eng::control::start_step(st, td[k], P[feet[k]], b.stance.heading, from, ground, b.biped.foot, b.biped.step, dt);
    }
    eng::control::advance_step(st, P[feet[k]], W[feet[k]], ground, b.biped.foot, b.biped.step, dt);
  }
}
}  // namespace

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
  b.desired = b.source.tick(dt, Eigen::Rotation2Dd(-b.stance.heading) * b.anchor);
  bool swing[2];          // the clip has this foot in the air (a step)
  double clip_ankle_h[2];  // the clip's ankle above its sole's lowest end (m), for the tiptoe test below
  {
    // Swing feet: the clip (authored on a flat floor at z = 0) has the sole's lowest end more than StepTuning::swing_lift above
    // its floor. Judged on the clip itself, not after fitting to the crates, where a leg too short for a low crate
    // leaves a planted foot hanging. A raised heel (the cross's pivot) keeps the toe down: not a swing.
    std::vector<Eigen::Quaterniond>& W0 = b.fk_W;
    std::vector<Eigen::Vector3d>& P0 = b.fk_P;
    pose_fk(desc.skeleton, b.desired.pose, W0, P0);
    const int* feet = b.bones.foot;
    for (int k = 0; k < 2; ++k) {
      const double gap = eng::control::clip_sole_gap(W0, P0, feet[k], b.biped.foot);
      swing[k] = gap > b.biped.step.swing_lift;
      clip_ankle_h[k] = P0[feet[k]].z() - gap;
    }
  }
  if (b.balance_qp && d.time > 0.0) {
    // The clip's floor: the lower of the crate tops under the two feet where they actually are, low-passed
    // (kBaseTau) so a swing foot passing over another crate does not jerk the desired root up or down. The stance's
    // crates only hold until the first step: after one the root was placed for crates the feet had left (a leg
    // over-stretched above a lower crate, or crouched on a higher one).
    double lowest = 1e9;
    for (int f : b.bones.foot) {
      const int fb = b.bodies.body[f];
      const Eigen::Vector3d c = d.x[fb].p + d.x[fb].R * b.biped.foot.centre;
      lowest = std::min(lowest, arena.top_at(c.x(), c.y()));
    }
    if (!b.have_support_base) b.support_base = std::min(b.stance.lead_top, b.stance.rear_top), b.have_support_base = true;
    b.support_base += (1.0 - std::exp(-dt / kBaseTau)) * (lowest - b.support_base);
  }
  if (b.balance_qp && d.time > 0.0) gate_lift_off(m, d, desc, b, swing, dt);
  place_desired_pose(desc, arena, b, b.desired);
  if (b.balance_qp) plan_steps(d, desc, arena, b, swing, dt);
  if (b.limp) return;
  const bool parent_space = b.space == ServoSpace::Parent || b.space == ServoSpace::ParentMeathook;
  bool loaded[2] = {d.time == 0.0, d.time == 0.0};  // placed on the crates: planted at the start
  if (!b.joints.empty() && !parent_space) {
    // Implicit world-space servo rooted at the feet: aim the leg targets at the ankles where they actually are
    // (closed-loop consistency, leg_ik.h); the legs then carry the pelvis to the clip's root.
    const LegBones* legs = b.bones.leg;
    // A leg is on the support path only while its foot touches something (contacts of the last step); a lifted
    // leg is servoed from the pelvis like an arm and aims at the ground-fitted desired ankle.
    // (FootContacts::support: within 2 cm, a margin against flicker.)
    const double* fn = b.contacts.normal_force;  // normal (z) force on each foot from the last solve (N)
    for (int k = 0; k < 2; ++k) loaded[k] = loaded[k] || b.contacts.support[k];
    // STEPPING AND ANCHORING. A swing foot (the clip lifts it; see the top of boxer_control) takes its leg off the
    // support path and the leg aims at the clip's ankle, so the physical foot steps. The feet the clip keeps
    // planted and that touch the crates anchor the desired motion: the desired root moves by their mean horizontal
    // error, so the clip's planted feet sit on the physical ones (a step the walk takes, or a foot that slipped,
    // carries the whole desired body with it instead of leaving the root reaching away from the feet).
    {
      std::vector<Eigen::Quaterniond>& W0 = b.fk_W;
      std::vector<Eigen::Vector3d>& P0 = b.fk_P;
      pose_fk(skel, b.desired.pose, W0, P0);
      Eigen::Vector2d err = Eigen::Vector2d::Zero();
      int planted = 0;
      for (int k = 0; k < 2; ++k) {
        if (swing[k]) loaded[k] = false;
        if (!loaded[k]) continue;
        err += (d.x[b.bodies.body[legs[k].foot]].p - P0[legs[k].foot]).head<2>();
        ++planted;
      }
      if (planted > 0 && !b.metrics.fell) {  // a fallen body's feet anchor nothing (the walk goes on as authored)
        err /= planted;
        b.anchor += err;
        b.desired.pose.root_position.head<2>() += err;
      }
    }
    // Ankle torque within what the sole can take: |tau| <= Fn * lever (centre of pressure inside the foot), so the
    // ankle gives way instead of tipping the foot over its heel / edge. Before the first solve: the static share.
    if (kAnkleLever > 0.0)
      for (int k = 0; k < 2; ++k) {
        const double f = d.time == 0.0 ? 0.5 * desc.total_mass() * 9.81 : std::max(0.0, fn[k]);
        b.joints[legs[k].foot].limit = std::max(kAnkleMinTorque, kAnkleLever * f);
      }
    std::vector<Eigen::Quaterniond>& Wtmp = b.W_d_metric;  // scratch
    std::vector<Eigen::Vector3d>& P = b.fk_P;
    pose_fk(skel, b.desired.pose, Wtmp, P);
    Eigen::Vector3d ankles[2];
    for (int k = 0; k < 2; ++k) {
      // A planted leg aims at its actual ankle (closed-loop consistency: the legs agree through the ground), lowered
      // by however much higher the ankle stands over its sole's lowest end than the clip's does: a foot left up on
      // its toes (seed 1's rear foot after a cross: heel 40 deg up, no load, for seconds) is pressed back down flat
      // instead of being held there; a flat foot is aimed exactly where it is.
      ankles[k] = P[legs[k].foot];
      // A stepping leg aims at its step's target (the bones' orientation tasks then agree with the ankle's).
      if (!loaded[k] && b.step[k].active) ankles[k] = b.step[k].target;
      if (loaded[k]) {
        const int fb = b.bodies.body[legs[k].foot];
        const Eigen::Vector3d a = d.x[fb].p;
        double h = -1e9;
        for (const Eigen::Vector3d& end : {b.biped.foot.heel, b.biped.foot.toe}) h = std::max(h, -(d.x[fb].R * end).z());
        ankles[k] = a - Eigen::Vector3d(0.0, 0.0, std::max(0.0, h - clip_ankle_h[k] - kTiptoeDeadband));
      }
      for (int bone : {legs[k].thigh, legs[k].shank, legs[k].foot}) {
        b.joints[bone].support = loaded[k];
        b.joints[bone].planted = loaded[k] && bone == legs[k].foot;
      }
    }
    // BALANCE LAYER (on top of eq. 3; Kudoh's "PD near the centre"): keep the centre of mass over the support.
    // The desired com offset from the support centre is the clip's own (desired pose, desired feet); the error of
    // the actual com against it, and the com velocity, shift the desired root horizontally the other way
    //   root_d += -(kp e + kd v)   (clamped), e = (com_a - centre_a) - (com_d - centre_d)
    // The legs are re-fitted below from the shifted root to the actual ankles, so the support servo (ankles,
    // knees, hips) pushes the body back over the feet. Only while a foot is planted.
    if (!b.balance_qp && (loaded[0] || loaded[1])) {
      const int foot_bones[2] = {legs[0].foot, legs[1].foot};
      const ComAndSupport cs = com_and_support(d, desc, b, Wtmp, P, foot_bones, loaded);
      const Eigen::Vector3d &com_a = cs.com_a, &com_d = cs.com_d, &centre_a = cs.centre_a, &centre_d = cs.centre_d;
      Eigen::Vector3d vcom = cs.vcom;
      Eigen::Vector3d e = (com_a - centre_a) - (com_d - centre_d);
      e.z() = 0, vcom.z() = 0;
      Eigen::Vector3d shift = -(kBalanceKp * e + kBalanceKd * vcom);
      if (shift.norm() > kBalanceMaxShift) shift *= kBalanceMaxShift / shift.norm();
      b.desired.pose.root_position += shift;
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
  // Person space: the heading is the pelvis's, LOW-PASSED (time constant kPersonHeadingTau): a push's sudden
  // twist of the pelvis otherwise turns the whole desired pose with it, the planted ankles twist the feet after it
  // and the feet spin on the crates (no torsional friction; seed 3, 315 deg push: feet yawed 40 deg in 0.6 s).
  // Slow turns are still followed. (Tried: heading from the planted feet -> every boxer fell at 1.3-2.6 s, the
  // feet's desired yaw then follows their own yaw.)
  double heading = b.stance.heading;
  if (b.space == eng::control::ServoSpace::Person) {
    const double h = eng::control::heading_of(b.W_a[0]);
    if (!b.have_person_heading) b.person_heading = h, b.have_person_heading = true;
    b.person_heading += (1.0 - std::exp(-dt / kPersonHeadingTau)) * std::remainder(h - b.person_heading, 2.0 * M_PI);
    // The game steers the free heading slowly toward facing the opponent (the "turn to face each other").
    b.person_heading += (1.0 - std::exp(-dt * kFaceGain)) * std::remainder(b.stance.heading - b.person_heading, 2.0 * M_PI);
    heading = b.person_heading;
  }
  eng::control::control_step(skel, b.space, b.gains, b.control_body, b.hook, b.desired, heading, dt, actual, b.servo,
                             help);
  if (b.balance_qp) {  // the QP writes every joint torque; the root spring is its root assist (limit below)
    b.root_spring.update(b.root_params, dt);
    // "lowers its motor gains when knocked out" (paper Fig. 7): the assist's limit scales with consciousness.
    b.qp_params.max_root_assist = b.root_params.max_torque * b.root_spring.consciousness();
    boxer_balance_qp(m, d, desc, b, loaded, dt);
    return;
  }
  // Root spring (paper section V): a torque-limited spring on the pelvis TILT toward the desired root's tilt, the
  // heading left free (no yaw torque), so it helps dynamic balance without steering. External: no reaction.
  b.root_spring.update(b.root_params, dt);
  {
    const Eigen::Quaterniond& Wd0 = b.desired.pose.rotation[0];
    const double h_a = eng::control::heading_of(b.W_a[0]), h_d = eng::control::heading_of(Wd0);
    const Eigen::Quaterniond target = eng::control::yaw_rotation(h_a - h_d) * Wd0;
    Eigen::Vector3d w = b.omega_a[0];
    w.z() = 0.0;  // damp tilt rates only
    b.root_torque = b.root_spring.compute(b.root_params, b.control_body.I_eff[0], b.control_body.total_mass,
                                          target.normalized(), b.W_a[0], w).torque;
    b.root_torque.z() = 0.0;
    help.torque += b.root_torque;
  }
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

void boxer_sense_contacts(const eng::physics::Data& d, Boxer& b) {
  eng::control::find_foot_contacts(d.contacts, b.bodies.body, b.bones, b.biped.contact, b.contacts);
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
  if (mt.err_sq_upright.empty()) mt.err_sq_upright.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const Eigen::Quaterniond Wa(d.x[b.bodies.body[i]].R);
    const double e2 = eng::control::orientation_error(b.W_d_metric[i], Wa).squaredNorm();
    mt.err_sq_sum[i] += e2;
    if (!mt.fell) mt.err_sq_upright[i] += e2;
  }
  ++mt.samples;
  if (!mt.fell) ++mt.samples_upright;

  if (!mt.fell) {
    const double t = b.root_torque.norm();
    mt.root_torque_sq_dt += t * t * dt;
    mt.root_torque_peak = std::max(mt.root_torque_peak, t);
    if (b.root_params.enabled && t >= 0.999 * b.root_params.max_torque) mt.root_saturated_time += dt;
  }
  const Eigen::Vector3d com = eng::physics::subtree_com(m, d, pelvis);
  if (mt.have_com) mt.max_com_speed = std::max(mt.max_com_speed, (com - mt.last_com).norm() / dt);
  mt.last_com = com;
  mt.have_com = true;

  // Fell: pelvis below half its standing height above the support, or a link other than feet and shanks
  // touching the crates or floor for more than 0.2 s.
  const bool touching = b.contacts.other_link_on_ground;  // (FootContacts: within 5 mm)
  mt.ground_contact_time = touching ? mt.ground_contact_time + dt : 0.0;

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
  if (!mt.fell) {
    if (d.x[pelvis].p.z() - support < 0.5 * mt.standing_height) {
      mt.fell = true;
      mt.fell_reason = "pelvis below half its standing height";
    } else if (mt.ground_contact_time > 0.2) {
      mt.fell = true;
      mt.fell_reason = "a link other than feet and shanks touched the ground for 0.2 s";
    }
    if (mt.fell) mt.fell_at = d.time, mt.fell_pelvis = d.x[pelvis].p;
    else mt.time_upright += dt;
  }
}

}  // namespace boxing
