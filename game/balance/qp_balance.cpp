// The balance QP controller (qp_balance.h).
#include "game/balance/qp_balance.h"

#include <chrono>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "engine/control/biped/balance_step.h"
#include "engine/control/biped/support_polygon.h"
#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/person_space.h"
#include "engine/control/servo/world_pose.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/narrowphase.h"
#include "game/balance/balance_controller.h"
#include "game/balance/com_support.h"
#include "game/balance/stand_up.h"
#include "game/boxer.h"

namespace boxing {

using eng::control::pose_fk;

double stance_drop(const QpBalance&, const Boxer& b) { return b.settings.tuning.qp.stance_drop; }

namespace {
// The mean of a body's contact points in the plan (floor x, y): a foot's middle as it stands. Left as it was when the
// body has none.
void contact_centre(const std::vector<eng::control::QpContact>& contacts, int body, Eigen::Vector2d& centre) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int count = 0;
  for (const auto& c : contacts)
    if (c.body == body) sum += c.point.head<2>(), ++count;
  if (count > 0) centre = sum / count;
}

// The com target once the return step's hold on it ends (its touch-down, or its weight shift given up): from where the
// hold left it back toward the clip's at `speed`, for at most `time` (a clip's target moving on is not chased). A
// balance step's swing (the LIP's fall) ends it. The state is the balance steps' (BalanceStepState::settling), so a
// fall or the referee's reset, which start those over, end it too.
void settle_after_return(eng::control::BalanceStepState& st, bool holding, bool balance_swing, double speed,
                         double time, double dt, Eigen::Vector2d& target, Eigen::Vector3d& v_d) {
  if (holding) {
    st.settling = true;
    st.settle_target = target;
    st.settle_elapsed = 0.0;
    return;
  }
  if (!st.settling) return;
  st.settle_elapsed += dt;
  const Eigen::Vector2d to = target - st.settle_target;
  const double most = speed * dt;
  if (balance_swing || to.norm() <= most || st.settle_elapsed >= time) {
    st.settling = false;
    return;
  }
  st.settle_target += to * (most / to.norm());
  target = st.settle_target;
  v_d.setZero();
}
// The legs kept off each other (BalanceQpTuning::leg_clearance*): a separation task per point where a left-leg geom
// comes within leg_clearance of a right-leg one. The shanks and feet do not collide and passed through each other in
// crossed stances; the thighs collide (set_self_colliding) and pressed on each other. A soft task, not a collision:
// the plan keeps the legs apart where the balance allows (the shanks colliding too cost the capture steps that cross
// the stance leg: docs/decisions/balance-steps.md, tenth and fourteenth rounds).
void add_leg_clearance(QpBalance& q, const eng::physics::Model& m, const eng::physics::Data& d, const Boxer& b) {
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const double weight = tq.leg_clearance_weight, gap = tq.leg_clearance, omega = tq.leg_clearance_omega;
  if (q.leg_geoms[0].empty()) list_leg_geoms(b, q.leg_geoms);
  if (weight <= 0.0) return;
  if (!tq.leg_clearance_in_step && b.ctl.balance_steps.step.active && !b.ctl.balance_steps.step.returning) return;
  const int thigh[2] = {b.bodies.body[b.bones.leg[0].thigh], b.bodies.body[b.bones.leg[1].thigh]};
  eng::physics::ContactPoint c[eng::physics::kMaxContactsPerPair];
  for (int ga : q.leg_geoms[0])
    for (int gb : q.leg_geoms[1]) {
      const eng::physics::Geom &A = m.geoms[ga], &B = m.geoms[gb];
      if (!tq.leg_clearance_thighs && A.body == thigh[0] && B.body == thigh[1]) continue;
      const int count = eng::physics::collide_shapes(A.shape, d.x[A.body] * A.local, B.shape, d.x[B.body] * B.local, gap, c,
                                                     eng::physics::kMaxContactsPerPair);
      for (int k = 0; k < count; ++k) {
        const Eigen::Vector3d& n = c[k].normal;  // from a to b
        const Eigen::Vector3d& p = c[k].position;
        const Eigen::Vector3d va = eng::physics::point_velocity(d, A.body, p);
        const Eigen::Vector3d vb = eng::physics::point_velocity(d, B.body, p);
        const double acc = omega * omega * (gap + c[k].depth) - 2.0 * omega * n.dot(vb - va);
        if (acc <= 0.0 || q.in.separations.size() >= size_t(kMaxLegSeparations)) continue;
        eng::control::QpSeparationTask t;
        t.body_a = A.body, t.body_b = B.body;
        t.point_a = t.point_b = p;
        t.normal = n;
        t.acc = acc;
        const double ma = m.bodies[A.body].mass, mb = m.bodies[B.body].mass;
        t.weight = weight * ma * mb / (ma + mb);
        q.in.separations.push_back(t);
      }
    }
}
}  // namespace

