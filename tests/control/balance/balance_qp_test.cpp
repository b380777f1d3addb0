// Balance QP (engine/control/balance/balance_qp.h): static equilibrium against closed form and RNEA, the torques
// against an independent forward-dynamics algorithm (ABA), and the friction cones / centre of pressure when the
// request cannot be met.
#include "engine/control/balance/balance_qp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"
#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;
using eng::control::BalanceQp;
using eng::control::BalanceQpInput;
using eng::control::BalanceQpParams;
using eng::control::BalanceQpResult;

namespace {
// What balance_qp_solve reads: the kinematics of the current q, v and the step's first half's M and c there
// (physics::step1 builds the same, with contacts and rows).
void kinematics_and_dynamics(const Model& m, Data& d) {
  forward_kinematics(m, d);
  mass_matrix(m, d);
  compute_bias(m, d);
}

// A 10 kg box "torso" (free, 0.2 x 0.2 x 0.1 m) standing on the floor, with a 2 kg "arm" hinged about y at the
// middle of its top face, pointing along +x (com 0.2 m out). Contacts: the four bottom corners.
struct Stand {
  Model m;
  Data d;
  int torso = 0, arm = 0;
  BalanceQpInput in;
  // arm_upper: the hinge limited to [-2, arm_upper] (NaN: unlimited).
  explicit Stand(double arm_angle = 0.0, double arm_upper = std::nan("")) {
    const Vec3 he(0.1, 0.1, 0.05);
    torso = m.add_body(make_body("torso", 0, JointType::Free, at({0, 0, 0.05}), 10.0, Vec3::Zero(), box_inertia(10.0, he)));
    Body a = make_body("arm", torso, JointType::Hinge, at({0, 0, 0.05}), 2.0, Vec3(0.2, 0, 0), rod_inertia_z(2.0, 0.4));
    a.axis = Vec3::UnitY();
    if (!std::isnan(arm_upper)) a.limited = true, a.lower = -2.0, a.upper = arm_upper;
    arm = m.add_body(a);
    m.finalize();
    d = make_data(m);
    d.q[m.bodies[arm].q_index] = arm_angle;
    kinematics_and_dynamics(m, d);
    in.dof_begin = 0;
    in.dof_end = m.nv;
    in.root_body = torso;
    for (double x : {-0.1, 0.1})
      for (double y : {-0.1, 0.1}) {
        eng::control::QpContact c;
        c.body = torso;
        c.point = Vec3(x, y, 0.0);
        c.normal = Vec3::UnitZ();
        c.mu = 0.6;
        in.contacts.push_back(c);
      }
    for (int b : {torso, arm}) in.angular.push_back({b, Vec3::Zero(), 1.0});
  }
  double mass() const { return 12.0; }
};

// Independent check of a plan: forward dynamics (ABA, RBDA Table 7.1) of its torques (the root rows included: the
// root assist's generalised force, zero when off) plus J^T f of its planned contact forces.
VecX qacc_under_aba(Stand& s, const BalanceQpResult& out) {
  VecX tau = out.tau;
  MatX J;
  for (size_t c = 0; c < s.in.contacts.size(); ++c) {
    point_jacobian(s.m, s.d, s.in.contacts[c].body, s.in.contacts[c].point, J);
    tau += J.transpose() * out.contact_force[c];
  }
  VecX qacc(s.m.nv);
  aba(s.m, s.d, tau, qacc);
  return qacc;
}
}  // namespace

TEST(BalanceQp, StandingStillCarriesTheWeightAndTheHingeHoldsTheArmAgainstGravity) {
  Stand s;
  BalanceQp ws;
  BalanceQpResult out;
  eng::control::balance_qp_solve(s.m, s.d, s.in, BalanceQpParams{}, ws, out);
  const double g = 9.81;
  EXPECT_LT(out.root_residual, 1e-6);
  EXPECT_NEAR(out.force.z(), s.mass() * g, 1e-3 * s.mass() * g);
  EXPECT_NEAR(out.force.head<2>().norm(), 0.0, 1e-2);
  EXPECT_LT(out.qacc.cwiseAbs().maxCoeff(), 0.02);  // ~0 (the load-spreading ridge on the forces leaves a trace)
  // The arm's gravity torque about the hinge, m g l = 2 * 9.81 * 0.2, opposed by the joint (closed form) ...
  const int hinge = s.m.bodies[s.arm].v_index;
  EXPECT_NEAR(std::abs(out.tau[hinge]), 2.0 * g * 0.2, 1e-3);
  // ... and exactly RNEA's gravity compensation (qacc = 0, the contacts act on the torso only).
  VecX c(s.m.nv);
  bias_forces(s.m, s.d, c);
  EXPECT_NEAR(out.tau[hinge], c[hinge], 1e-3);
  // Centre of pressure under the com (x = 2 * 0.2 / 12).
  EXPECT_NEAR(out.cop.x(), 2.0 * 0.2 / 12.0, 1e-3);
  EXPECT_NEAR(out.cop.y(), 0.0, 1e-6);
}

