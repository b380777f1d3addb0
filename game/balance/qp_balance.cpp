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
#include "game/balance/unassisted_getup.h"
#include "game/boxer.h"
#include "game/footwork.h"

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
// comes within leg_clearance of a right-leg one: the two points' relative acceleration along their normal at
// omega^2 (leg_clearance + depth) - 2 omega v_n (none where that is negative: already parting fast enough). The shanks
// and feet do not collide with each other; the thighs do (set_self_colliding). A soft task, not a collision: the plan
// keeps the legs apart where the balance allows, so a capture step can still cross the stance leg
// (docs/decisions/balance-steps.md).
void add_leg_clearance(QpBalance& q, const eng::physics::Model& m, const eng::physics::Data& d, const Boxer& b) {
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const double weight = tq.leg_clearance_weight, gap = tq.leg_clearance, omega = tq.leg_clearance_omega;
  if (q.leg_geoms[0].empty()) list_leg_geoms(b, q.leg_geoms);
  if (weight <= 0.0) return;
  // A capture step's swing may cross the stance leg: no clearance then. A footwork move's steps never cross (the foot
  // on the move's side goes first), so they keep it.
  if (!tq.leg_clearance_in_step && b.ctl.balance_steps.step.active && !b.ctl.balance_steps.step.returning &&
      !footwork_busy(b))
    return;
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

// What one tick's stages hand on to the next (plain values: the task lists live in QpBalance::in, the poses in
// Boxer::scratch, so a tick allocates nothing).
struct QpStep {
  bool touching[2] = {false, false};  // a planted foot that touches its crate: held through its contact points
  bool first_tick = false;            // no solved contacts yet (d.prev_contacts is empty, the body is not in the air)
  ComAndSupport cs;                   // the com and the support centres, actual and desired
  Eigen::Vector3d up = Eigen::Vector3d::Zero();  // the pelvis's up axis against where the pose wants it
  bool kudoh = false;        // Kudoh's priorities on (BalanceQpTuning::trunk_weight, com_weight)
  bool unsupported = false;  // too few contact points to carry the com and momentum tasks: those priced down
  bool finite = true;        // the solve's torques are finite
};

// The bones' servo gains (eq. 3): natural frequency, stiffness and damping, scaled with consciousness.
struct ServoGains {
  double wn, kp, kd;
};
ServoGains servo_gains(const Boxer& b) {
  const double wn = b.settings.gains.omega_n * b.ctl.gain_scale, kp = wn * wn, kd = 2.0 * b.settings.gains.zeta * wn;
  return {wn, kp, kd};
}

// Stage 1: the root assist's limit for this tick, and the input emptied and set to the boxer's DoF block.
void begin_input(QpBalance& q, BalanceTick& tick) {
  const eng::physics::Model& m = tick.m;
  Boxer& b = tick.b;
  // The root spring is the QP's root assist: "lowers its motor gains when knocked out" (paper Fig. 7), the assist's
  // limit scales with consciousness.
  b.ctl.root_spring.update(b.settings.root_params, tick.dt);
  q.params.max_root_assist = root_assist_limit(b);  // (0 without a root spring: no assist planned, as w_root_assist = 0)
  const int pelvis = b.bodies.body[0];
  eng::control::BalanceQpInput& in = q.in;
  in.clear();
  in.root_body = pelvis;
  in.dof_begin = m.bodies[pelvis].v_index;
  in.dof_end = in.dof_begin;
  for (size_t i = 1; i < m.bodies.size(); ++i)
    if (m.bodies[i].root == pelvis) in.dof_end = std::max(in.dof_end, m.bodies[i].v_index + m.bodies[i].nv);
}

// Stage 2, the mode: true where the plan is off this tick. DOWN: the QP plans a body standing on its feet, and its
// torques on a lying one (links pressed on the ground) make the limbs flail and the simulation diverge; a fallen
// boxer goes limp (the passive joint damping stays). GettingUp: the stand-up's explicit servo torques and root assist
// (stand_up.h), on the ground only; lifted off it (a strong drag, a crate) those diverge as the plan's do in the air,
// so there it is limp too.
bool down_or_getting_up(QpBalance& q, BalanceTick& tick) {
  const eng::physics::Model& m = tick.m;
  eng::physics::Data& d = tick.d;
  Boxer& b = tick.b;
  const eng::control::BalanceQpInput& in = q.in;
  if (b.ctl.state.fallen()) {
    for (int k = in.dof_begin; k < in.dof_end; ++k) d.tau[k] = 0.0;
    return true;
  }
  if (b.ctl.state.state != BoxerState::GettingUp) return false;
  for (int k = in.dof_begin; k < in.dof_end; ++k) d.tau[k] = 0.0;
  if (b.settings.tuning.stand_up.unassisted) {  // --getup unassisted: the QP with the get-up plan's supports
    actuate_unassisted_getup(q, tick);
    return true;
  }
  const int pelvis = b.bodies.body[0];
  bool on_ground = false;  // a link of this boxer touching the crates or the floor (last solve's contacts)
  for (const auto& c : d.prev_contacts) {
    if ((c.body_a == 0) == (c.body_b == 0) || c.point.depth < -b.settings.tuning.qp.touch_gap) continue;
    on_ground = on_ground || m.bodies[c.body_a == 0 ? c.body_b : c.body_a].root == pelvis;
  }
  if (on_ground) actuate_stand_up(tick, b.settings.tuning.stand_up);
  else b.ctl.root_torque.setZero(), b.ctl.root_force.setZero();
  return true;
}

// Stage 3: the plan's contacts, the touching points (gap < BalanceQpTuning::touch_gap) with the crates and the floor
// from the last solve (the ones FootContacts was sensed from; after step1, d.prev_contacts: this step's contacts are
// found but not solved yet), of the feet the clip plants and of any other link (a knee, a hand: left out, the plan
// would take that link for free and push it into the crate). A planted foot is held only while it touches
// (FootContacts::on_ground); one that hovers a little above its crate is lowered onto it (add_swing_foot_task).
void gather_contacts(QpBalance& q, BalanceTick& tick, QpStep& s) {
  const eng::physics::Model& m = tick.m;
  const eng::physics::Data& d = tick.d;
  const Boxer& b = tick.b;
  const bool* loaded = tick.loaded;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const int pelvis = b.bodies.body[0];
  const int* feet = b.bones.foot;
  s.touching[0] = loaded[0] && b.ctl.contacts.on_ground[0];
  s.touching[1] = loaded[1] && b.ctl.contacts.on_ground[1];
  for (const auto& c : d.prev_contacts) {
    if (c.point.depth < -tq.touch_gap) continue;  // speculative, not touching
    if (c.body_a != 0 && c.body_b != 0) continue;  // only the crates and floor (static) carry the body
    const int body = c.body_a == 0 ? c.body_b : c.body_a;
    if (m.bodies[body].root != pelvis) continue;
    int foot = -1;
    for (int k = 0; k < 2; ++k)
      if (body == b.bodies.body[feet[k]]) foot = k;
    if (foot >= 0 && !loaded[foot]) continue;  // a swing foot brushing the crate carries nothing
    eng::control::QpContact qc;
    qc.body = body;
    qc.point = c.point.position;
    qc.normal = c.body_b == body ? c.point.normal : Eigen::Vector3d(-c.point.normal);
    qc.mu = tq.mu;
    q.in.contacts.push_back(qc);
  }
  s.first_tick = q.ticks++ == 0;
}

// Stage 3, the mode again: true where the body is in the air (thrown, yanked up by the player's strong drag). With no
// ground the plan's com, momentum and foot tasks cannot be met and it chases them with the limbs; the servo's own
// torques diverge too (the legs' gains are sized for moving the body over a planted foot). So the body hangs on its
// passive joint damping, as when fallen, until a foot or a link touches the ground again.
bool airborne(QpBalance& q, BalanceTick& tick, const QpStep& s) {
  const eng::control::BalanceQpInput& in = q.in;
  if (!in.contacts.empty() || s.touching[0] || s.touching[1] || s.first_tick) return false;
  for (int k = in.dof_begin; k < in.dof_end; ++k) tick.d.tau[k] = 0.0;
  tick.b.ctl.root_torque.setZero();
  return true;
}

// The clip's com over its feet (desired com - desired support centre; zero with no foot planted), and its velocity
// v_d, differenced tick to tick: not across a change of the planted feet (the support centre jumps), at most
// BalanceQpTuning::max_com_speed.
Eigen::Vector3d desired_com_motion(QpBalance& q, BalanceTick& tick, const ComAndSupport& cs, Eigen::Vector3d& v_d) {
  const bool* loaded = tick.loaded;
  const BalanceQpTuning& tq = tick.b.settings.tuning.qp;
  Eigen::Vector3d rel_d = cs.com_d - cs.centre_d;
  if (cs.feet == 0) rel_d.setZero();
  const int support_set = (loaded[0] ? 1 : 0) | (loaded[1] ? 2 : 0);
  v_d = Eigen::Vector3d::Zero();
  if (q.have_com_d && support_set == q.support_set) v_d = (rel_d - q.com_d_rel_last) / tick.dt;
  if (v_d.norm() > tq.max_com_speed) v_d *= tq.max_com_speed / v_d.norm();
  q.com_d_rel_last = rel_d;
  q.support_set = support_set;
  q.have_com_d = true;
  return rel_d;
}

// A step held for its weight shift (gate_lift_off): the com target clamped into the other foot's contacts
// (BalanceQpTuning::shift_margin inside). The return step's shift (take_balance_steps) goes over that foot's middle,
// as the lift waits for the capture point well inside it (BalanceStepTuning::return_shift_margin, where shift_margin
// inside the hull is only 1 cm inside its side), moving there at return_shift_speed. True while that shift is under way.
bool shift_weight(QpBalance& q, BalanceTick& tick, const QpStep& s, Eigen::Vector2d& target) {
  const Boxer& b = tick.b;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const eng::control::BalanceQpInput& in = q.in;
  bool return_shift = false;
  for (int k = 0; k < 2; ++k) {
    if (!b.ctl.gate[k].holding) continue;
    const int other = b.bodies.body[b.bones.foot[1 - k]];
    q.pts.clear();
    for (const auto& c : in.contacts)
      if (c.body == other) q.pts.push_back(c.point.head<2>());
    if (q.pts.empty()) continue;
    eng::control::convex_hull_2d_in_place(q.pts, q.hull);
    target = eng::control::clamp_to_polygon(q.hull, target, tq.shift_margin);
    if (b.ctl.balance_steps.shifting == k) {
      contact_centre(in.contacts, other, target);
      if (!q.return_shift) q.return_shift_target = s.cs.com_a.head<2>();
      const Eigen::Vector2d to = target - q.return_shift_target;
      // A footwork step's shift (its own swing time set) is a boxer's quick unweighting, not the recovery's careful one.
      const bool quick = b.ctl.balance_steps.return_duration > 0.0;
      const double most = (quick ? b.settings.tuning.footwork.shift_speed : tq.return_shift_speed) * tick.dt;
      q.return_shift_target += to.norm() > most ? Eigen::Vector2d(to * (most / to.norm())) : to;
      target = q.return_shift_target;
      return_shift = true;
    }
  }
  return return_shift;
}

// The com target's floor position from the support: the clip's (com_a - e) clamped into the support polygon of the
// touching contacts, BalanceQpTuning::support_margin inside (a target the ground reaction cannot reach, after a step
// that landed short, is not chased over the edge), then over a weight shift's stance foot (shift_weight). In a return
// step's swing it sits over the stance foot's middle with no clip velocity fed forward (v_d zeroed: differenced from
// a desired pose whose foot the step swings, it runs the com off the stance foot's side); after the touch-down it comes
// back to the clip's slowly (settle_after_return; set there at once, the com runs on past the front foot).
Eigen::Vector2d support_target(QpBalance& q, BalanceTick& tick, const QpStep& s, const Eigen::Vector3d& e,
                               Eigen::Vector3d& v_d) {
  const Boxer& b = tick.b;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const eng::control::BalanceQpInput& in = q.in;
  const Eigen::Vector3d& com_a = s.cs.com_a;
  q.pts.clear();
  for (const auto& c : in.contacts) q.pts.push_back(c.point.head<2>());
  eng::control::convex_hull_2d_in_place(q.pts, q.hull);
  q.ground_hull = q.hull;  // (kept whole for com_acc_in_support: a weight shift narrows q.hull to one foot)
  Eigen::Vector2d target = eng::control::clamp_to_polygon(q.hull, com_a.head<2>() - e.head<2>(), tq.support_margin);
  const bool return_shift = shift_weight(q, tick, s, target);
  q.return_shift = return_shift;
  const eng::control::BalanceStep& step = b.ctl.balance_steps.step;
  // A footwork step (quick) keeps the clip's target, the anchored desired body between the feet: the com travels
  // with the step (clamped into the stance foot's sole while it swings), as a boxer's does.
  const bool held = step.active && step.returning && !step.quick;
  if (held) {
    contact_centre(in.contacts, b.bodies.body[b.bones.foot[1 - step.foot]], target);
    v_d.setZero();
  }
  // A footwork step's swing, once the foot is up (FootworkTuning::goal_after): the com aims at the move's end (the
  // feet's middle there) instead of staying over the stance foot, so it arrives moving the move's way and the next
  // foot can lift at once (held over the stance foot, it had to travel the whole stride from rest after each
  // landing: 1.5-2.5 s a move, and a move back went forward; tests/game/footwork_test.cpp).
  if (step.active && step.quick && footwork_busy(b) &&
      step.elapsed > b.settings.tuning.footwork.goal_after * step.duration) {
    target = b.ctl.footwork.goal;
    v_d.setZero();
  }
  const bool quick_shift = return_shift && b.ctl.balance_steps.return_duration > 0.0;
  if (quick_shift || (step.active && step.quick)) tick.b.ctl.balance_steps.settling = false;
  settle_after_return(tick.b.ctl.balance_steps, (return_shift && !quick_shift) || held,
                      step.active && !step.returning, tq.return_shift_speed, tq.return_settle_time, tick.dt, target, v_d);
  return target;
}

// The com acceleration as a PD target (Kudoh's thesis sec. 2.5.1) on the error e, with v_d fed forward, at most
// BalanceQpTuning::max_com_acc. Then only the part of it the soles can give (com_acc_in_support): only with a root
// assist to buy the rest, and not while the player's hands hold or push the body (their force moves the com too: the
// soles' centre of pressure no longer bounds its acceleration).
void com_pd(QpBalance& q, BalanceTick& tick, const QpStep& s, const Eigen::Vector3d& e, const Eigen::Vector3d& v_d) {
  const eng::physics::Data& d = tick.d;
  const BalanceQpTuning& tq = tick.b.settings.tuning.qp;
  eng::control::BalanceQpInput& in = q.in;
  const Eigen::Vector3d &com_a = s.cs.com_a, &vcom = s.cs.vcom;
  const double kp = tq.com_omega * tq.com_omega, kd = 2.0 * tq.com_omega;
  in.com_acc = -kp * e - kd * (vcom - v_d);
  if (in.com_acc.norm() > tq.max_com_acc) in.com_acc *= tq.max_com_acc / in.com_acc.norm();
  if (tq.com_acc_in_support && q.params.max_root_assist > 0.0 && in.contacts.size() >= 3 && d.time >= tick.b.ctl.handled_until) {
    double floor_z = 0.0;
    for (const auto& c : in.contacts) floor_z += c.point.z();
    floor_z /= double(in.contacts.size());  // (the tops under the feet differ by centimetres: small against the com's metre)
    in.com_acc = eng::control::ground_com_acceleration(q.ground_hull, com_a, in.com_acc, com_a.z() - floor_z, tq.cop_margin,
                                                       tq.cop_ramp);
  }
}

// A balance step's landing below the swing leg's reach (a return step's too, sent down to the floor between two
// crates): the com's height task aims that much lower, so the stance knee bends and the foot gets down
// (BalanceStepTuning::reach_share).
void come_down_to_landing(QpBalance& q, BalanceTick& tick, const QpStep& s) {
  const eng::physics::Data& d = tick.d;
  const Boxer& b = tick.b;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const eng::control::BalanceStep& bs = b.ctl.balance_steps.step;
  const eng::control::BalanceStepTuning& ts = b.settings.tuning.balance_step;
  const double kp = tq.com_omega * tq.com_omega, kd = 2.0 * tq.com_omega;
  const eng::control::LegBones& leg = b.bones.leg[bs.foot];
  const Eigen::Vector3d &hip = d.x[b.bodies.body[leg.thigh]].p, &knee = d.x[b.bodies.body[leg.shank]].p,
                        &ankle = d.x[b.bodies.body[leg.foot]].p;
  const Eigen::Vector3d land = Eigen::Vector3d(bs.to.x(), bs.to.y(), bs.to_top) -
                               Eigen::AngleAxisd(bs.yaw, Eigen::Vector3d::UnitZ()) * b.settings.tuning.foot.sole_offset();
  const double drop = eng::control::step_reach_drop(hip, land, (knee - hip).norm() + (ankle - knee).norm(),
                                                    ts.reach_share, ts.reach_max_drop);
  if (drop > 0.0) q.in.com_acc.z() = std::min(q.in.com_acc.z(), std::max(-tq.max_com_acc, -kp * drop - kd * s.cs.vcom.z()));
}

// A quick step's swing (lift_off_gate.h: capturable once the foot lands) and a balance step's (balance_step.h: placed
// where the capture point will be at touch-down): the com falls toward the landing foot as the linear inverted
// pendulum does about the stance's pivot nearest the capture point xi, com'' = omega^2 (com - p) (Pratt et al. 2006),
// the model the landing was placed with; held over the stance foot instead, the plan asks the ground for what it
// cannot give (docs/decisions/balance-steps.md). A carried step (StepTuning::carry) counts while it is no longer than
// the quick step's longest (a longer one, slowed to rise onto a higher crate, falls long enough for the capture point
// to run off, so its com target stays over the stance foot). With a root assist a balance step's pivot goes on past the stance's edge toward xi by the
// assist's reach, tau / (m g) (the centroidal moment pivot, Popovic, Goswami & Herr 2005), so the plan slows the fall
// with the assist as it does standing; not a clip's quick step, which would buy its fall from the assist.
void fall_in_swing(QpBalance& q, BalanceTick& tick, const QpStep& s) {
  const eng::physics::Model& m = tick.m;
  const Boxer& b = tick.b;
  const bool* loaded = tick.loaded;
  const eng::control::BalanceQpInput& in = q.in;
  const Eigen::Vector3d &com_a = s.cs.com_a, &vcom = s.cs.vcom;
  const eng::control::BalanceStep& bs = b.ctl.balance_steps.step;
  const eng::control::BalanceStepTuning& ts = b.settings.tuning.balance_step;
  for (int k = 0; k < 2; ++k) {
    const eng::control::StepPlan& plan = b.ctl.step[k];
    const bool carried = plan.active && plan.carried && plan.duration <= b.settings.tuning.gate.quick_max_swing;
    const bool quick_swing = ((b.ctl.gate[k].lifted && b.ctl.gate[k].quick) || carried) && !loaded[k];
    const bool balance_swing = bs.active && !bs.returning && bs.foot == k;
    if (!(quick_swing || balance_swing) || in.contacts.empty()) continue;
    const double omega = eng::control::lip_omega(std::max(0.3, com_a.z() - b.ctl.support_base));
    const Eigen::Vector2d xi = com_a.head<2>() + vcom.head<2>() / omega;
    Eigen::Vector2d p = eng::control::clamp_to_polygon(q.hull, xi, 0.0);
    const double beyond = (xi - p).norm(), reach = balance_swing ? assist_reach(m, b) : 0.0;
    p += beyond > reach ? Eigen::Vector2d((xi - p) * (reach / beyond)) : Eigen::Vector2d(xi - p);
    q.in.com_acc.head<2>() = omega * omega * (com_a.head<2>() - p);
    if (balance_swing && ts.reach_share > 0.0) come_down_to_landing(q, tick, s);
  }
  if (bs.active && bs.returning && ts.reach_share > 0.0 && !in.contacts.empty()) come_down_to_landing(q, tick, s);
}

// The angular momentum about the com damped toward zero (BalanceQpTuning::momentum_damping), at most max_momentum_rate.
void damp_momentum(QpBalance& q, BalanceTick& tick, const QpStep& s) {
  namespace ph = eng::physics;
  const BalanceQpTuning& tq = tick.b.settings.tuning.qp;
  eng::control::BalanceQpInput& in = q.in;
  const ph::Vec6 h = ph::spatial_momentum(tick.m, tick.d, tick.b.bodies.body[0]);
  const Eigen::Vector3d k_com = h.head<3>() - s.cs.com_a.cross(h.tail<3>());
  in.momentum_rate = -tq.momentum_damping * k_com;
  if (in.momentum_rate.norm() > tq.max_momentum_rate) in.momentum_rate *= tq.max_momentum_rate / in.momentum_rate.norm();
}

// Stage 4: the com and momentum targets. The com is measured against the support: PD toward the desired pose's com
// over its feet, put on the actual feet centre, its height the pose's (com_pd), the floor target kept in the support
// (support_target); in a step's swing it falls as the LIP (fall_in_swing). With no foot planted there is nothing to
// plan with: the com falls (com_acc = g).
void com_target(QpBalance& q, BalanceTick& tick, QpStep& s) {
  Boxer& b = tick.b;
  // Desired pose FK (after anchoring / leg fitting): com and feet.
  pose_fk(tick.desc.skeleton, b.desired.pose, b.scratch.fk_W, b.scratch.fk_P);
  s.cs = com_and_support(tick.d, tick.desc, b, b.scratch.fk_W, b.scratch.fk_P, b.bones.foot, tick.loaded);
  Eigen::Vector3d v_d;
  const Eigen::Vector3d rel_d = desired_com_motion(q, tick, s.cs, v_d);
  if (s.cs.feet == 0) {
    q.in.com_acc = tick.m.gravity;
    return;
  }
  const Eigen::Vector3d &com_a = s.cs.com_a, &com_d = s.cs.com_d;
  Eigen::Vector3d e = (com_a - s.cs.centre_a) - rel_d;
  e.z() = com_a.z() - com_d.z();
  if (!q.in.contacts.empty()) {
    const Eigen::Vector2d target = support_target(q, tick, s, e, v_d);
    e.head<2>() = com_a.head<2>() - target;
  }
  com_pd(q, tick, s, e, v_d);
  fall_in_swing(q, tick, s);
  damp_momentum(q, tick, s);
}

// Kudoh's priorities (BalanceQpTuning::trunk_weight, com_weight) only while the boxer stands on its support in guard:
// not in the player's hands (BoxerControlState::handled_until), not in a balance step (its swing needs the com task low
// and the trunk free to lean), not on fewer than min_support_contacts points or tilted past losing_balance_tilt (held
// to a posture and a com the ground cannot give, the plan whips the arms), and not stunned (the bone tasks' weaker
// gains let the com task outweigh them and swing the arms). docs/decisions/match-fight.md.
void kudoh_priorities(QpBalance& q, BalanceTick& tick, QpStep& s) {
  const eng::physics::Data& d = tick.d;
  const Boxer& b = tick.b;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const int pelvis = b.bodies.body[0];
  s.up = d.x[pelvis].R * (b.ctl.servo.W_d[0].toRotationMatrix().transpose() * Eigen::Vector3d::UnitZ());
  s.kudoh = !b.ctl.balance_steps.step.active && d.time >= b.ctl.handled_until &&
            (s.first_tick || int(q.in.contacts.size()) >= tq.min_support_contacts) &&
            s.up.z() >= std::cos(tq.losing_balance_tilt) && b.ctl.state.state == BoxerState::Guard;
}

// Every bone's orientation task: eq. 3 as an acceleration, alpha = omega_n^2 Delta(W_d, W_a) + 2 zeta omega_n
// (omega_d - omega_a), weighted by the bone's servo inertia (heavy subtrees matter most, as eq. 3's gains scale with
// them); the trunk's priced up under Kudoh's priorities. A punch's striking arm (upper arm, forearm, glove) can be
// driven harder while the punch is aimed (PunchAim::arm_gain). The arms' return (BalanceQpTuning::arm_return_*), under
// Kudoh's priorities once the com has been slow a while: an arm off its pose tracks a target arm_return_step ahead.
void add_bone_tasks(QpBalance& q, BalanceTick& tick, const QpStep& s, const ServoGains& g) {
  const eng::physics::Data& d = tick.d;
  const auto& skel = tick.desc.skeleton;
  const Boxer& b = tick.b;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const int n = skel.size();
  const double kp = g.kp, kd = g.kd;
  const PunchAim& aim = b.ctl.aim;
  const int aim_forearm = aim.active && aim.glove > 0 ? skel.parent[aim.glove] : -1;
  const int aim_upper = aim_forearm > 0 ? skel.parent[aim_forearm] : -1;
  const double trunk_price = s.kudoh ? tq.trunk_weight : 1.0;
  if (s.cs.vcom.head<2>().norm() < tq.arm_return_com_speed) {
    if (q.slow_since < 0.0) q.slow_since = d.time;
  } else {
    q.slow_since = -1.0;
  }
  const bool arms_return = s.kudoh && tq.arm_return_weight > 0.0 && q.slow_since >= 0.0 && d.time - q.slow_since >= tq.arm_return_after;
  for (int i = 0; i < n; ++i) {
    eng::control::QpAngularTask t;
    t.body = b.bodies.body[i];
    const bool arm = aim.arm_gain != 1.0 && (i == aim.glove || i == aim_forearm || i == aim_upper) && aim.active;
    const double ga = arm ? aim.arm_gain : 1.0;
    const Eigen::Vector3d e = eng::control::orientation_error(b.ctl.servo.W_d[i], b.scratch.W_a[i]);
    t.alpha = ga * ga * kp * e + ga * kd * (b.ctl.servo.omega_d[i] - b.scratch.omega_a[i]);
    t.weight = b.control_body.I_eff[i] * (arm ? ga * ga : 1.0) * (q.trunk.size() > size_t(i) && q.trunk[i] ? trunk_price : 1.0);
    if (arms_return && !arm && q.arm.size() > size_t(i) && q.arm[i] && e.norm() > tq.arm_return_step) {
      t.alpha = kp * (tq.arm_return_step / e.norm()) * e + kd * (b.ctl.servo.omega_d[i] - b.scratch.omega_a[i]);
      t.weight *= tq.arm_return_weight;
    }
    q.in.angular.push_back(t);
  }
}

// The punch's strike: the glove's centre driven along a velocity field into the target (PunchAim::strike).
void add_strike_task(QpBalance& q, BalanceTick& tick) {
  const eng::physics::Data& d = tick.d;
  const eng::assets::CharacterDesc& desc = tick.desc;
  const Boxer& b = tick.b;
  const PunchAim& aim = b.ctl.aim;
  const int aim_forearm = aim.active && aim.glove > 0 ? desc.skeleton.parent[aim.glove] : -1;
  const int aim_upper = aim_forearm > 0 ? desc.skeleton.parent[aim_forearm] : -1;
  if (!(aim.active && aim.strike > 0.0 && aim.strike_speed > 0.0 && aim_upper > 0)) return;
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
  q.in.points.push_back(t);
}

// A touching foot, held through its contact points (balance_qp.h): a strong orientation task rolls a foot standing on
// an edge or corner flat about it (the sole is the support). Its target keeps the clip's tilt of the foot but the
// foot's actual heading: the contacts have no torsional friction, so a planted foot is not twisted toward the clip's
// yaw (the body turns above it).
void hold_planted_foot(QpBalance& q, BalanceTick& tick, int k, const ServoGains& g) {
  const Boxer& b = tick.b;
  const int* feet = b.bones.foot;
  const Eigen::Quaterniond& Wd_foot = b.ctl.servo.W_d[feet[k]];
  const Eigen::Quaterniond target =
      eng::control::yaw_rotation(eng::control::heading_of(b.scratch.W_a[feet[k]]) - eng::control::heading_of(Wd_foot)) *
      Wd_foot;
  q.in.angular[feet[k]].alpha = g.kp * eng::control::orientation_error(target, b.scratch.W_a[feet[k]]) - g.kd * b.scratch.omega_a[feet[k]];
  q.in.angular[feet[k]].weight = b.settings.tuning.qp.planted_foot_weight;
}

// A foot not touching: its ankle PD toward a target. A planted-but-hovering foot aims BalanceQpTuning::land below where
// it is (it comes down onto the crate); a swing foot aims at its step's target (plan_steps: the clip's ankle moved onto
// a good foothold), with the target's velocity fed forward (PD alone lags a 1-2 m/s swing by ~2 zeta v / wn):
// differenced tick to tick, the height from the clip's own (the crate under the foot changes in jumps), zero on the
// tick the foot leaves the support; a balance or carried step's path rate and horizontal acceleration instead
// (swing_acc_feed_forward; a balance step's own swing: balance_step_acc_feed_forward). A balance step (balance_step.h)
// swings faster and is tracked more stiffly. A stepping foot is kept level as strongly as a planted one (weakly held,
// the leg lifts the ankle while the toe stays on the crate and the foot drags).
void add_swing_foot_task(QpBalance& q, BalanceTick& tick, int k, const ServoGains& g) {
  const eng::physics::Data& d = tick.d;
  const Boxer& b = tick.b;
  const bool* loaded = tick.loaded;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const int* feet = b.bones.foot;
  const int pelvis = b.bodies.body[0];
  const int fb = b.bodies.body[feet[k]];
  eng::control::QpPointTask t;
  t.body = fb;
  t.point = d.x[fb].p;
  const Eigen::Vector3d v = eng::physics::point_velocity(d, fb, t.point);
  const eng::control::StepPlan& step = b.ctl.step[k];
  const Eigen::Vector3d swing_target = step.active ? step.target : b.scratch.fk_P[feet[k]];
  const Eigen::Vector3d target = loaded[k] ? Eigen::Vector3d(t.point - Eigen::Vector3d(0, 0, tq.land)) : swing_target;
  const Eigen::Vector3d ff_point(swing_target.x(), swing_target.y(), step.active ? step.clip_z : swing_target.z());
  Eigen::Vector3d v_ff = Eigen::Vector3d::Zero();
  if (!loaded[k] && q.swing_prev[k]) v_ff = (ff_point - q.swing_target_prev[k]) / tick.dt;
  const bool quick = b.ctl.balance_steps.step.active && b.ctl.balance_steps.step.foot == k;
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
  const double sw = quick ? tq.balance_step_omega : g.wn, skp = sw * sw, skd = 2.0 * sw;
  t.acc = (quick ? skp : g.kp) * (target - t.point) + (quick ? skd : g.kd) * ((loaded[k] ? Eigen::Vector3d::Zero() : v_ff) - v);
  if (!loaded[k]) t.acc += a_ff;
  t.weight = tq.swing_weight * tick.desc.bones[feet[k]].mass;
  if (quick && tq.balance_step_relative) t.ref_body = pelvis, t.ref_point = d.x[pelvis].p;
  q.in.points.push_back(t);
  if (step.active) q.in.angular[feet[k]].weight = tq.planted_foot_weight;
}

// Stage 5: the tracking tasks: every bone, the punch's strike, the feet (held or swung), the legs kept apart.
void add_tasks(QpBalance& q, BalanceTick& tick, QpStep& s) {
  const ServoGains g = servo_gains(tick.b);
  kudoh_priorities(q, tick, s);
  add_bone_tasks(q, tick, s, g);
  add_strike_task(q, tick);
  for (int k = 0; k < 2; ++k) {
    if (s.touching[k]) hold_planted_foot(q, tick, k, g);
    else add_swing_foot_task(q, tick, k, g);
  }
  for (int k = 0; k < 2; ++k) q.swing_prev[k] = !tick.loaded[k] && !s.touching[k];
  add_leg_clearance(q, tick.m, tick.d, tick.b);
}

// Stage 6: this tick's prices (q.solve_params, from q.params).
//  * The feet's joint limits kept in the plan (BalanceQpParams::w_limit) while the boxer is calm: the step's stop at
//    a rear ankle's limit yanks the foot past its friction and walks it off its crate (docs/decisions/foot-slide.md).
//    Not in a push's recovery (the step's stops there are part of how the body catches itself), nor in the player's
//    hands.
//  * The com and momentum tasks: times com_weight under Kudoh's priorities; times balance_step_com_scale in a balance
//    step's swing (held to the stance foot's support they throw the upper body against the fall the step catches:
//    docs/decisions/balance-steps.md); times few_contacts_task_scale on too few contact points to carry them (no
//    support polygon: the plan mostly tracks the pose instead of swinging the arms for targets the ground cannot
//    give). Not during a balance step, whose stance foot often rolls onto an edge (priced down there, the plan asks
//    one corner for the body's weight and launches it); in a push's recovery one point under each foot still carries
//    the body (recovery_support_contacts).
void weigh_tasks(QpBalance& q, BalanceTick& tick, QpStep& s) {
  const eng::physics::Data& d = tick.d;
  const Boxer& b = tick.b;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  eng::control::BalanceQpInput& in = q.in;
  eng::control::BalanceQpParams& params = q.solve_params;
  params = q.params;
  for (int k = 0; k < 2; ++k) in.limit_bodies.push_back(b.bodies.body[b.bones.foot[k]]);
  const double calm = std::clamp(2.0 - s.cs.vcom.head<2>().norm() / tq.limit_calm_speed, 0.0, 1.0);
  const bool upset = b.ctl.balance_steps.recovering || b.ctl.balance_steps.step.active || d.time < b.ctl.handled_until;
  params.w_limit = upset ? 0.0 : tq.limit_weight * calm;
  if (s.kudoh) params.w_force *= tq.com_weight, params.w_moment *= tq.com_weight;
  if (b.ctl.balance_steps.step.active && !b.ctl.balance_steps.step.returning) {
    params.w_force *= tq.balance_step_com_scale;
    params.w_moment *= tq.balance_step_com_scale;
  }
  const int enough = b.ctl.balance_steps.recovering ? tq.recovery_support_contacts : tq.min_support_contacts;
  s.unsupported = int(in.contacts.size()) < enough && !s.first_tick && !b.ctl.balance_steps.step.active;
  if (s.unsupported) {
    params.w_force *= tq.few_contacts_task_scale;
    params.w_moment *= tq.few_contacts_task_scale;
  }
}

// Stage 7: the solve, its torques written to the boxer's DoFs (the root rows: the root assist's generalised force,
// zero when it is off). A non-finite solve (a guard) leaves the joints limp for the tick instead of poisoning the
// simulation. Its wall-clock cost is recorded for the report only (boxers[i].qp.solve_us_median / p95).
void solve(QpBalance& q, BalanceTick& tick, QpStep& s) {
  eng::physics::Data& d = tick.d;
  const eng::control::BalanceQpInput& in = q.in;
  const auto t0 = std::chrono::steady_clock::now();
  eng::control::balance_qp_solve(tick.m, d, in, q.solve_params, q.ws, q.out);
  q.solve_us.record(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
  s.finite = q.out.tau.allFinite();
  for (int k = 0; k < in.dof_end - in.dof_begin; ++k) d.tau[in.dof_begin + k] = s.finite ? q.out.tau[k] : 0.0;
}

// Stage 8: strength. Each joint's torque within BalanceQpTuning::joint_torque_limit (a ball joint's as a vector), a
// guard. While the boxer is losing its balance (too few contacts, the pelvis tilted past losing_balance_tilt from where
// the pose wants it, or in the player's hands) the torque-velocity limit too (speed_strength): there the plan, short of
// the ground reaction its targets need, spins the arms as reaction wheels; standing it stays off, as punches and blocks
// move the elbows fast (docs/decisions/joint-speed.md). Never on the leg a balance step swings (it must move fast), and
// on the rest of the body during a step only in the player's hands; the arms then get the looser step_arm_strength.
void apply_limits(QpBalance& q, BalanceTick& tick, const QpStep& s) {
  const eng::physics::Model& m = tick.m;
  eng::physics::Data& d = tick.d;
  Boxer& b = tick.b;
  const auto& skel = tick.desc.skeleton;
  const BalanceQpTuning& tq = b.settings.tuning.qp;
  const bool handled = d.time < b.ctl.handled_until;
  const bool losing_balance = s.unsupported || handled || s.up.z() < std::cos(tq.losing_balance_tilt);
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
  b.ctl.root_torque = s.finite ? q.out.root_assist : Eigen::Vector3d::Zero();
}
}  // namespace

// The balance QP's inputs for one boxer (balance_qp.h), solved, and its joint torques written to d.tau, in stages:
// the mode (limp when down or in the air, the stand-up's torques when getting up), the contacts, the com and momentum
// targets, the tracking tasks, their prices, the solve, the joints' strength. Tuning: BalanceQpTuning (qp_balance.h);
// measurements docs/decisions/balance-qp-tuning.md.
void actuate(QpBalance& q, BalanceTick& tick) {
  QpStep s;
  begin_input(q, tick);
  if (q.getup.active && tick.b.ctl.state.state != BoxerState::GettingUp) end_unassisted_getup(q, tick);
  if (down_or_getting_up(q, tick)) return;
  gather_contacts(q, tick, s);
  if (airborne(q, tick, s)) return;
  com_target(q, tick, s);
  add_tasks(q, tick, s);
  weigh_tasks(q, tick, s);
  solve(q, tick, s);
  apply_limits(q, tick, s);
}

}  // namespace boxing
