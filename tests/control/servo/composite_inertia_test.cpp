// Effective inertia for the gain rule k1 = I omega_n^2, k2 = 2 zeta I omega_n.
#include "engine/control/servo/composite_inertia.h"

#include <gtest/gtest.h>

using namespace eng::control;
using Eigen::Matrix3d;
using Eigen::Vector3d;

TEST(CompositeInertia, TwoLinkChainMatchesHandComputation) {
  eng::anim::Skeleton skel;
  skel.name = {"a", "b"};
  skel.parent = {-1, 0};
  skel.offset = {Vector3d::Zero(), Vector3d(0.4, 0, 0)};
  const std::vector<double> m = {2.0, 1.0};
  const std::vector<Vector3d> com = {Vector3d(0, 0, 0.1), Vector3d(0.2, 0, 0.1)};
  const std::vector<Matrix3d> I = {Vector3d(0.1, 0.2, 0.3).asDiagonal(), Vector3d(0.01, 0.05, 0.05).asDiagonal()};
  std::vector<Matrix3d> J;
  const auto s = composite_inertias(skel, m, com, I, InertiaScalar::MeanPrincipal, &J);
  // Bone b about its joint: r = (0.2, 0, 0.1), |r|^2 = 0.05:
  //   I_b + m (|r|^2 E - r r^T) = diag(.01,.05,.05) + [[.01,0,-.02],[0,.05,0],[-.02,0,.04]]
  Matrix3d Jb;
  Jb << 0.02, 0, -0.02, 0, 0.10, 0, -0.02, 0, 0.09;
  // Root about its joint: body a (r = (0,0,.1)): diag(.12,.22,.30); body b (r = (.6,0,.1), |r|^2 = .37):
  //   diag(.01,.05,.05) + [[.01,0,-.06],[0,.37,0],[-.06,0,.36]]
  Matrix3d Ja;
  Ja << 0.14, 0, -0.06, 0, 0.64, 0, -0.06, 0, 0.71;
  EXPECT_LT((J[1] - Jb).norm(), 1e-12);
  EXPECT_LT((J[0] - Ja).norm(), 1e-12);
  EXPECT_NEAR(s[1], 0.21 / 3.0, 1e-12);
  EXPECT_NEAR(s[0], 1.49 / 3.0, 1e-12);
  // Max principal of Jb: eigenvalues of [[.02,-.02],[-.02,.09]] and .10 -> .10 on y.
  const auto smax = composite_inertias(skel, m, com, I, InertiaScalar::MaxPrincipal);
  EXPECT_NEAR(smax[1], 0.10, 1e-12);
  const auto sm = subtree_masses(skel, m);
  EXPECT_DOUBLE_EQ(sm[0], 3.0);
  EXPECT_DOUBLE_EQ(sm[1], 1.0);
}