TEST(BalanceQp, TorquesAndPlannedContactForcesReproduceTheQaccUnderAba) {
  Stand s(0.4);
  // A moving state and tasks the contacts cannot all satisfy.
  for (int k = 0; k < s.m.nv; ++k) s.d.v[k] = 0.1 * std::sin(1.0 + 2.3 * k);
  kinematics_and_dynamics(s.m, s.d);
  s.in.angular[1].alpha = Vec3(0, -8.0, 0);
  s.in.com_acc = Vec3(0.5, -0.3, 0.2);
  BalanceQp ws;
  BalanceQpResult out;
  eng::control::balance_qp_solve(s.m, s.d, s.in, BalanceQpParams{}, ws, out);
  // Independent check: forward dynamics of tau + J^T f gives back the planned qacc.
  const VecX qacc = qacc_under_aba(s, out);
  EXPECT_LT((qacc - out.qacc).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT(out.tau.head<6>().norm(), 1e-6);  // the floating base gets no torque
}

TEST(BalanceQp, AnImpossibleRequestKeepsEveryForceInItsConeAndTheCopInTheFoot) {
  Stand s;
  s.in.com_acc = Vec3(20.0, 0.0, 0.0);  // would need mu = 2 (and the held box cannot move anyway)
  s.in.momentum_rate = Vec3(0.0, 40.0, 0.0);  // would need the centre of pressure 0.34 m out, beyond the box
  BalanceQp ws;
  BalanceQpResult out;
  eng::control::balance_qp_solve(s.m, s.d, s.in, BalanceQpParams{}, ws, out);
  for (size_t c = 0; c < s.in.contacts.size(); ++c) {
    const Vec3& f = out.contact_force[c];
    EXPECT_GE(f.z(), -1e-9);
    EXPECT_LE(f.head<2>().norm(), 0.6 * f.z() + 1e-9);  // inside the cone (the plan uses its inner pyramid)
  }
  EXPECT_GT(out.moment.y(), 0.0);  // the asked moment, as far as the sole and friction allow
  EXPECT_LE(std::abs(out.cop.x()), 0.1 + 1e-9);
  EXPECT_LE(std::abs(out.cop.y()), 0.1 + 1e-9);
  EXPECT_LT(out.root_residual, 1e-6);
}

TEST(BalanceQp, BiasAccelerationsMatchFiniteDifferencesOfTheVelocity) {
  // Jdot v of a point on the arm: d/dt (J v) at qacc = 0, by a small explicit step of the kinematics.
  Stand s(0.3);
  for (int k = 0; k < s.m.nv; ++k) s.d.v[k] = 0.7 * std::cos(0.5 + 1.7 * k);
  kinematics_and_dynamics(s.m, s.d);
  const Vec3 local(0.35, 0.02, 0.01);
  auto point_and_velocity = [&](const Data& d, Vec3& p, Vec3& v, Vec3& w) {
    p = d.x[s.arm].apply(local);
    w = d.v_body[s.arm].head<3>();
    v = d.v_body[s.arm].tail<3>() + w.cross(p);
  };
  Vec3 p0, v0, w0;
  point_and_velocity(s.d, p0, v0, w0);
  const Vec3 a_bias = eng::control::bias_point_acceleration(s.m, s.d, s.arm, p0);
  const Vec3 alpha_bias = eng::control::bias_angular_acceleration(s.m, s.d, s.arm);
  // Advance q by v h (qacc = 0: v constant in joint space), then difference the world velocities.
  const double h = 1e-6;
  Data d2 = s.d;
  const Body& tb = s.m.bodies[s.torso];
  d2.q.segment<3>(tb.q_index) += h * s.d.v.segment<3>(tb.v_index);  // free joint: world linear velocity
  const Quat q0 = quat_from(s.d.q.data() + tb.q_index + 3);
  quat_store((q0 * quat_exp(h * s.d.v.segment<3>(tb.v_index + 3))).normalized(), d2.q.data() + tb.q_index + 3);
  d2.q[s.m.bodies[s.arm].q_index] += h * s.d.v[s.m.bodies[s.arm].v_index];
  kinematics_and_dynamics(s.m, d2);
  Vec3 p1, v1, w1;
  point_and_velocity(d2, p1, v1, w1);
  EXPECT_LT(((v1 - v0) / h - a_bias).norm(), 1e-4 * (1.0 + a_bias.norm()));
  EXPECT_LT(((w1 - w0) / h - alpha_bias).norm(), 1e-4 * (1.0 + alpha_bias.norm()));
}

TEST(BalanceQp, RootAssistHoldsAComOutsideTheSupportWithTheClosedFormTorqueAndWithinItsLimit) {
  // Only the two -x corners touch: the com (x = 2 * 0.2 / 12 = 0.033) is 0.133 m beyond the support line, so the
  // ground alone cannot hold the box up (it tips about the line).
  Stand s;
  s.in.contacts.erase(std::remove_if(s.in.contacts.begin(), s.in.contacts.end(),
                                     [](const eng::control::QpContact& c) { return c.point.x() > 0.0; }),
                      s.in.contacts.end());
  ASSERT_EQ(s.in.contacts.size(), 2u);
  BalanceQp ws;
  BalanceQpResult off, on, limited;
  eng::control::balance_qp_solve(s.m, s.d, s.in, BalanceQpParams{}, ws, off);
  BalanceQpParams p;
  p.w_root_assist = 1e-4;
  p.max_root_assist = 100.0;
  eng::control::balance_qp_solve(s.m, s.d, s.in, p, ws, on);
  const int pitch = 4;  // the free root's angular velocity about y (the torso's tipping)
  EXPECT_EQ(off.root_assist.norm(), 0.0);
  EXPECT_GT(std::abs(off.qacc[pitch]), 5.0);  // without help the box tips (gravity's moment 15.7 N m)
  // With the assist it stands: the torque is gravity's moment about the support line, m g 0.1333 (closed form), and
  // the box does not tip.
  const double g = 9.81, lever = 0.1 + 2.0 * 0.2 / 12.0;
  EXPECT_NEAR(on.root_assist.y(), -s.mass() * g * lever, 0.02 * s.mass() * g * lever);
  EXPECT_LT(std::abs(on.qacc[pitch]), 0.05 * std::abs(off.qacc[pitch]));
  EXPECT_FALSE(on.assist_clamped);
  // The torques, the contact forces and the assist (tau's root rows) reproduce qacc under ABA.
  const VecX qacc = qacc_under_aba(s, on);
  EXPECT_LT((qacc - on.qacc).cwiseAbs().maxCoeff(), 1e-8);
  // A limit below what holding it takes: the price rises until the plan fits the limit (to within the final clamp),
  // and the box tips, slower than without help.
  p.max_root_assist = 5.0;
  eng::control::balance_qp_solve(s.m, s.d, s.in, p, ws, limited);
  EXPECT_LE(limited.root_assist.norm(), 5.0 + 1e-9);
  EXPECT_GT(limited.root_assist.norm(), 4.0);
  EXPECT_GT(std::abs(limited.qacc[pitch]), std::abs(on.qacc[pitch]));
  EXPECT_LT(std::abs(limited.qacc[pitch]), std::abs(off.qacc[pitch]));
}

TEST(BalanceQp, PricedTorquesStillHoldTheArmAndMeetTheDynamics) {
  Stand s(0.4);
  for (int k = 0; k < s.m.nv; ++k) s.d.v[k] = 0.1 * std::sin(1.0 + 2.3 * k);
  kinematics_and_dynamics(s.m, s.d);
  BalanceQp ws;
  BalanceQpResult free_tau, priced;
  eng::control::balance_qp_solve(s.m, s.d, s.in, BalanceQpParams{}, ws, free_tau);
  BalanceQpParams p;
  p.w_torque = 1e-3;
  eng::control::balance_qp_solve(s.m, s.d, s.in, p, ws, priced);
  const VecX qacc = qacc_under_aba(s, priced);
  EXPECT_LT((qacc - priced.qacc).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT(priced.root_residual, 1e-6);
  // The hinge still holds the arm: the price (1e-3 per (N m)^2 on gravity's 3.6 N m) is nothing against the
  // tracking, so the hinge torque and acceleration barely move.
  const int hinge = s.m.bodies[s.arm].v_index;
  EXPECT_NEAR(priced.tau[hinge], free_tau.tau[hinge], 0.01 * std::abs(free_tau.tau[hinge]));
  EXPECT_NEAR(priced.qacc[hinge], free_tau.qacc[hinge], 0.01);
}

TEST(BalanceQp, ARelativePointTaskIsMetRelativeToItsReferenceWhileTheBaseRecoils) {
  // The box and its arm in the air (no contacts: momentum is conserved, the torso recoils from the arm) and one task:
  // the arm's tip accelerating relative to the hinge point on the torso (QpPointTask::ref_body). The plan's relative
  // acceleration, recomputed independently from the physics' point Jacobians, is the asked one; the tip's world
  // acceleration is not (the torso's recoil), which is what the relative task is for.
  Stand s(0.3);
  s.in.contacts.clear();
  s.in.angular.clear();
  s.in.com_acc = s.m.gravity;  // falling freely
  const Vec3 tip = s.d.x[s.arm].apply(Vec3(0.4, 0.0, 0.0)), hinge = s.d.x[s.torso].apply(Vec3(0.0, 0.0, 0.05));
  const Vec3 tangent = Vec3::UnitY().cross(tip - hinge).normalized();  // the way the hinge moves the tip
  eng::control::QpPointTask t;
  t.body = s.arm, t.point = tip, t.acc = -3.0 * tangent, t.weight = 100.0;
  t.ref_body = s.torso, t.ref_point = hinge;
  s.in.points.push_back(t);
  BalanceQp ws;
  BalanceQpResult out;
  eng::control::balance_qp_solve(s.m, s.d, s.in, BalanceQpParams{}, ws, out);
  MatX Jt, Jh;
  point_jacobian(s.m, s.d, s.arm, tip, Jt);
  point_jacobian(s.m, s.d, s.torso, hinge, Jh);
  const Vec3 a_tip = Jt * out.qacc + eng::control::bias_point_acceleration(s.m, s.d, s.arm, tip);
  const Vec3 a_hinge = Jh * out.qacc + eng::control::bias_point_acceleration(s.m, s.d, s.torso, hinge);
  EXPECT_NEAR((a_tip - a_hinge).dot(tangent), -3.0, 0.03);
  EXPECT_GT((a_hinge - s.m.gravity).norm(), 0.1) << "the torso recoils from the arm";
  EXPECT_GT(((a_tip - s.m.gravity) - t.acc).norm(), 0.1) << "so the tip's own acceleration is not the asked one";
  EXPECT_LT(out.root_residual, 1e-6);
}

TEST(BalanceQp, AJointNearItsLimitIsPlannedToStopShortOfItOnlyWhileItApproaches) {
  // The arm's hinge limited at 0.5 rad, the arm at 0.47 (C = 0.03, inside the default 0.05 margin), its task asking
  // 20 rad/s^2 further in. The step's limit rows (step1) tell the plan where the limits are. Approaching at 1 rad/s the
  // limit task asks C'' = kp (margin - C) - kd C' = 400 * 0.02 + 40 * 1 = 48 rad/s^2 back, priced 100 against the
  // arm's 1: the least-squares compromise is (20 - 100 * 48) / 101 = -47.3 rad/s^2 of hinge acceleration.
  auto hinge_acc = [](double qdot, double w_limit, bool arm_listed) {
    Stand s(0.47, 0.5);
    s.d.v[s.m.bodies[s.arm].v_index] = qdot;
    step1(s.m, s.d);
    s.in.angular[1].alpha = Vec3(0, 20.0, 0);
    if (!arm_listed) s.in.limit_bodies = {s.torso};
    BalanceQpParams p;
    p.w_limit = w_limit;
    BalanceQp ws;
    BalanceQpResult out;
    eng::control::balance_qp_solve(s.m, s.d, s.in, p, ws, out);
    EXPECT_LT(out.root_residual, 1e-6);
    return out.qacc[s.m.bodies[s.arm].v_index];
  };
  EXPECT_GT(hinge_acc(1.0, 0.0, true), 15.0) << "without the task the plan drives the arm into its stop";
  EXPECT_NEAR(hinge_acc(1.0, 100.0, true), (20.0 - 100.0 * 48.0) / 101.0, 1.0);
  // Moving off the limit (C' = +1: the task would ask 8 - 40 < 0): no task, the plan as without it.
  EXPECT_NEAR(hinge_acc(-1.0, 100.0, true), hinge_acc(-1.0, 0.0, true), 1e-9);
  // A body not in BalanceQpInput::limit_bodies: its limits are not the plan's.
  EXPECT_NEAR(hinge_acc(1.0, 100.0, false), hinge_acc(1.0, 0.0, false), 1e-9);
}

TEST(BalanceQp, ASeparationTaskBetweenTwoSiblingLimbsIsMetAndSharedByBoth) {
  // A 10 kg box in the air with two 2 kg arms pointing up from its top face, 0.1 m apart across y, each hinged about x
  // (they swing toward and away from each other). One task: the tips' relative acceleration along +y (from the right
  // arm's tip, a, to the left one's, b) 4 m/s^2. Neither arm is the other's ancestor: the plan's relative acceleration,
  // recomputed from the physics' point Jacobians, is the asked one, and by symmetry the two arms share it (hinge
  // accelerations equal and opposite); the root's recoil cancels.
  Model m;
  const int torso = m.add_body(make_body("torso", 0, JointType::Free, at({0, 0, 1.0}), 10.0, Vec3::Zero(),
                                         box_inertia(10.0, Vec3(0.1, 0.1, 0.05))));
  int arm[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    Body a = make_body(k == 0 ? "right" : "left", torso, JointType::Hinge, at({0, k == 0 ? -0.05 : 0.05, 0.05}), 2.0,
                       Vec3(0, 0, 0.2), box_inertia(2.0, Vec3(0.02, 0.02, 0.2)));
    a.axis = Vec3::UnitX();
    arm[k] = m.add_body(a);
  }
  m.finalize();
  Data d = make_data(m);
  kinematics_and_dynamics(m, d);
  BalanceQpInput in;
  in.dof_begin = 0, in.dof_end = m.nv, in.root_body = torso;
  in.com_acc = m.gravity;  // falling freely
  eng::control::QpSeparationTask t;
  t.body_a = arm[0], t.body_b = arm[1];
  t.point_a = d.x[arm[0]].apply(Vec3(0, 0, 0.4)), t.point_b = d.x[arm[1]].apply(Vec3(0, 0, 0.4));
  t.normal = Vec3::UnitY(), t.acc = 4.0, t.weight = 100.0;
  in.separations.push_back(t);
  BalanceQp ws;
  BalanceQpResult out;
  eng::control::balance_qp_solve(m, d, in, BalanceQpParams{}, ws, out);
  MatX Ja, Jb;
  point_jacobian(m, d, arm[0], t.point_a, Ja);
  point_jacobian(m, d, arm[1], t.point_b, Jb);
  const Vec3 a_a = Ja * out.qacc + eng::control::bias_point_acceleration(m, d, arm[0], t.point_a);
  const Vec3 a_b = Jb * out.qacc + eng::control::bias_point_acceleration(m, d, arm[1], t.point_b);
  EXPECT_NEAR((a_b - a_a).dot(t.normal), 4.0, 0.04);
  const double qa = out.qacc[m.bodies[arm[0]].v_index], qb = out.qacc[m.bodies[arm[1]].v_index];
  EXPECT_GT(std::abs(qa), 1.0) << "the right arm moves too: its chain is in the task's row";
  EXPECT_NEAR(qa, -qb, 1e-3 * std::abs(qa));
  EXPECT_LT(out.root_residual, 1e-6);
  // Without the task the arms stay (no other task asks them to move).
  in.separations.clear();
  eng::control::balance_qp_solve(m, d, in, BalanceQpParams{}, ws, out);
  EXPECT_LT(std::abs(out.qacc[m.bodies[arm[1]].v_index]), 1e-6);
}
