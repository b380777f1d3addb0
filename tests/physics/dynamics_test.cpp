// Cross-checks of the dynamics algorithms against each other and against finite differences.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

TEST(Spatial, TransformInverseAndForceDuality) {
  const Pose P{Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix(), Vec3(0.3, -1, 2)};
  const SpatialTransform X = to_spatial(P);
  Vec6 mv, f;
  mv << 1, 2, 3, 4, 5, 6;
  f << -1, 0.5, 2, 3, -2, 1;
  EXPECT_LT((X.inverse().apply_motion(X.apply_motion(mv)) - mv).norm(), 1e-12);
  EXPECT_LT((X.inverse_motion(X.apply_motion(mv)) - mv).norm(), 1e-12);
  // power is invariant: (X m) . (X* f) = m . f
  EXPECT_NEAR(X.apply_motion(mv).dot(X.apply_force(f)), mv.dot(f), 1e-12);
  EXPECT_LT((X.matrix() * mv - X.apply_motion(mv)).norm(), 1e-12);
  EXPECT_LT((crf(mv) + crm(mv).transpose()).norm(), 1e-15);
}

TEST(Dynamics, HumanoidTreeHas36Dofs) {
  const Model m = humanoid_tree();
  EXPECT_EQ(m.nv, 36);
  EXPECT_EQ(m.bodies.size(), 18u);  // world + 17 (16 jointed links + a fixed glove... see builder)
}

TEST(Dynamics, AbaMatchesCrbaSolveOnRandomHumanoidStates) {
  const Model m = humanoid_tree();
  Data d = make_data(m);
  std::mt19937 rng(42);
  MatX M;
  VecX c(m.nv), tau(m.nv), qacc(m.nv), tau2(m.nv);
  for (int trial = 0; trial < 20; ++trial) {
    randomize(m, d, rng);
    for (int k = 0; k < m.nv; ++k) tau[k] = std::normal_distribution<double>(0, 5)(rng);
    forward_kinematics(m, d);
    crba(m, d, M);
    bias_forces(m, d, c);
    const VecX ref = M.ldlt().solve(tau - c);
    aba(m, d, tau, qacc);
    EXPECT_LT((qacc - ref).norm() / ref.norm(), 1e-9) << "trial " << trial;
    rnea(m, d, qacc, tau2);
    EXPECT_LT((tau2 - tau).norm() / tau.norm(), 1e-9) << "trial " << trial;
  }
}

TEST(Dynamics, MassMatrixSymmetricPositiveDefiniteAndMatchesRnea) {
  const Model m = humanoid_tree();
  Data d = make_data(m);
  std::mt19937 rng(7);
  MatX M;
  VecX c(m.nv), t(m.nv), e(m.nv);
  for (int trial = 0; trial < 5; ++trial) {
    randomize(m, d, rng);
    forward_kinematics(m, d);
    crba(m, d, M);
    EXPECT_LT((M - M.transpose()).norm(), 1e-12 * M.norm());
    Eigen::SelfAdjointEigenSolver<MatX> es(M);
    EXPECT_GT(es.eigenvalues().minCoeff(), 0.0);
    // column k of M = rnea(e_k) - rnea(0)
    bias_forces(m, d, c);
    for (int k = 0; k < m.nv; ++k) {
      e.setZero();
      e[k] = 1.0;
      rnea(m, d, e, t);
      EXPECT_LT((t - c - M.col(k)).norm(), 1e-9 * M.norm());
    }
  }
}

TEST(Dynamics, SparseLtdlSolveMatchesDenseSolve) {
  const Model m = humanoid_tree();
  Data d = make_data(m);
  std::mt19937 rng(3);
  randomize(m, d, rng);
  forward_kinematics(m, d);
  MatX M, LD = MatX::Zero(m.nv, m.nv);
  crba(m, d, M);
  factor_ltdl(m, M, LD);
  VecX b = VecX::Random(m.nv), x = b;
  solve_ltdl(m, LD, x);
  EXPECT_LT((M * x - b).norm() / b.norm(), 1e-10);
}

TEST(Dynamics, PointAndBodyJacobianMatchFiniteDifferences) {
  const Model m = humanoid_tree();
  Data d = make_data(m);
  std::mt19937 rng(11);
  randomize(m, d, rng);
  forward_kinematics(m, d);
  const VecX q0 = d.q;
  const VecX dv = d.v;
  for (int body : {1, 5, 10, 16}) {
    const Vec3 local(0.1, -0.05, 0.2);
    const Vec3 p = d.x[body].apply(local);
    MatX J, Jb;
    point_jacobian(m, d, body, p, J);
    body_jacobian(m, d, body, p, Jb);
    const double eps = 1e-6;
    Data dp = d, dm = d;
    dp.q = q_plus(m, q0, dv, eps);
    dm.q = q_plus(m, q0, dv, -eps);
    forward_kinematics(m, dp);
    forward_kinematics(m, dm);
    const Vec3 fd = (dp.x[body].apply(local) - dm.x[body].apply(local)) / (2 * eps);
    EXPECT_LT((J * dv - fd).norm(), 1e-6 * (1 + fd.norm())) << "body " << body;
    EXPECT_LT((Jb.bottomRows(3) * dv - fd).norm(), 1e-6 * (1 + fd.norm()));
    // angular part: R_dot R^T = [w]
    const Mat3 W = (dp.x[body].R - dm.x[body].R) / (2 * eps) * d.x[body].R.transpose();
    const Vec3 w(W(2, 1), W(0, 2), W(1, 0));
    EXPECT_LT((Jb.topRows(3) * dv - w).norm(), 1e-6 * (1 + w.norm()));
    // and J v equals the point velocity from the spatial body velocity
    const Vec6& vb = d.v_body[body];
    EXPECT_LT((J * dv - (lin(vb) + ang(vb).cross(p))).norm(), 1e-10);
  }
}

TEST(Dynamics, ComJacobianMatchesFiniteDifferences) {
  const Model m = humanoid_tree();
  Data d = make_data(m);
  std::mt19937 rng(5);
  randomize(m, d, rng);
  forward_kinematics(m, d);
  MatX J;
  com_jacobian(m, d, 1, J);
  const double eps = 1e-6;
  Data dp = d, dm = d;
  dp.q = q_plus(m, d.q, d.v, eps);
  dm.q = q_plus(m, d.q, d.v, -eps);
  forward_kinematics(m, dp);
  forward_kinematics(m, dm);
  const Vec3 fd = (subtree_com(m, dp, 1) - subtree_com(m, dm, 1)) / (2 * eps);
  EXPECT_LT((J * d.v - fd).norm(), 1e-6 * (1 + fd.norm()));
  // linear momentum = total mass * com velocity
  double mass = 0;
  for (size_t i = 1; i < m.bodies.size(); ++i) mass += m.bodies[i].mass;
  EXPECT_LT((lin(spatial_momentum(m, d, 1)) - mass * J * d.v).norm(), 1e-9 * mass * fd.norm());
}

TEST(Dynamics, KineticEnergyIsHalfVMV) {
  const Model m = humanoid_tree();
  Data d = make_data(m);
  std::mt19937 rng(9);
  randomize(m, d, rng);
  forward_kinematics(m, d);
  MatX M;
  crba(m, d, M);
  EXPECT_NEAR(kinetic_energy(m, d), 0.5 * d.v.dot(M * d.v), 1e-9 * d.v.dot(M * d.v));
}
