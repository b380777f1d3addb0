// step() = step1() + step2() (MuJoCo's mj_step1 / mj_step2 split) and what step1 leaves in Data.
#include <gtest/gtest.h>

#include <cstring>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {
bool same_bits(const VecX& a, const VecX& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}
bool same_bits(const MatX& a, const MatX& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}
// the "controller" of these tests: torques, an applied force and spring references from the state
void control(const Model& m, Data& d, int i) {
  clear_applied(d);
  apply_force_at_point(m, d, 2, Vec3(std::sin(0.01 * i) * 30, 10, 0), d.com_world[2]);
  for (int k = 6; k < m.nv; ++k) d.tau[k] = 5 * std::sin(0.02 * i + k) - 0.1 * d.v[k];
  for (int k = 6; k < m.nv; ++k) d.spring_ref[k] = 0.3 * std::sin(0.005 * i + k);
}
}  // namespace

TEST(StepSplit, Step1ThenStep2IsStepBitForBit) {
  const Model m = humanoid_on_floor();
  Data a = make_data(m), b = make_data(m);
  a.q[2] = b.q[2] = 1.0;
  for (int i = 0; i < 600; ++i) {
    // the same control inputs, computed from the same kinematics (forward_kinematics as the game does)
    forward_kinematics(m, a);
    control(m, a, i);
    step(m, a);
    forward_kinematics(m, b);
    control(m, b, i);
    step1(m, b);
    step2(m, b);
    ASSERT_TRUE(same_bits(a.q, b.q)) << "step " << i;
    ASSERT_TRUE(same_bits(a.v, b.v)) << "step " << i;
  }
  EXPECT_GT(a.contacts.size(), 0u);  // the run exercised contacts
  EXPECT_TRUE(same_bits(a.bias, b.bias));
  EXPECT_TRUE(same_bits(a.M, b.M));
}

// step(m, d, &times) times its stages (step.h StageTimes) and steps exactly as step(m, d): the clock is never read back.
TEST(StepSplit, ProfiledStepIsTheSameBitForBit) {
  const Model m = humanoid_on_floor();
  Data a = make_data(m), b = make_data(m);
  a.q[2] = b.q[2] = 1.0;
  StageTimes t;
  for (int i = 0; i < 300; ++i) {
    forward_kinematics(m, a);
    control(m, a, i);
    step(m, a);
    forward_kinematics(m, b);
    control(m, b, i);
    step(m, b, &t);
    ASSERT_TRUE(same_bits(a.q, b.q)) << "step " << i;
    ASSERT_TRUE(same_bits(a.v, b.v)) << "step " << i;
  }
  for (const double s : {t.collision, t.dynamics, t.solver, t.integration}) EXPECT_GE(s, 0.0);
  EXPECT_GT(t.dynamics, 0.0);
  EXPECT_GT(t.solver, 0.0);  // the humanoid landed: contact rows were solved
}

TEST(StepSplit, AfterStep1MassMatrixAndBiasAreThePhysicalOnes) {
  const Model m = humanoid_on_floor();
  Data d = make_data(m);
  std::mt19937 rng(7);
  randomize(m, d, rng);  // random q, v and nonzero applied forces
  step1(m, d);
  // reference: CRBA and RNEA(qacc = 0) on a copy with the applied forces removed
  Data ref = d;
  clear_applied(ref);
  forward_kinematics(m, ref);
  MatX M(m.nv, m.nv);
  crba(m, ref, M);
  VecX c(m.nv), c_rnea(m.nv);
  bias_forces(m, ref, c);
  rnea(m, ref, VecX::Zero(m.nv), c_rnea);
  EXPECT_TRUE(same_bits(d.M_crba, M));
  EXPECT_TRUE(same_bits(d.qfrc_bias, c));
  EXPECT_TRUE(same_bits(d.qfrc_bias, c_rnea));
  EXPECT_TRUE(same_bits(d.bias, d.qfrc_bias));
  // the applied forces were really there and are excluded (c with them differs)
  VecX c_applied(m.nv);
  bias_forces(m, d, c_applied);
  EXPECT_GT((c_applied - d.qfrc_bias).norm(), 1e-3);
  // d.M = M_crba + (armature + dt damping + dt^2 stiffness) on the diagonal, nothing else
  MatX extra = d.M - d.M_crba;
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    for (int k = 0; k < b.nv; ++k) {
      const int j = b.v_index + k;
      EXPECT_NEAR(extra(j, j), b.armature + m.dt * b.damping + m.dt * m.dt * b.stiffness, 1e-12);
      extra(j, j) = 0.0;
    }
  }
  EXPECT_EQ(extra.cwiseAbs().maxCoeff(), 0.0);
  // d.LD factors d.M: solving M x = M e_0 gives e_0
  VecX x = d.M.col(0);
  solve_ltdl(m, d.LD, x);
  EXPECT_NEAR((x - VecX::Unit(m.nv, 0)).norm(), 0.0, 1e-10);
}

TEST(StepSplit, Step1LeavesKinematicsAndContactsOfTheCurrentState) {
  const Model m = humanoid_on_floor();
  Data d = make_data(m);
  d.q[2] = 0.95;  // feet near the floor
  for (int i = 0; i < 100; ++i) step(m, d);
  const VecX q0 = d.q, v0 = d.v;
  const double t0 = d.time;
  step1(m, d);
  EXPECT_TRUE(same_bits(d.q, q0));
  EXPECT_TRUE(same_bits(d.v, v0));
  EXPECT_EQ(d.time, t0);
  Data ref = d;
  forward_kinematics(m, ref);
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    EXPECT_EQ(d.x[i].p, ref.x[i].p);
    EXPECT_EQ(d.com_world[i], ref.com_world[i]);
  }
  ASSERT_GT(d.contacts.size(), 0u);
  for (const Contact& c : d.contacts) {  // contacts of the current poses: the narrowphase again agrees
    const Geom& ga = m.geoms[c.point.geom_a];
    EXPECT_EQ(d.geom_x[c.point.geom_a].p, (ref.x[ga.body] * ga.local).p);
  }
}

// step2 skips the second RNEA when no force is applied; that is exact only if rigid_bias_forces equals
// bias_forces bit for bit when the applied forces are +0.
TEST(StepSplit, RigidBiasEqualsBiasForcesBitForBitWhenNothingIsApplied) {
  const Model m = humanoid_tree();
  Data d = make_data(m);
  std::mt19937 rng(3);
  VecX c1(m.nv), c2(m.nv);
  for (int trial = 0; trial < 50; ++trial) {
    randomize(m, d, rng);
    clear_applied(d);
    forward_kinematics(m, d);
    bias_forces(m, d, c1);
    rigid_bias_forces(m, d, c2);
    ASSERT_TRUE(same_bits(c1, c2)) << trial;
  }
}
