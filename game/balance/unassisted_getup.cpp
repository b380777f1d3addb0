// The unassisted get-up (unassisted_getup.h).
#include "game/balance/unassisted_getup.h"

#include <algorithm>
#include <cmath>

#include "engine/control/biped/support_polygon.h"
#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/world_pose.h"
#include "engine/physics/dynamics.h"
#include "game/balance/balance_controller.h"
#include "game/balance/com_support.h"
#include "game/balance/qp_balance.h"
#include "game/boxer.h"

namespace boxing {

namespace {

int bone_of(const Boxer& b, int body) {
  for (int i = 0; i < int(b.bodies.body.size()); ++i)
    if (b.bodies.body[i] == body) return i;
  return -1;
}

// The plan's contacts: the touching points (gap < BalanceQpTuning::touch_gap, last solve's contacts) of the links in
// this phase's support set; the next phase's support points gathered into q.pts (its gate). False: no link of the
// boxer touches the ground.
bool gather_support(QpBalance& q, BalanceTick& tick, const GetUpPlan& p, double mu) {
  const eng::physics::Model& m = tick.m;
  const eng::physics::Data& d = tick.d;
  const Boxer& b = tick.b;
  const int pelvis = b.bodies.body[0];
  const std::vector<uint8_t>& now = getup_supports(p);
  const std::vector<uint8_t>& next = getup_next_supports(p);
  q.pts.clear();
  bool on_ground = false;
  for (const auto& c : d.prev_contacts) {
    if ((c.body_a == 0) == (c.body_b == 0) || c.point.depth < -b.settings.tuning.qp.touch_gap) continue;
    const int body = c.body_a == 0 ? c.body_b : c.body_a;
    if (m.bodies[body].root != pelvis) continue;
    on_ground = true;
    const int bone = bone_of(b, body);
    if (bone < 0) continue;
    if (next[bone]) q.pts.push_back(c.point.position.head<2>());
    if (!now[bone] || int(q.in.contacts.size()) >= eng::control::kQpMaxContacts) continue;
    eng::control::QpContact qc;
    qc.body = body;
    qc.point = c.point.position;
    qc.normal = c.body_b == body ? c.point.normal : Eigen::Vector3d(-c.point.normal);
    qc.mu = mu;
    q.in.contacts.push_back(qc);
  }
  return on_ground;
}

}  // namespace

void end_unassisted_getup(QpBalance& q, BalanceTick& tick) {
  q.getup.active = false;
  tick.b.ctl.clip_rate = 1.0;
}

void actuate_unassisted_getup(QpBalance& q, BalanceTick& tick) {
  const eng::physics::Model& m = tick.m;
  eng::physics::Data& d = tick.d;
  Boxer& b = tick.b;
  const auto& skel = tick.desc.skeleton;
  const int n = skel.size();
  const GetUpPlanTuning& t = b.settings.tuning.stand_up.plan;
  GetUpPlan& p = q.getup;
  eng::control::BalanceQpInput& in = q.in;
  if (!p.active) {  // lying on the back: the chest's front (+X of the bone) looks up (getup_metrics.h lying_of)
    const int chest = skel.find("chest");
    getup_plan_start(p, (d.x[b.bodies.body[chest >= 0 ? chest : 0]].R * Eigen::Vector3d::UnitX()).z() > 0.0, skel);
  }
  b.ctl.root_force.setZero();  // never a force: the get-up is the body's
  if (!gather_support(q, tick, p, b.settings.tuning.qp.mu)) {
    b.ctl.root_torque.setZero();
    return;  // in the air (d.tau zeroed by the caller): limp
  }
  // The com: toward the clip's, its floor point kept over the next phase's support polygon (support_margin inside).
  eng::control::pose_fk(skel, b.desired.pose, b.scratch.fk_W, b.scratch.fk_P);
  const bool no_feet[2] = {false, false};
  const ComAndSupport cs = com_and_support(d, tick.desc, b, b.scratch.fk_W, b.scratch.fk_P, b.bones.foot, no_feet);
  GetUpMeasure me;
  me.com = cs.com_a.head<2>();
  me.next_points = int(q.pts.size());
  eng::control::convex_hull_2d_in_place(q.pts, q.hull);
  if (!p.have_offset) p.com_offset = cs.com_a - cs.com_d, p.have_offset = true;
  Eigen::Vector3d target = cs.com_d + p.com_offset;
  if (q.hull.size() >= 3) {
    me.next_inside = -eng::control::outside_distance(q.hull, me.com);
    target.head<2>() = eng::control::clamp_to_polygon(q.hull, target.head<2>(), t.support_margin);
  }
  me.com_error = (cs.com_a - target).norm();
  const double kp = t.com_omega * t.com_omega, kd = 2.0 * t.com_omega;
  in.com_acc = kp * (target - cs.com_a) - kd * cs.vcom;
  if (in.com_acc.norm() > t.max_com_acc) in.com_acc *= t.max_com_acc / in.com_acc.norm();
  const eng::physics::Vec6 h = eng::physics::spatial_momentum(m, d, b.bodies.body[0]);
  in.momentum_rate = -t.momentum_damping * (h.head<3>() - cs.com_a.cross(h.tail<3>()));
  if (in.momentum_rate.norm() > t.max_momentum_rate) in.momentum_rate *= t.max_momentum_rate / in.momentum_rate.norm();
  // Every bone toward the clip: eq. 3 as an acceleration, weighted by its servo inertia (qp_balance.cpp add_bone_tasks).
  const double wn = b.settings.gains.omega_n * b.ctl.gain_scale, bkp = wn * wn, bkd = 2.0 * b.settings.gains.zeta * wn;
  for (int i = 0; i < n; ++i) {
    eng::control::QpAngularTask a;
    a.body = b.bodies.body[i];
    a.alpha = bkp * eng::control::orientation_error(b.ctl.servo.W_d[i], b.scratch.W_a[i]) +
              bkd * (b.ctl.servo.omega_d[i] - b.scratch.omega_a[i]);
    a.weight = b.control_body.I_eff[i];
    in.angular.push_back(a);
  }
  // The prices: the com and momentum tasks com_weight times the standing plan's (as Kudoh's priorities in the fight:
  // at 1 the bone tasks outweigh them and the body tracks the clip's limbs lying where it is), the root assist a
  // torque at most max_root_torque, joint torques priced (bounded internal forces).
  eng::control::BalanceQpParams& params = q.solve_params;
  params = q.params;
  params.w_root_assist = t.root_price;
  params.max_root_assist = t.max_root_torque;
  params.w_torque = t.torque_price;
  params.w_limit = 0.0;
  params.w_force *= t.com_weight, params.w_moment *= t.com_weight;
  eng::control::balance_qp_solve(m, d, in, params, q.ws, q.out);
  const bool finite = q.out.tau.allFinite();
  for (int k = 0; k < in.dof_end - in.dof_begin; ++k) d.tau[in.dof_begin + k] = finite ? q.out.tau[k] : 0.0;
  // A person's strength: each joint's torque (a ball joint's as a vector) within person_strength.h's.
  for (int bone = 1; bone < n; ++bone) {
    const eng::physics::Body& body = m.bodies[b.bodies.body[bone]];
    if (body.nv == 0 || p.strength[bone] <= 0.0) continue;
    auto tau = d.tau.segment(body.v_index, body.nv);
    const double norm = tau.norm();
    if (norm > p.strength[bone]) tau *= p.strength[bone] / norm;
  }
  b.ctl.root_torque = finite ? q.out.root_assist : Eigen::Vector3d::Zero();
  b.ctl.clip_rate = getup_plan_advance(p, t, me, tick.dt);
}

}  // namespace boxing
