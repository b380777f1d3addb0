// Balance QP (see balance_qp.h): the tracking objective and the contact forces' generalised forces, qacc as an
// affine function of the friction-pyramid weights (KKT system), the non-negative least squares in those weights,
// then the torques.
#include "engine/control/balance/balance_qp.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/physics/dynamics.h"
#include "engine/physics/spatial.h"

namespace eng::control {

using physics::ang;
using physics::lin;

namespace {

// Spatial acceleration of `body` with qacc = 0 (world coordinates at the origin): sum of cdof_dot v over its
// ancestor DoFs (the same recursion as rnea's a_i = a_parent + S qacc + Sdot v).
Vec6 bias_spatial_acceleration(const physics::Model& m, const physics::Data& d, int body) {
  Vec6 a = Vec6::Zero();
  for (int k = m.body_last_dof[body]; k >= 0; k = m.dof_parent[k]) a += d.cdof_dot[k] * d.v[k];
  return a;
}

// The body's Jacobian over the block [b0, b0 + n), compacted to the columns it can move (its ancestor DoFs in
// the block, listed in `cols` as block indices): angular rows 0-2, the linear velocity of a point fixed to it rows
// 3-5. A boxer's hand depends on 18 of 37 DoFs, a foot on 15: the task products below run over those only.
void block_jacobian(const physics::Model& m, const physics::Data& d, int body, const Vec3& p, int b0, int n,
                    QpMat6N& J, std::vector<int>& cols) {
  cols.clear();
  for (int k = m.body_last_dof[body]; k >= 0; k = m.dof_parent[k])
    if (k >= b0 && k < b0 + n) cols.push_back(k - b0);
  J.resize(6, static_cast<int>(cols.size()));
  for (int a = 0; a < static_cast<int>(cols.size()); ++a) {
    const int k = b0 + cols[a];
    J.block<3, 1>(0, a) = ang(d.cdof[k]);
    J.block<3, 1>(3, a) = lin(d.cdof[k]) + ang(d.cdof[k]).cross(p);
  }
}

// Cholesky factor of Q restricted to the passive set, in P's order (L lower, np x np in ws.L): appending P's last
// variable adds one row, L_new = [L 0; l^T d] with L l = Q_P,j and d = sqrt(Q_jj - l.l) (O(np^2), Golub & Van Loan
// sec. 4.2); a variable leaving rebuilds the factor (rare: the inner loop's drops).
void chol_append(const QpMatKK& Q, const std::vector<int>& P, int np, QpMatKK& L) {
  const int j = P[np - 1];
  double dd = Q(j, j);
  for (int a = 0; a < np - 1; ++a) {
    double s = Q(P[a], j);
    for (int c = 0; c < a; ++c) s -= L(a, c) * L(np - 1, c);
    const double l = s / L(a, a);
    L(np - 1, a) = l;
    dd -= l * l;
  }
  // Q is positive definite (the ridge); a round-off non-positive pivot is clamped, not propagated.
  L(np - 1, np - 1) = std::sqrt(std::max(dd, 1e-15 * Q(j, j) + 1e-300));
}

// z = Q_PP^-1 q_P from the factor: L y = q_P, L^T z = y.
void chol_solve(const QpVecK& q, const std::vector<int>& P, int np, const QpMatKK& L, QpVecK& z) {
  for (int a = 0; a < np; ++a) {
    double s = q[P[a]];
    for (int c = 0; c < a; ++c) s -= L(a, c) * z[c];
    z[a] = s / L(a, a);
  }
  for (int a = np - 1; a >= 0; --a) {
    double s = z[a];
    for (int c = a + 1; c < np; ++c) s -= L(c, a) * z[c];
    z[a] = s / L(a, a);
  }
}

// H = L L^T in place (the lower triangle of A becomes L), unblocked, column by column (Golub & Van Loan alg. 4.2.1,
// the gaxpy form). At the balance QP's sizes (37 DoFs) Eigen's LLT takes its blocked path, whose packing costs more
// than the arithmetic. A non-positive pivot (not expected: H has the ridge) is clamped, as in chol_append.
void dense_cholesky(QpMatNN& A) {
  const int n = static_cast<int>(A.rows());
  for (int j = 0; j < n; ++j) {
    if (j > 0) A.col(j).tail(n - j).noalias() -= A.block(j, 0, n - j, j) * A.row(j).head(j).transpose();
    const double d = std::sqrt(std::max(A(j, j), 1e-300));
    A(j, j) = d;
    A.col(j).tail(n - j - 1) /= d;
  }
}

// x = (L L^T)^-1 x for each column of X: forward substitution down L's columns, back substitution along them.
template <typename Cols>
void cholesky_solve_in_place(const QpMatNN& L, Cols&& X) {
  const int n = static_cast<int>(L.rows());
  for (int c = 0; c < X.cols(); ++c) {
    auto x = X.col(c);
    for (int j = 0; j < n; ++j) {
      x[j] /= L(j, j);
      x.tail(n - j - 1) -= x[j] * L.col(j).tail(n - j - 1);
    }
    for (int j = n - 1; j >= 0; --j) x[j] = (x[j] - L.col(j).tail(n - j - 1).dot(x.tail(n - j - 1))) / L(j, j);
  }
}

// Lawson & Hanson's active-set NNLS ("Solving Least Squares Problems", 1974, ch. 23) in normal-equation form:
// min 1/2 x^T Q x - q^T x subject to x >= 0, Q symmetric positive definite. Exact in a finite number of steps
// (projected Gauss-Seidel needs thousands of sweeps here: Q = A^T A has rank 6 plus a tiny ridge). The passive
// set's system is solved from a Cholesky factor grown one row per added variable (above), not refactored.
void nnls(const QpMatKK& Q, const QpVecK& q, BalanceQp& ws, QpVecK& x) {
  const int K = static_cast<int>(q.size());
  x.setZero(K);
  std::vector<int>& P = ws.passive;
  std::vector<char>& in_p = ws.in_passive;
  P.clear();
  in_p.assign(K, 0);
  ws.L.resize(K, K);
  ws.z.resize(K);
  const double tol = 1e-10 * (q.cwiseAbs().maxCoeff() + 1e-30);
  // Warm start: the last solve's passive set (a standing boxer's contacts change slowly). If the problem has the
  // same size and the set's own solution is positive, start from it; the loop below then checks the optimality
  // conditions as usual (and goes on adding variables where they fail), so the answer is the same optimum.
  if (static_cast<int>(ws.warm.size()) > 0 && ws.warm_K == K) {
    for (int j : ws.warm) P.push_back(j), in_p[j] = 1;
    const int np = static_cast<int>(P.size());
    for (int a = 1; a <= np; ++a) chol_append(Q, P, a, ws.L);
    chol_solve(q, P, np, ws.L, ws.z);
    if (ws.z.head(np).minCoeff() > 0.0) {
      for (int a = 0; a < np; ++a) x[P[a]] = ws.z[a];
    } else {
      for (int j : P) in_p[j] = 0;
      P.clear();
    }
  }
  for (int outer = 0; outer < 3 * K + 10; ++outer) {
    // w = q - Q x over the passive columns only (x is zero elsewhere)
    ws.wk = q;
    for (int j : P) ws.wk.noalias() -= x[j] * Q.col(j);
    int j = -1;
    double best = tol;
    for (int k = 0; k < K; ++k)
      if (!in_p[k] && ws.wk[k] > best) best = ws.wk[k], j = k;
    if (j < 0) break;
    P.push_back(j), in_p[j] = 1;
    chol_append(Q, P, static_cast<int>(P.size()), ws.L);
    for (int inner = 0; inner < 3 * K + 10; ++inner) {
      const int np = static_cast<int>(P.size());
      chol_solve(q, P, np, ws.L, ws.z);
      if (ws.z.head(np).minCoeff() > 0.0) {
        for (int a = 0; a < np; ++a) x[P[a]] = ws.z[a];
        break;
      }
      // Step from x toward z until the first passive variable hits zero, then drop the zeros.
      double alpha = 1.0;
      for (int a = 0; a < np; ++a)
        if (ws.z[a] <= 0.0) alpha = std::min(alpha, x[P[a]] / (x[P[a]] - ws.z[a]));
      for (int a = 0; a < np; ++a) x[P[a]] += alpha * (ws.z[a] - x[P[a]]);
      int keep = 0;
      for (int a = 0; a < np; ++a) {
        if (x[P[a]] > 1e-12) P[keep++] = P[a];
        else x[P[a]] = 0.0, in_p[P[a]] = 0;
      }
      P.resize(keep);
      if (keep == 0) break;
      for (int a = 1; a <= keep; ++a) chol_append(Q, P, a, ws.L);  // refactor the smaller set
    }
  }
  ws.warm.assign(P.begin(), P.end());
  ws.warm_K = K;
}

// The root assist's torque from the last six unknowns (+-x, +-y, +-z) and its magnitude.
Vec3 assist_torque(const QpVecK& beta, int nc) {
  Vec3 a = Vec3::Zero();
  for (int k = 0; k < 6; ++k) a += beta[4 * nc + k] * (k % 2 == 0 ? 1.0 : -1.0) * Vec3::Unit(k / 2);
  return a;
}
double assist_norm(const QpVecK& beta, int nc) { return assist_torque(beta, nc).norm(); }

}  // namespace

Vec3 bias_angular_acceleration(const physics::Model& m, const physics::Data& d, int body) {
  return ang(bias_spatial_acceleration(m, d, body));
}

Vec3 bias_point_acceleration(const physics::Model& m, const physics::Data& d, int body, const Vec3& point) {
  // Classical acceleration of a body-fixed point from the spatial one at the origin (RBDA eq. 2.47 with the
  // velocity-product term): a_p = a_O + alpha x p + omega x v_p, v_p = v_O + omega x p.
  const Vec6 a = bias_spatial_acceleration(m, d, body);
  const Vec3 w = ang(d.v_body[body]);
  const Vec3 vp = lin(d.v_body[body]) + w.cross(point);
  return lin(a) + ang(a).cross(point) + w.cross(vp);
}

void balance_qp_solve(const physics::Model& m, const physics::Data& d, const BalanceQpInput& in,
                      const BalanceQpParams& p, BalanceQp& ws, BalanceQpResult& out) {
  const int b0 = in.dof_begin, n = in.dof_end - in.dof_begin;
  if (n > kQpMaxDofs || n < 6) {  // not an articulation this workspace can hold: no plan, no torque
    out.qacc.setZero(std::max(n, 0)), out.tau.setZero(std::max(n, 0));
    out.contact_force.clear();
    out.root_residual = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  // Contacts past the workspace's capacity are left out of the plan (balance_qp.h).
  const int nc = std::min(static_cast<int>(in.contacts.size()), kQpMaxContacts);
  // Unknowns of the reduced problem: 4 pyramid edges per contact, then (root assist on) +-x, +-y, +-z torques.
  const int na = p.w_root_assist > 0.0 && p.max_root_assist > 0.0 ? 6 : 0;
  const int K = 4 * nc + na;

  // Mass and com of the articulation.
  double mass = 0.0;
  Vec3 com = Vec3::Zero();
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    if (m.bodies[i].root != in.root_body) continue;
    mass += m.bodies[i].mass;
    com += m.bodies[i].mass * d.com_world[i];
  }
  com /= mass;

  // M and c(q, v) of the articulation: its blocks of what the step's first half built (step1: d.M_crba,
  // d.qfrc_bias), once per tick for the physics and every boxer.
  const auto M = d.M_crba.block(b0, b0, n, n);
  const VecX& c_full = d.qfrc_bias;

  // ---- The tracking objective over qacc: 1/2 qacc^T H qacc - g^T qacc ----
  ws.H.setZero(n, n);
  ws.g.setZero(n);
  QpMatNN& H = ws.H;
  H.diagonal().setConstant(p.reg_qacc);
  // w |J_t qacc - target|^2 over the task's columns only (J compacted by block_jacobian).
  auto add_task = [&](int row0, const Vec3& target, double w) {
    const std::vector<int>& cols = ws.cols;
    const int s = static_cast<int>(cols.size());
    for (int a = 0; a < s; ++a) {
      const Vec3 ja = ws.J.block<3, 1>(row0, a);
      ws.g[cols[a]] += w * ja.dot(target);
      H(cols[a], cols[a]) += w * ja.dot(ja);
      for (int c = a + 1; c < s; ++c) {  // J^T J is symmetric: each off-diagonal product once
        const double h = w * ja.dot(ws.J.block<3, 1>(row0, c));
        H(cols[a], cols[c]) += h;
        H(cols[c], cols[a]) += h;
      }
    }
  };
  for (const QpAngularTask& t : in.angular) {
    block_jacobian(m, d, t.body, d.com_world[t.body], b0, n, ws.J, ws.cols);
    add_task(0, t.alpha - bias_angular_acceleration(m, d, t.body), t.weight);
  }
  for (const QpPointTask& t : in.points) {
    block_jacobian(m, d, t.body, t.point, b0, n, ws.J, ws.cols);
    Vec3 bias = bias_point_acceleration(m, d, t.body, t.point);
    if (t.ref_body >= 0) {
      // J_point - J_ref: the reference's DoFs are among the point's (an ancestor's chain is part of its descendant's).
      block_jacobian(m, d, t.ref_body, t.ref_point, b0, n, ws.J_ref, ws.cols_ref);
      for (size_t r = 0; r < ws.cols_ref.size(); ++r)
        for (size_t a = 0; a < ws.cols.size(); ++a)
          if (ws.cols[a] == ws.cols_ref[r]) ws.J.col(static_cast<int>(a)) -= ws.J_ref.col(static_cast<int>(r));
      bias -= bias_point_acceleration(m, d, t.ref_body, t.ref_point);
    }
    add_task(3, t.acc - bias, t.weight);
  }
  // Separation tasks: w (row qacc - target)^2 with row = normal^T (J_b - J_a), dense over the block (the two chains
  // share the root's and the pelvis's DoFs, and neither contains the other).
  for (const QpSeparationTask& t : in.separations) {
    ws.row.setZero(n);
    block_jacobian(m, d, t.body_b, t.point_b, b0, n, ws.J, ws.cols);
    for (size_t a = 0; a < ws.cols.size(); ++a) ws.row[ws.cols[a]] += t.normal.dot(ws.J.block<3, 1>(3, int(a)));
    block_jacobian(m, d, t.body_a, t.point_a, b0, n, ws.J, ws.cols);
    for (size_t a = 0; a < ws.cols.size(); ++a) ws.row[ws.cols[a]] -= t.normal.dot(ws.J.block<3, 1>(3, int(a)));
    const double target = t.acc - t.normal.dot(bias_point_acceleration(m, d, t.body_b, t.point_b) -
                                               bias_point_acceleration(m, d, t.body_a, t.point_a));
    H.noalias() += t.weight * ws.row * ws.row.transpose();
    ws.g.noalias() += (t.weight * target) * ws.row;
  }
  // Joint limits (BalanceQpParams::w_limit): the step's limit rows of this articulation, J sparse over the joint's DoFs
  // with J v = dC/dt (the row's Jdot v left out: the swing axis turns slowly).
  if (p.w_limit > 0.0) {
    for (const physics::ConstraintRow& r : d.rows) {
      if (r.kind != physics::ConstraintRow::Limit || r.C > p.limit_margin || r.nz_count == 0) continue;
      const int* idx = d.J_idx.data() + r.nz_begin;
      const double* jv = d.J_val.data() + r.nz_begin;
      if (idx[0] < b0 || idx[0] >= b0 + n) continue;
      if (!in.limit_bodies.empty() &&
          std::find(in.limit_bodies.begin(), in.limit_bodies.end(), m.dof_body[idx[r.nz_count - 1]]) == in.limit_bodies.end())
        continue;
      double C_dot = 0.0;
      for (int a = 0; a < r.nz_count; ++a) C_dot += jv[a] * d.v[idx[a]];
      const double acc = p.limit_kp * (p.limit_margin - r.C) - p.limit_kd * C_dot;
      if (acc <= 0.0) continue;
      for (int a = 0; a < r.nz_count; ++a) {
        ws.g[idx[a] - b0] += p.w_limit * jv[a] * acc;
        for (int c = 0; c < r.nz_count; ++c) H(idx[a] - b0, idx[c] - b0) += p.w_limit * jv[a] * jv[c];
      }
    }
  }
  // Contact points stay put (damped): a heavily weighted task rather than an equality, because a flat foot's
  // four corners give 12 dependent rows, and a foot touching at one corner or edge must stay free to roll flat
  // about it (its orientation task does that).
  for (int ci = 0; ci < nc; ++ci) {
    const QpContact& c = in.contacts[ci];
    block_jacobian(m, d, c.body, c.point, b0, n, ws.J, ws.cols);
    const Vec3 w = ang(d.v_body[c.body]);
    const Vec3 v = lin(d.v_body[c.body]) + w.cross(c.point);
    add_task(3, -p.hold_damping * v - bias_point_acceleration(m, d, c.body, c.point), p.w_hold);
  }

  // ---- Contact forces: pyramid edges u (f_c = sum beta u, beta >= 0), their wrench about the com (A) and
  // their generalised force over the block (G = J_c^T u; its root rows enter the Newton-Euler equality) ----
  ws.basis.resize(K);
  ws.A.setZero(6, K);
  ws.G.resize(n, K);
  for (int c = 0; c < nc; ++c) {
    const QpContact& ct = in.contacts[c];
    const Vec3 nrm = ct.normal.normalized();
    const Vec3 t1 = nrm.unitOrthogonal(), t2 = nrm.cross(t1);
    const Vec3 r = ct.point - com;
    const Vec3 u[4] = {nrm + ct.mu * t1, nrm - ct.mu * t1, nrm + ct.mu * t2, nrm - ct.mu * t2};
    block_jacobian(m, d, ct.body, ct.point, b0, n, ws.J, ws.cols);
    for (int k = 0; k < 4; ++k) {
      ws.basis[4 * c + k] = u[k];
      ws.A.block<3, 1>(0, 4 * c + k) = std::sqrt(p.w_force) * u[k];
      ws.A.block<3, 1>(3, 4 * c + k) = std::sqrt(p.w_moment) * r.cross(u[k]);
      ws.G.col(4 * c + k).setZero();
      for (int a = 0; a < static_cast<int>(ws.cols.size()); ++a)
        ws.G(ws.cols[a], 4 * c + k) = ws.J.block<3, 1>(3, a).dot(u[k]);
    }
  }
  // Root assist: a pure torque on the root body, a moment about the com like any other.
  if (na > 0) {
    block_jacobian(m, d, in.root_body, d.x[in.root_body].p, b0, n, ws.J, ws.cols);
    for (int k = 0; k < 6; ++k) {
      const Vec3 e = (k % 2 == 0 ? 1.0 : -1.0) * Vec3::Unit(k / 2);
      ws.A.block<3, 1>(0, 4 * nc + k).setZero();
      ws.A.block<3, 1>(3, 4 * nc + k) = std::sqrt(p.w_moment) * e;
      ws.G.col(4 * nc + k).setZero();
      for (int a = 0; a < static_cast<int>(ws.cols.size()); ++a)
        ws.G(ws.cols[a], 4 * nc + k) = ws.J.block<3, 1>(0, a).dot(e);
    }
  }

  // ---- Newton-Euler of the floating base, exactly: M_root qacc + c_root = F beta. For a given beta the best
  // qacc solves the KKT system [H E^T; E 0] [qacc; lambda] = [g; F beta - c_root], affine in beta:
  // qacc = q0 + Q1 beta. ----
  Eigen::Matrix<double, 6, 1> c_root;
  for (int k = 0; k < 6; ++k) {
    const int dof = b0 + k;
    c_root[k] = c_full[dof] + m.bodies[m.dof_body[dof]].damping * d.v[dof];
  }
  // Solved by the range-space (Schur complement) method (Nocedal & Wright sec. 16.2), H being positive definite
  // (the qacc ridge): with Y = H^-1 E^T and S = E Y (6 x 6, positive definite: E has full row rank),
  //   lambda = S^-1 (E H^-1 t - b),  qacc = H^-1 t - Y lambda.
  // For q0: t = g, b = -c_root. For Q1: t = 0, b = F (the pyramid edges' root rows), so Q1 = Y S^-1 F. Two
  // Cholesky factors (n and 6) instead of an LU of the (n + 6) KKT matrix with K + 1 right-hand sides.
  ws.E = M.topRows(6);
  for (int k = 0; k < 6; ++k) ws.E(k, k) += m.bodies[m.dof_body[b0 + k]].armature;
  ws.L_H = H;
  dense_cholesky(ws.L_H);
  ws.Y = ws.E.transpose();
  cholesky_solve_in_place(ws.L_H, ws.Y);
  ws.S.noalias() = ws.E.lazyProduct(ws.Y);
  ws.llt_S.compute(ws.S);
  ws.sol.resize(n, K + 1);
  ws.sol.col(0) = ws.g;
  cholesky_solve_in_place(ws.L_H, ws.sol.leftCols(1));
  ws.lambda.noalias() = ws.E * ws.sol.col(0);
  ws.lambda += c_root;
  ws.llt_S.solveInPlace(ws.lambda);
  ws.sol.col(0).noalias() -= ws.Y * ws.lambda;
  if (K > 0) {
    ws.SF = ws.G.topRows(6);
    ws.llt_S.solveInPlace(ws.SF);
    ws.sol.rightCols(K).noalias() = ws.Y.lazyProduct(ws.SF);  // 6 deep: coefficient-wise beats the blocked kernel
  }
  const auto q0 = ws.sol.col(0).head(n);
  const auto Q1 = ws.sol.topRightCorner(n, K);

  // ---- The reduced problem in beta: tracking cost at qacc(beta) plus the wrench terms, beta >= 0 ----
  //   1/2 beta^T (Q1^T H Q1 + A^T A + ridge) beta - (A^T b - Q1^T (H q0 - g))^T beta
  const Vec3 F_des = mass * (in.com_acc - m.gravity);
  ws.b.head<3>() = std::sqrt(p.w_force) * F_des;
  ws.b.tail<3>() = std::sqrt(p.w_moment) * in.momentum_rate;
  ws.beta.setZero(K);
  if (K > 0) {
    // Q1 = Y S^-1 F has rank 6, and H Y = E^T, so Q1^T H Q1 = SF^T E Y SF = SF^T F (S SF = F): a 6-deep product
    // instead of two n-deep ones, and Q1^T w = SF^T (Y^T w).
    ws.Q.noalias() = ws.SF.transpose().lazyProduct(ws.G.topRows(6));
    ws.Q.noalias() += ws.A.transpose().lazyProduct(ws.A);
    ws.w.noalias() = H * q0;
    ws.w -= ws.g;
    ws.q.noalias() = ws.A.transpose() * ws.b;
    ws.lambda.noalias() = ws.Y.transpose() * ws.w;
    ws.q.noalias() -= ws.SF.transpose() * ws.lambda;
    // Joint torques priced too (minimum effort): tau_joints = T1 beta + t0 is affine in beta like qacc. Without it
    // the torques are free in the plan, and a body touching the crates at several links (a knee and a foot) could be
    // planned with large opposing contact forces (the ridge alone lets a knee landing ask tens of kN m and the
    // simulation diverge: docs/decisions/balance-qp-tuning.md).
    if (p.w_torque > 0.0 && n > 6) {
      const int nj = n - 6;
      ws.HQ1.noalias() = M.bottomRows(nj) * ws.Y;  // (M Q1)_joints = (M_joints Y) S^-1 F, 6 deep again
      ws.T1.noalias() = ws.HQ1.lazyProduct(ws.SF);
      ws.T1 -= ws.G.bottomRows(nj);
      ws.t0.noalias() = M.bottomRows(nj) * q0;
      for (int k = 0; k < nj; ++k) {
        const int dof = b0 + 6 + k;
        const auto& body = m.bodies[m.dof_body[dof]];
        ws.T1.row(k) += body.armature * Q1.row(6 + k);
        ws.t0[k] += body.armature * q0[6 + k] + c_full[dof] + body.damping * d.v[dof];
      }
      // + w T1^T T1, into Q's lower triangle only (a symmetric rank-nj update: half a general product's work)
      ws.Q.selfadjointView<Eigen::Lower>().rankUpdate(ws.T1.transpose(), p.w_torque);
      ws.q.noalias() -= p.w_torque * ws.T1.transpose() * ws.t0;
    }
    // Q from its lower triangle (symmetric: the products above agree with their transposes up to round-off)
    ws.Q.triangularView<Eigen::StrictlyUpper>() = ws.Q.transpose();
    const double reg = (nc > 0 ? p.reg_beta * ws.Q.diagonal().head(4 * nc).mean() : 0.0) + 1e-12;
    ws.Q.diagonal().array() += reg;
    ws.Q.diagonal().tail(na).array() += p.w_root_assist;
    nnls(ws.Q, ws.q, ws, ws.beta);
    // The torque limit: where the plan asks for more, the assist's price goes up until the plan fits the limit (the
    // smallest price found that does, by factors of 10 then bisection in log price), so the plan is made within the
    // limit rather than clipped after it (a clipped plan's body misses its accelerations and falls where it clips:
    // docs/decisions/balance-qp-tuning.md).
    if (na > 0 && assist_norm(ws.beta, nc) > p.max_root_assist) {
      const Eigen::Matrix<double, 6, 1> base = ws.Q.diagonal().tail<6>().array() - p.w_root_assist;
      auto solve_at = [&](double price) {
        ws.Q.diagonal().tail<6>() = base.array() + price;
        nnls(ws.Q, ws.q, ws, ws.beta);
        return assist_norm(ws.beta, nc) <= p.max_root_assist;
      };
      double lo = p.w_root_assist, hi = lo;
      bool fits = false;
      for (int i = 0; i < 8 && !fits; ++i) {
        lo = hi, hi *= 10.0;
        fits = solve_at(hi);
      }
      ws.beta_fit = ws.beta;
      for (int i = 0; i < 6 && fits; ++i) {
        const double mid = std::sqrt(lo * hi);
        if (solve_at(mid)) hi = mid, ws.beta_fit = ws.beta;
        else lo = mid;
      }
      ws.beta = ws.beta_fit;
    }
  }
  out.qacc = q0;
  if (K > 0) out.qacc.noalias() += Q1 * ws.beta;

  out.contact_force.assign(nc, Vec3::Zero());
  out.force.setZero();
  out.moment.setZero();
  Vec3 cop_sum = Vec3::Zero();
  double fn_sum = 0.0;
  for (int c = 0; c < nc; ++c) {
    Vec3 f = Vec3::Zero();
    for (int k = 0; k < 4; ++k) f += ws.beta[4 * c + k] * ws.basis[4 * c + k];
    out.contact_force[c] = f;
    out.force += f;
    out.moment += (in.contacts[c].point - com).cross(f);
    const double fn = std::max(0.0, f.dot(in.contacts[c].normal.normalized()));
    cop_sum += fn * in.contacts[c].point;
    fn_sum += fn;
  }
  out.cop = fn_sum > 0.0 ? Vec3(cop_sum / fn_sum) : com;
  out.root_assist = na > 0 ? assist_torque(ws.beta, nc) : Vec3::Zero();
  const double scale = std::min(1.0, p.max_root_assist / std::max(out.root_assist.norm(), 1e-12));
  out.assist_clamped = scale < 1.0;
  out.root_assist *= scale;

  // ---- Torques: tau = M qacc + c - J^T f (plus the passive terms the step adds: armature on M's diagonal,
  // joint damping -D v, integrated implicitly by the step and taken here at the current v) ----
  out.tau.noalias() = M * out.qacc;
  if (nc > 0) out.tau.noalias() -= ws.G.leftCols(4 * nc) * ws.beta.head(4 * nc);  // - J^T f
  for (int k = 0; k < n; ++k) {
    const int dof = b0 + k;
    const auto& body = m.bodies[m.dof_body[dof]];
    out.tau[k] += body.armature * out.qacc[k] + c_full[dof] + body.damping * d.v[dof];
  }
  // The root rows are the assist's generalised force (J_root^T [tau_a; 0]), zero when off; after a clamp the root
  // gets the clamped torque and the body falls short of qacc there.
  ws.tau_assist.setZero(6);
  if (na > 0) {
    ws.tau_assist.noalias() = ws.G.topRows(6).rightCols(na) * ws.beta.tail(na);
    ws.tau_assist *= scale;
    out.root_residual = (out.tau.head<6>() - ws.tau_assist / scale).norm();
    out.tau.head<6>() = ws.tau_assist;
  } else {
    out.root_residual = out.tau.head<6>().norm();
    out.tau.head<6>().setZero();  // the floating base is unactuated
  }
}

}  // namespace eng::control