// The balance QP's inputs for one boxer (balance_qp.h), solved, and its joint torques written to d.tau.
//  * Contacts: the touching contact points (gap < BalanceQpTuning::touch_gap) with the crates, from the last step: of the feet
//    the clip plants and of any other link (a knee, a hand).
//  * Com: PD toward the desired pose's com, measured against the support (desired com - desired feet centre,
//    put on the actual feet centre), with the clip's com velocity over its feet as feed-forward: Kudoh's com
//    acceleration as a PD target (thesis sec. 2.5.1). The target is clamped into the contacts' support polygon.
//  * Angular momentum about the com damped toward zero.
//  * Every bone: eq. 3 as an acceleration, alpha = omega_n^2 Delta(W_d, W_a) + 2 zeta omega_n (omega_d - omega_a),
//    weighted by the bone's servo inertia (heavy subtrees matter most, as eq. 3's gains scale with them).
//  * Touching feet: their contact points held (balance_qp.h) and a strong orientation task (clip's tilt, own
//    heading); swing feet: the ankle toward its step's target (PD, plan_steps); a planted foot that hovers is lowered.
//  * The legs: kept off each other (add_leg_clearance), a separation task where a left-leg geom nears a right-leg one.
// Measured against the PD balance layer (README): stand and 150 N pushes as good, larger pushes, every punch and
// defence drill, tracking and the walk better.
// Tuning: BalanceQpTuning (qp_balance.h); measurements docs/decisions/balance-qp-tuning.md.
void actuate(QpBalance& q, BalanceTick& tick) {
  const eng::physics::Model& m = tick.m;
  eng::physics::Data& d = tick.d;
  const eng::assets::CharacterDesc& desc = tick.desc;
  Boxer& b = tick.b;
  const bool* loaded = tick.loaded;
  const double dt = tick.dt;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  // The root spring is the QP's root assist: "lowers its motor gains when knocked out" (paper Fig. 7), the assist's
  // limit scales with consciousness.
  b.ctl.root_spring.update(b.settings.root_params, dt);
  q.params.max_root_assist = root_assist_limit(b);  // (0 without a root spring: no assist planned, as w_root_assist = 0)
  namespace ph = eng::physics;
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  const int pelvis = b.bodies.body[0];
  eng::control::BalanceQpInput& in = q.in;
  in.clear();
  in.root_body = pelvis;
  in.dof_begin = m.bodies[pelvis].v_index;
  in.dof_end = in.dof_begin;
  for (size_t i = 1; i < m.bodies.size(); ++i)
    if (m.bodies[i].root == pelvis) in.dof_end = std::max(in.dof_end, m.bodies[i].v_index + m.bodies[i].nv);
  const int* feet = b.bones.foot;
  if (b.ctl.state.fallen()) {
    // DOWN: the QP stands a boxer, it does not yet move one lying on the crates (the stand-ups are the match's
    // work). Its torques on a lying body, its links pressed on the ground, made the limbs flail at 30-80 rad/s and
    // the simulation diverge within 1-4 s (walk seed 3, even with every ground contact in the plan, accelerations
    // capped at 200 rad/s^2 or torques at 400 N m). So a fallen boxer goes limp (the passive joint damping stays).
    for (int k = in.dof_begin; k < in.dof_end; ++k) d.tau[k] = 0.0;
    return;
  }
  if (b.ctl.state.state == BoxerState::GettingUp) {  // the match's stand-up: the servo's torques + root assist
    for (int k = in.dof_begin; k < in.dof_end; ++k) d.tau[k] = 0.0;
    // ... on the ground only: lifted off it (a strong drag, a crate) those explicit torques diverged within 0.1 s
    // (the chaos soak, match seed 11), as the QP's did in the air (below). In the air: limp.
    bool on_ground = false;  // a link of this boxer touching the crates or the floor (last solve's contacts)
    for (const auto& c : d.prev_contacts) {
      if ((c.body_a == 0) == (c.body_b == 0) || c.point.depth < -tq.touch_gap) continue;
      on_ground = on_ground || m.bodies[c.body_a == 0 ? c.body_b : c.body_a].root == pelvis;
    }
    if (on_ground) actuate_stand_up(tick, b.settings.tuning.stand_up);
    else b.ctl.root_torque.setZero(), b.ctl.root_force.setZero();
    return;
  }

  // Contacts of the planted feet. A foot is held (planted) only while it actually touches (FootContacts::on_ground):
  // a foot the clip plants but that hovers a little above its crate is lowered onto it instead (below).
  const bool touching[2] = {loaded[0] && b.ctl.contacts.on_ground[0], loaded[1] && b.ctl.contacts.on_ground[1]};
  // The contacts of the last solve (the ones FootContacts was sensed from; after step1, d.prev_contacts: this
  // step's contacts are found but not solved yet).
  for (const auto& c : d.prev_contacts) {
    if (c.point.depth < -tq.touch_gap) continue;  // speculative, not touching
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
    qc.mu = tq.mu;
    in.contacts.push_back(qc);
  }
  // (The first tick has no solved contacts yet: d.prev_contacts is empty, the body is not in the air.)
  const bool first_tick = q.ticks++ == 0;
  if (in.contacts.empty() && !touching[0] && !touching[1] && !first_tick) {
    // AIRBORNE (thrown, yanked up by the player's strong drag): with no ground the plan's com, momentum and foot
    // tasks cannot be met, and it chased them with the limbs (600-2000 N m, gloves at 40-90 m/s, divergence within a
    // second). The servo's own torques instead (explicit, as in the stand-up) diverged too: the legs' gains are sized
    // for moving the body over a planted foot, and even the upper body's alone, on a free-floating body, ran away
    // within 0.2 s under a strong drag. So in the air the body hangs on its passive joint damping (as when fallen)
    // until a foot or a link touches the ground again.
    for (int k = in.dof_begin; k < in.dof_end; ++k) d.tau[k] = 0.0;
    b.ctl.root_torque.setZero();
    return;
  }

  // Desired pose FK (after anchoring / leg fitting): com and feet.
  std::vector<Eigen::Quaterniond>& Wd = b.scratch.fk_W;
  std::vector<Eigen::Vector3d>& Pd = b.scratch.fk_P;
  pose_fk(skel, b.desired.pose, Wd, Pd);
  const ComAndSupport cs = com_and_support(d, desc, b, Wd, Pd, feet, loaded);
  const Eigen::Vector3d &com_a = cs.com_a, &vcom = cs.vcom, &com_d = cs.com_d, &centre_a = cs.centre_a,
                        &centre_d = cs.centre_d;
  const int nl = cs.feet;
  Eigen::Vector3d rel_d = com_d - centre_d;  // the clip's com over its feet
  if (nl == 0) rel_d.setZero();
  // The clip's com velocity over its feet, differenced tick to tick; not across a change of the planted feet
  // (the support centre jumps) and at most tq.max_com_speed.
  const int support_set = (loaded[0] ? 1 : 0) | (loaded[1] ? 2 : 0);
  Eigen::Vector3d v_d = Eigen::Vector3d::Zero();
  if (q.have_com_d && support_set == q.support_set) v_d = (rel_d - q.com_d_rel_last) / dt;
  if (v_d.norm() > tq.max_com_speed) v_d *= tq.max_com_speed / v_d.norm();
  q.com_d_rel_last = rel_d;
  q.support_set = support_set;
  q.have_com_d = true;
  if (nl > 0) {
    Eigen::Vector3d e = (com_a - centre_a) - rel_d;
    e.z() = com_a.z() - com_d.z();
    // The target's floor projection clamped into the support polygon of the touching contacts (less a margin):
    // a target the ground reaction cannot reach (after a step that landed short, say) is not chased over the edge.
    if (!in.contacts.empty()) {
      q.pts.clear();
      for (const auto& c : in.contacts) q.pts.push_back(c.point.head<2>());
      eng::control::convex_hull_2d_in_place(q.pts, q.hull);
      q.ground_hull = q.hull;  // (kept whole for com_acc_in_support: a weight shift below narrows q.hull to one foot)
      Eigen::Vector2d target = eng::control::clamp_to_polygon(q.hull, com_a.head<2>() - e.head<2>(), tq.support_margin);
      // A step held for its weight shift (gate_lift_off): the target goes over the other foot's contacts. The
      // return step's (take_balance_steps) gets there at tq.return_shift_speed.
      bool return_shift = false;
      for (int k = 0; k < 2; ++k) {
        if (!b.ctl.gate[k].holding) continue;
        const int other = b.bodies.body[feet[1 - k]];
        q.pts.clear();
        for (const auto& c : in.contacts)
          if (c.body == other) q.pts.push_back(c.point.head<2>());
        if (q.pts.empty()) continue;
        eng::control::convex_hull_2d_in_place(q.pts, q.hull);
        target = eng::control::clamp_to_polygon(q.hull, target, tq.shift_margin);
        if (b.ctl.balance_steps.shifting == k) {
          // The return step's shift goes over the foot's middle. shift_margin inside its hull is only 1 cm inside its
          // side (the margin moves the hull's corners toward its centre), while the lift waits for the capture point
          // BalanceStepTuning::return_shift_margin (4 cm) inside it: 1 in 200 of Yin's pushes lifted a return.
          contact_centre(in.contacts, other, target);
          if (!q.return_shift) q.return_shift_target = com_a.head<2>();
          const Eigen::Vector2d to = target - q.return_shift_target;
          const double most = tq.return_shift_speed * dt;
          q.return_shift_target += to.norm() > most ? Eigen::Vector2d(to * (most / to.norm())) : to;
          target = q.return_shift_target;
          return_shift = true;
        }
      }
      q.return_shift = return_shift;
      // The return step's swing: the com held over the stance foot's middle, and no clip velocity fed forward (the
      // clip's com over its feet, differenced from a desired pose whose foot the step swings, read 0.9 m/s and the com
      // ran off the stance foot's side). After the touch-down the target comes back to the clip's slowly: set there
      // at once, 0.3 m away, the com ran on past the front foot at 0.4 m/s.
      const eng::control::BalanceStep& step = b.ctl.balance_steps.step;
      if (step.active && step.returning) {
        contact_centre(in.contacts, b.bodies.body[feet[1 - step.foot]], target);
        v_d.setZero();
      }
      settle_after_return(b.ctl.balance_steps, return_shift || (step.active && step.returning),
                          step.active && !step.returning, tq.return_shift_speed, tq.return_settle_time, dt, target, v_d);
      e.head<2>() = com_a.head<2>() - target;
    }
    const double kp = tq.com_omega * tq.com_omega, kd = 2.0 * tq.com_omega;
    in.com_acc = -kp * e - kd * (vcom - v_d);
    if (in.com_acc.norm() > tq.max_com_acc) in.com_acc *= tq.max_com_acc / in.com_acc.norm();
    // The part of it the soles can give (BalanceQpTuning::com_acc_in_support): only with a root assist to buy the rest,
    // and not while the player's hands hold or push the body (their force moves the com too: the soles' centre of
    // pressure no longer bounds its acceleration).
    if (tq.com_acc_in_support && q.params.max_root_assist > 0.0 && in.contacts.size() >= 3 && d.time >= b.ctl.handled_until) {
      double floor_z = 0.0;
      for (const auto& c : in.contacts) floor_z += c.point.z();
      floor_z /= double(in.contacts.size());  // (the tops under the feet differ by centimetres: small against the com's metre)
      in.com_acc = eng::control::ground_com_acceleration(q.ground_hull, com_a, in.com_acc, com_a.z() - floor_z, tq.cop_margin,
                                                         tq.cop_ramp);
    }
    // A quick step's swing (lift_off_gate.h: capturable once the foot lands, not over the stance foot) and a balance
    // step's (balance_step.h: placed where the capture point will be at touch-down): the com falls toward the landing
    // foot as the linear inverted pendulum does about the stance foot's centre of pressure nearest the capture point,
    // com'' = omega^2 (com - p) (the LIP of Pratt et al. 2006), the model the landing was placed with. Held to the
    // target over the stance foot instead, the plan asked the ground for what it cannot give: in the walks it bought
    // it from the root assist (walk seed 7, 20 s: rms 70 N m against 29); in a push's crossing step it pulled the com
    // back at 6 m/s^2 by folding the trunk over the hips (docs/decisions/balance-steps.md, fourth round).
    const eng::control::BalanceStep& bs = b.ctl.balance_steps.step;
    const eng::control::BalanceStepTuning& ts = b.settings.tuning.balance_step;
    // A balance step's landing below the swing leg's reach: the com's height task aims that much lower, so the stance
    // knee bends and the foot gets down (BalanceStepTuning::reach_share). A return step's too: sent to the floor
    // between two crates, 0.22 m below the stance's top, a return hung on a crate's side and the com ran off.
    auto come_down_to_landing = [&] {
      const eng::control::LegBones& leg = b.bones.leg[bs.foot];
      const Eigen::Vector3d &hip = d.x[b.bodies.body[leg.thigh]].p, &knee = d.x[b.bodies.body[leg.shank]].p,
                            &ankle = d.x[b.bodies.body[leg.foot]].p;
      const Eigen::Vector3d land = Eigen::Vector3d(bs.to.x(), bs.to.y(), bs.to_top) -
                                   Eigen::AngleAxisd(bs.yaw, Eigen::Vector3d::UnitZ()) * b.settings.tuning.foot.sole_offset();
      const double drop = eng::control::step_reach_drop(hip, land, (knee - hip).norm() + (ankle - knee).norm(),
                                                        ts.reach_share, ts.reach_max_drop);
      if (drop > 0.0) in.com_acc.z() = std::min(in.com_acc.z(), std::max(-tq.max_com_acc, -kp * drop - kd * vcom.z()));
    };
    for (int k = 0; k < 2; ++k) {
      // (A carried step, StepTuning::carry, goes on past the clip's touch-down, where the gate lets go: its swing
      // too, up to the quick step's longest; a longer one, slowed to rise onto a higher crate, keeps the com task's
      // target over the stance foot: in the LIP's fall for 0.4-0.5 s the capture point ran off and a balance step
      // lunged 1.3 m.)
      const eng::control::StepPlan& plan = b.ctl.step[k];
      const bool carried = plan.active && plan.carried && plan.duration <= b.settings.tuning.gate.quick_max_swing;
      const bool quick_swing = ((b.ctl.gate[k].lifted && b.ctl.gate[k].quick) || carried) && !loaded[k];
      const bool balance_swing = bs.active && !bs.returning && bs.foot == k;
      if (!(quick_swing || balance_swing) || in.contacts.empty()) continue;
      const double omega = eng::control::lip_omega(std::max(0.3, com_a.z() - b.ctl.support_base));
      const Eigen::Vector2d xi = com_a.head<2>() + vcom.head<2>() / omega;
      // With a root assist (the match's root spring) the pivot goes on past the stance's edge toward xi by the
      // assist's reach, tau / (m g) (the centroidal moment pivot, Popovic, Goswami & Herr 2005): the plan slows the
      // fall with the assist as it does standing. Pivoting at the edge, the swing let the fall run: 800 N x 0.2 s
      // shoves in the match floored 19 of 64 boxers with the steps, 18 in place, 7 with this pivot
      // (docs/decisions/balance-steps.md, sixth round).
      Eigen::Vector2d p = eng::control::clamp_to_polygon(q.hull, xi, 0.0);
      // (Not a clip's quick step: the walks bought its fall from the assist, above.)
      const double beyond = (xi - p).norm(), reach = balance_swing ? assist_reach(m, b) : 0.0;
      p += beyond > reach ? Eigen::Vector2d((xi - p) * (reach / beyond)) : Eigen::Vector2d(xi - p);
      in.com_acc.head<2>() = omega * omega * (com_a.head<2>() - p);
      if (balance_swing && ts.reach_share > 0.0) come_down_to_landing();
    }
    if (bs.active && bs.returning && ts.reach_share > 0.0 && !in.contacts.empty()) come_down_to_landing();
    const ph::Vec6 h = ph::spatial_momentum(m, d, pelvis);
    const Eigen::Vector3d k_com = h.head<3>() - com_a.cross(h.tail<3>());
    in.momentum_rate = -tq.momentum_damping * k_com;
    if (in.momentum_rate.norm() > tq.max_momentum_rate) in.momentum_rate *= tq.max_momentum_rate / in.momentum_rate.norm();
  } else {
    in.com_acc = m.gravity;  // airborne: nothing to plan with
  }

  // Bone orientation tasks (eq. 3 as accelerations).
  const double wn = b.settings.gains.omega_n * b.ctl.gain_scale, kp = wn * wn, kd = 2.0 * b.settings.gains.zeta * wn;
  // A punch's striking arm (upper arm, forearm, glove) can be driven harder while the punch is aimed (PunchAim::arm_gain;
  // 1 in the match since the strike task below carries the glove).
  const PunchAim& aim = b.ctl.aim;
  const int aim_forearm = aim.active && aim.glove > 0 ? skel.parent[aim.glove] : -1;
  const int aim_upper = aim_forearm > 0 ? skel.parent[aim_forearm] : -1;
  // Kudoh's priorities (BalanceQpTuning::trunk_weight, com_weight) while the boxer stands on its support: not
  // while the player's hands hold or push it (BoxerControlState::handled_until), not during a balance step (the step's swing needs the com task low and the trunk free to lean) nor on fewer than
  // min_support_contacts points or tilted past losing_balance_tilt (dragged, tumbling: held to a trunk posture and a
  // com the ground cannot give, the plan whipped the arms to 36-40 m/s in the chaos soak), and only in guard: a stunned
  // boxer's bone tasks are 0.49 times weaker (its gains), the com task x30 outweighed them and the plan swung the arms
  // (gloves at 31-41 m/s in 4 of 10 matches of the sweep, the chaos soak's 5 of 36 runs over 30 m/s).
  // The pelvis's up axis against where the pose wants it (the tilt both gates below read).
  const Eigen::Vector3d up = d.x[pelvis].R * (b.ctl.servo.W_d[0].toRotationMatrix().transpose() * Eigen::Vector3d::UnitZ());
  const bool kudoh = !b.ctl.balance_steps.step.active && d.time >= b.ctl.handled_until && (first_tick || int(in.contacts.size()) >= tq.min_support_contacts) &&
                     up.z() >= std::cos(tq.losing_balance_tilt) && b.ctl.state.state == BoxerState::Guard;
  const double trunk_price = kudoh ? tq.trunk_weight : 1.0;
  // The arms' return (BalanceQpTuning::arm_return_*): with Kudoh's priorities, once the com has been slow a while.
  if (vcom.head<2>().norm() < tq.arm_return_com_speed) {
    if (q.slow_since < 0.0) q.slow_since = d.time;
  } else {
    q.slow_since = -1.0;
  }
  const bool arms_return = kudoh && tq.arm_return_weight > 0.0 && q.slow_since >= 0.0 && d.time - q.slow_since >= tq.arm_return_after;
  for (int i = 0; i < n; ++i) {
    eng::control::QpAngularTask t;
    t.body = b.bodies.body[i];
    const bool arm = aim.arm_gain != 1.0 && (i == aim.glove || i == aim_forearm || i == aim_upper) && aim.active;
    const double g = arm ? aim.arm_gain : 1.0;
    const Eigen::Vector3d e = eng::control::orientation_error(b.ctl.servo.W_d[i], b.scratch.W_a[i]);
    t.alpha = g * g * kp * e + g * kd * (b.ctl.servo.omega_d[i] - b.scratch.omega_a[i]);
    t.weight = b.control_body.I_eff[i] * (arm ? g * g : 1.0) * (q.trunk.size() > size_t(i) && q.trunk[i] ? trunk_price : 1.0);
    if (arms_return && !arm && q.arm.size() > size_t(i) && q.arm[i] && e.norm() > tq.arm_return_step) {
      t.alpha = kp * (tq.arm_return_step / e.norm()) * e + kd * (b.ctl.servo.omega_d[i] - b.scratch.omega_a[i]);
      t.weight *= tq.arm_return_weight;
    }
    in.angular.push_back(t);
  }
  // The punch's strike: the glove's centre driven along a velocity field into the target (PunchAim::strike).
  if (aim.active && aim.strike > 0.0 && aim.strike_speed > 0.0 && aim_upper > 0) {
    eng::control::QpPointTask t;
    t.body = b.bodies.body[aim.glove];
    const auto& xg = d.x[t.body];
    t.point = xg.p + xg.R * desc.bones[aim.glove].com;
    const Eigen::Vector3d v = eng::physics::point_velocity(d, t.body, t.point);
    const Eigen::Vector3d to = aim.target - t.point;
    const double dist = to.norm();
    const Eigen::Vector3d v_d = dist > 1e-9 ? Eigen::Vector3d(to / dist * std::min(aim.strike_speed, aim.strike_rate * dist))
                                            : Eigen::Vector3d::Zero();
    t.acc = aim.strike_omega * (v_d - v);
    const double arm_mass = desc.bones[aim.glove].mass + desc.bones[aim_forearm].mass + desc.bones[aim_upper].mass;
    t.weight = aim.strike * aim.strike_weight * arm_mass;
    in.points.push_back(t);
  }
  for (int k = 0; k < 2; ++k) {
    const int fb = b.bodies.body[feet[k]];
    if (touching[k]) {
      // Held through its contact points (balance_qp.h); the foot's orientation task rolls a foot standing on an
      // edge or corner flat about it, strongly (the sole is the support).
      // The target keeps the clip's tilt of the foot but takes the foot's actual heading: the contacts have no
      // torsional friction, so a planted foot is not twisted toward the clip's yaw (the body turns above it).
      const Eigen::Quaterniond& Wd_foot = b.ctl.servo.W_d[feet[k]];
      const Eigen::Quaterniond target =
          eng::control::yaw_rotation(eng::control::heading_of(b.scratch.W_a[feet[k]]) - eng::control::heading_of(Wd_foot)) *
          Wd_foot;
      in.angular[feet[k]].alpha = kp * eng::control::orientation_error(target, b.scratch.W_a[feet[k]]) - kd * b.scratch.omega_a[feet[k]];
      in.angular[feet[k]].weight = tq.planted_foot_weight;
    } else {
      eng::control::QpPointTask t;
      t.body = fb;
      t.point = d.x[fb].p;
      const Eigen::Vector3d v = eng::physics::point_velocity(d, fb, t.point);
      // A planted-but-hovering foot aims tq.land below where it is (it comes down onto the crate).
      // A swing foot aims at its step's target (plan_steps: the clip's ankle, moved onto a good foothold).
      const eng::control::StepPlan& step = b.ctl.step[k];
      const Eigen::Vector3d swing_target = step.active ? step.target : Pd[feet[k]];
      const Eigen::Vector3d target = loaded[k] ? Eigen::Vector3d(t.point - Eigen::Vector3d(0, 0, tq.land)) : swing_target;
      // The target's velocity as feed-forward (a step's swing moves at 1-2 m/s: PD alone lags ~2 zeta v / wn,
      // 10-20 cm). Differenced tick to tick, the height from the clip's own (the crate under the foot changes in
      // jumps); zero on the tick a foot leaves the support.
      const Eigen::Vector3d ff_point(swing_target.x(), swing_target.y(), step.active ? step.clip_z : swing_target.z());
      Eigen::Vector3d v_ff = Eigen::Vector3d::Zero();
      if (!loaded[k] && q.swing_prev[k]) v_ff = (ff_point - q.swing_target_prev[k]) / dt;
      // A balance step (balance_step.h) swings faster than the clip's and is tracked more stiffly.
      const bool quick = b.ctl.balance_steps.step.active && b.ctl.balance_steps.step.foot == k;
      // A balance or carried step: its path's rate (no re-plan jumps) and its horizontal acceleration, but a balance
      // step's own (phase 1) swing's (BalanceQpTuning::swing_acc_feed_forward).
      Eigen::Vector3d a_ff = Eigen::Vector3d::Zero();
      if (step.has_velocity) {
        v_ff = step.velocity;
        const bool phase1 = quick && !b.ctl.balance_steps.step.returning;
        const double share = phase1 ? tq.balance_step_acc_feed_forward : tq.swing_acc_feed_forward;
        a_ff = share * Eigen::Vector3d(step.acceleration.x(), step.acceleration.y(), 0.0);
      }
      const double max_v = quick ? tq.balance_step_speed : tq.max_swing_speed;
      if (v_ff.norm() > max_v) v_ff *= max_v / v_ff.norm();
      q.swing_target_prev[k] = ff_point;
      const double sw = quick ? tq.balance_step_omega : wn, skp = sw * sw, skd = 2.0 * sw;
      t.acc = (quick ? skp : kp) * (target - t.point) + (quick ? skd : kd) * ((loaded[k] ? Eigen::Vector3d::Zero() : v_ff) - v);
      if (!loaded[k]) t.acc += a_ff;
      t.weight = tq.swing_weight * desc.bones[feet[k]].mass;
      if (quick && tq.balance_step_relative) t.ref_body = pelvis, t.ref_point = d.x[pelvis].p;
      in.points.push_back(t);
      // A stepping foot is kept level as strongly as a planted one: weakly held (its servo inertia), the leg lifted
      // the ankle while the toe stayed on the crate, the foot pitched 10-40 deg toe-down and dragged.
      if (step.active) in.angular[feet[k]].weight = tq.planted_foot_weight;
    }
  }
  for (int k = 0; k < 2; ++k) q.swing_prev[k] = !loaded[k] && !touching[k];
  add_leg_clearance(q, m, d, b);
  // The solve's wall-clock cost, for the report only (boxers[i].qp.solve_us_median / p95); nothing reads it back.
  const auto t0 = std::chrono::steady_clock::now();
  // On fewer than three contact points there is no support polygon: the ground cannot give the com and momentum
  // targets, and a plan held to them swung the arms (1100 N m at the shoulder, gloves at 47 m/s) on a boxer the
  // player had upended. There the com and momentum tasks are priced tq.few_contacts_task_scale times lower and the
  // plan mostly tracks the pose. (Standing, walking and fighting: a few ticks a minute, one foot's edge.)
  eng::control::BalanceQpParams& params = q.solve_params;
  params = q.params;
  // The feet's joint limits kept in the plan (BalanceQpParams::w_limit) while the boxer is calm: the step's stop at the
  // rear ankle's limits (its twist as the cross turns the leg over a planted foot) yanked the foot past its friction,
  // and punch by punch the foot walked off its crate. Not in a push's recovery: the step's stops there are part of how
  // the body catches itself (priced at every speed, 155-157 of 224 pushes survived against 165-174), nor in the
  // player's hands. Measured: docs/decisions/foot-slide.md.
  for (int k = 0; k < 2; ++k) in.limit_bodies.push_back(b.bodies.body[feet[k]]);
  const double calm = std::clamp(2.0 - vcom.head<2>().norm() / tq.limit_calm_speed, 0.0, 1.0);
  const bool upset = b.ctl.balance_steps.recovering || b.ctl.balance_steps.step.active || d.time < b.ctl.handled_until;
  params.w_limit = upset ? 0.0 : tq.limit_weight * calm;
  if (kudoh) params.w_force *= tq.com_weight, params.w_moment *= tq.com_weight;
  // During a balance step's swing the com and momentum tasks are priced lower: held to the stance foot's support they
  // threw the upper body against the fall the step is there to catch (docs/decisions/balance-steps.md).
  if (b.ctl.balance_steps.step.active && !b.ctl.balance_steps.step.returning) {
    params.w_force *= tq.balance_step_com_scale;
    params.w_moment *= tq.balance_step_com_scale;
  }
  // Not during a balance step: its stance foot often rolls onto an edge or a corner (1-2 contact points), and with the
  // com task priced down there the plan asked one corner for 3.7 kN and launched the body 12 cm into the air
  // (0.2 s x 394 N to the right, seed 2); the step's own pricing (balance_step_com_scale) stays.
  // In a push's recovery (between its steps) a foot often lands on an edge or a corner; one contact point under each
  // foot still carries the body, and with the com task priced down the plan dropped the body's weight and tipped it
  // the way the posture pulled (planned 100 N up and 500 N forward against a desired 5 m/s^2 backward).
  const int enough = b.ctl.balance_steps.recovering ? tq.recovery_support_contacts : tq.min_support_contacts;
  const bool unsupported = int(in.contacts.size()) < enough && !first_tick && !b.ctl.balance_steps.step.active;
  if (unsupported) {
    params.w_force *= tq.few_contacts_task_scale;
    params.w_moment *= tq.few_contacts_task_scale;
  }
  eng::control::balance_qp_solve(m, d, in, params, q.ws, q.out);
  q.solve_us.record(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
  // A non-finite solve (never seen standing; a guard) leaves the joints limp for the tick instead of poisoning the
  // whole simulation.
  const bool finite = q.out.tau.allFinite();
  // The root rows: the root assist's generalised force (zero when it is off).
  for (int k = 0; k < in.dof_end - in.dof_begin; ++k) d.tau[in.dof_begin + k] = finite ? q.out.tau[k] : 0.0;
  // Strength: each joint's torque within tq.joint_torque_limit (a ball joint's as a vector), a guard. Standing,
  // walking and fighting never reach it (largest seen in 60 s matches: 292 N m at a hip, 262 at a shoulder). While the
  // boxer is losing its balance, the torque-velocity limit too (tq.speed_strength): there the plan, short of the
  // ground reaction its com and momentum targets need, spun the arms as reaction wheels (gloves at 31-51 m/s in the
  // chaos soak). Standing it stays off: the elbows of punches and blocks reach 60-86 rad/s, and the limit on every
  // joint at every tick made 4 falls without a hit in the match sweep (docs/decisions/joint-speed.md).
  // Losing its balance: no support polygon, or the pelvis tilted past tq.losing_balance_tilt from where the pose wants it.
  // Handled by the player's hands too (BoxerControlState::handled_until): a boxer dropped by a strong drag of its
  // thigh, still upright and on its feet when let go, swung an arm to 34 m/s as it fell (the chaos soak's match).
  // Never the leg a balance step swings (it must move fast; limited, seed 2's step after a 400 N push from behind came
  // too late), and the rest of the body during a step only in the player's hands: dragged through a recovery's
  // steps, a boxer swung an arm to 30-31 m/s (the chaos soak's match, seeds 5 and 8, 200 s), while with no hands on it
  // the limit during a step cost pushes (Yin's five, seeds 1-48: 227 of 240 against 230; left 394 N seed 4 fell).
  // The arms alone, at that limit, cost the same seed 4; with a looser one (step_arm_strength) they keep it.
  const bool handled = d.time < b.ctl.handled_until;
  const bool losing_balance = unsupported || handled || up.z() < std::cos(tq.losing_balance_tilt);
  const eng::control::BalanceStep& step = b.ctl.balance_steps.step;
  const eng::control::LegBones* swing_leg = step.active ? &b.bones.leg[step.foot] : nullptr;
  for (int bone = 1; bone < int(b.bodies.body.size()); ++bone) {
    const eng::physics::Body& body = m.bodies[b.bodies.body[bone]];
    if (body.nv == 0) continue;
    auto t = d.tau.segment(body.v_index, body.nv);
    const double n = t.norm();
    if (n > tq.joint_torque_limit) t *= tq.joint_torque_limit / n;
    const bool swinging = swing_leg && (bone == swing_leg->thigh || bone == swing_leg->shank || bone == swing_leg->foot);
    const bool limited = losing_balance && !swinging && (!step.active || handled);
    const bool arm = q.arm[size_t(bone)] || q.arm[size_t(skel.parent[bone])];  // upper arm, forearm, glove
    if (limited)
      eng::control::limit_torque_by_speed(t, d.v.segment(body.v_index, body.nv), tq.speed_strength);
    else if (losing_balance && step.active && arm)
      eng::control::limit_torque_by_speed(t, d.v.segment(body.v_index, body.nv), tq.step_arm_strength);
  }
  b.ctl.root_torque = finite ? q.out.root_assist : Eigen::Vector3d::Zero();
}


}  // namespace boxing
