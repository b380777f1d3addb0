// Balance QP (see balance_qp.h): the tracking objective and the contact forces' generalised forces, qacc as an
// affine function of the friction-pyramid weights (KKT system), the non-negative least squares in those weights,
// then the torques.
#include "engine/control/balance/balance_qp.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

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

// Rows of the body's Jacobian restricted to the block [b0, b0 + n): angular (3 x n) and the linear velocity of
// a point fixed to it (3 x n). Columns outside the body's ancestors stay zero.
void block_jacobian(const physics::Model& m, const physics::Data& d, int body, const Vec3& p, int b0, int n,
                    MatX& J) {
  J.setZero(6, n);
  for (int k = m.body_last_dof[body]; k >= 0; k = m.dof_parent[k]) {
    if (k < b0 || k >= b0 + n) continue;
    J.block<3, 1>(0, k - b0) = ang(d.cdof[k]);
    J.block<3, 1>(3, k - b0) = lin(d.cdof[k]) + ang(d.cdof[k]).cross(p);
  }
}

// Lawson & Hanson's active-set NNLS ("Solving Least Squares Problems", 1974, ch. 23) in normal-equation form:
// min 1/2 x^T Q x - q^T x subject to x >= 0, Q symmetric positive definite. Exact in a finite number of steps
// (projected Gauss-Seidel needed thousands of sweeps here: Q = A^T A has rank 6 plus a tiny ridge).
void nnls(const MatX& Q, const VecX& q, BalanceQp& ws, VecX& x) {
  const int K = static_cast<int>(q.size());
  x.setZero(K);
  std::vector<int>& P = ws.passive;
  std::vector<char>& in_p = ws.in_passive;
  P.clear();
  in_p.assign(K, 0);
  const double tol = 1e-10 * (q.cwiseAbs().maxCoeff() + 1e-30);
  for (int outer = 0; outer < 3 * K + 10; ++outer) {
    ws.w.noalias() = q - Q * x;
    int j = -1;
    double best = tol;
    for (int k = 0; k < K; ++k)
      if (!in_p[k] && ws.w[k] > best) best = ws.w[k], j = k;
    if (j < 0) break;
    P.push_back(j), in_p[j] = 1;
    for (int inner = 0; inner < 3 * K + 10; ++inner) {
      const int np = static_cast<int>(P.size());
      ws.Qpp.resize(np, np);
      ws.qp.resize(np);
      for (int a = 0; a < np; ++a) {
        ws.qp[a] = q[P[a]];
        for (int c = 0; c < np; ++c) ws.Qpp(a, c) = Q(P[a], P[c]);
      }
      ws.z = ws.Qpp.ldlt().solve(ws.qp);
      if (ws.z.minCoeff() > 0.0) {
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
    }
  }
}

// The root assist's torque from the last six unknowns (+-x, +-y, +-z) and its magnitude.
Vec3 assist_torque(const VecX& beta, int nc) {
  Vec3 a = Vec3::Zero();
  for (int k = 0; k < 6; ++k) a += beta[4 * nc + k] * (k % 2 == 0 ? 1.0 : -1.0) * Vec3::Unit(k / 2);
  return a;
}
double assist_norm(const VecX& beta, int nc) { return assist_torque(beta, nc).norm(); }

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
  const int nc = static_cast<int>(in.contacts.size());
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

  ws.M_full.resize(m.nv, m.nv);
  ws.c_full.resize(m.nv);
  physics::crba(m, d, ws.M_full);
  physics::bias_forces(m, d, ws.c_full);
  const auto M = ws.M_full.block(b0, b0, n, n);

  // ---- The tracking objective over qacc: 1/2 qacc^T H qacc - g^T qacc ----
  ws.KKT.setZero(n + 6, n + 6);
  ws.g.setZero(n);
  auto H = ws.KKT.topLeftCorner(n, n);
  H.diagonal().setConstant(p.reg_qacc);
  auto add_task = [&](const auto& Jt, const Vec3& target, double w) {
    H.noalias() += w * Jt.transpose() * Jt;
    ws.g.noalias() += w * Jt.transpose() * target;
  };
  for (const QpAngularTask& t : in.angular) {
    block_jacobian(m, d, t.body, d.com_world[t.body], b0, n, ws.J);
    add_task(ws.J.topRows<3>(), t.alpha - bias_angular_acceleration(m, d, t.body), t.weight);
  }
  for (const QpPointTask& t : in.points) {
    block_jacobian(m, d, t.body, t.point, b0, n, ws.J);
    add_task(ws.J.bottomRows<3>(), t.acc - bias_point_acceleration(m, d, t.body, t.point), t.weight);
  }
  // Contact points stay put (damped): a heavily weighted task rather than an equality, because a flat foot's
  // four corners give 12 dependent rows, and a foot touching at one corner or edge must stay free to roll flat
  // about it (its orientation task does that).
  for (const QpContact& c : in.contacts) {
    block_jacobian(m, d, c.body, c.point, b0, n, ws.J);
    const Vec3 w = ang(d.v_body[c.body]);
    const Vec3 v = lin(d.v_body[c.body]) + w.cross(c.point);
    add_task(ws.J.bottomRows<3>(), -p.hold_damping * v - bias_point_acceleration(m, d, c.body, c.point), p.w_hold);
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
    block_jacobian(m, d, ct.body, ct.point, b0, n, ws.J);
    for (int k = 0; k < 4; ++k) {
      ws.basis[4 * c + k] = u[k];
      ws.A.block<3, 1>(0, 4 * c + k) = std::sqrt(p.w_force) * u[k];
      ws.A.block<3, 1>(3, 4 * c + k) = std::sqrt(p.w_moment) * r.cross(u[k]);
      ws.G.col(4 * c + k).noalias() = ws.J.bottomRows<3>().transpose() * u[k];
    }
  }
  // Root assist: a pure torque on the root body, a moment about the com like any other.
  if (na > 0) {
    block_jacobian(m, d, in.root_body, d.x[in.root_body].p, b0, n, ws.J);
    for (int k = 0; k < 6; ++k) {
      const Vec3 e = (k % 2 == 0 ? 1.0 : -1.0) * Vec3::Unit(k / 2);
      ws.A.block<3, 1>(0, 4 * nc + k).setZero();
      ws.A.block<3, 1>(3, 4 * nc + k) = std::sqrt(p.w_moment) * e;
      ws.G.col(4 * nc + k).noalias() = ws.J.topRows<3>().transpose() * e;
    }
  }

  // ---- Newton-Euler of the floating base, exactly: M_root qacc + c_root = F beta. For a given beta the best
  // qacc solves the KKT system [H E^T; E 0] [qacc; lambda] = [g; F beta - c_root], affine in beta:
  // qacc = q0 + Q1 beta. ----
  Eigen::Matrix<double, 6, 1> c_root;
  for (int k = 0; k < 6; ++k) {
    const int dof = b0 + k;
    c_root[k] = ws.c_full[dof] + m.bodies[m.dof_body[dof]].damping * d.v[dof];
  }
  ws.KKT.block(n, 0, 6, n) = M.topRows(6);
  for (int k = 0; k < 6; ++k) ws.KKT(n + k, k) += m.bodies[m.dof_body[b0 + k]].armature;
  ws.KKT.topRightCorner(n, 6) = ws.KKT.bottomLeftCorner(6, n).transpose();
  ws.lu.compute(ws.KKT);
  ws.rhs.setZero(n + 6, K + 1);
  ws.rhs.col(0).head(n) = ws.g;
  ws.rhs.col(0).tail<6>() = -c_root;
  ws.rhs.bottomRightCorner(6, K) = ws.G.topRows(6);
  ws.sol = ws.lu.solve(ws.rhs);
  const auto q0 = ws.sol.col(0).head(n);
  const auto Q1 = ws.sol.topRightCorner(n, K);

  // ---- The reduced problem in beta: tracking cost at qacc(beta) plus the wrench terms, beta >= 0 ----
  //   1/2 beta^T (Q1^T H Q1 + A^T A + ridge) beta - (A^T b - Q1^T (H q0 - g))^T beta
  const Vec3 F_des = mass * (in.com_acc - m.gravity);
  ws.b.head<3>() = std::sqrt(p.w_force) * F_des;
  ws.b.tail<3>() = std::sqrt(p.w_moment) * in.momentum_rate;
  ws.beta.setZero(K);
  if (K > 0) {
    ws.HQ1.noalias() = H.selfadjointView<Eigen::Upper>() * Q1;
    ws.Q.noalias() = Q1.transpose() * ws.HQ1;
    ws.Q.noalias() += ws.A.transpose() * ws.A;
    ws.Q = 0.5 * (ws.Q + ws.Q.transpose()).eval();
    ws.w.noalias() = H.selfadjointView<Eigen::Upper>() * q0;
    ws.w -= ws.g;
    ws.q.noalias() = ws.A.transpose() * ws.b;
    ws.q.noalias() -= Q1.transpose() * ws.w;
    // Joint torques priced too (minimum effort): tau_joints = T1 beta + t0 is affine in beta like qacc. Without it
    // the torques are free in the plan, and a body touching the crates at several links (a knee and a foot) could be
    // planned with large opposing contact forces (the ridge alone let a knee landing ask 38 kN m: walk seed 6,
    // root assist on, 192 s, the simulation then diverged).
    if (p.w_torque > 0.0 && n > 6) {
      const int nj = n - 6;
      ws.T1.noalias() = M.bottomRows(nj) * Q1;
      ws.T1 -= ws.G.bottomRows(nj);
      ws.t0.noalias() = M.bottomRows(nj) * q0;
      for (int k = 0; k < nj; ++k) {
        const int dof = b0 + 6 + k;
        const auto& body = m.bodies[m.dof_body[dof]];
        ws.T1.row(k) += body.armature * Q1.row(6 + k);
        ws.t0[k] += body.armature * q0[6 + k] + ws.c_full[dof] + body.damping * d.v[dof];
      }
      ws.Q.noalias() += p.w_torque * ws.T1.transpose() * ws.T1;
      ws.q.noalias() -= p.w_torque * ws.T1.transpose() * ws.t0;
    }
    const double reg = (nc > 0 ? p.reg_beta * ws.Q.diagonal().head(4 * nc).mean() : 0.0) + 1e-12;
    ws.Q.diagonal().array() += reg;
    ws.Q.diagonal().tail(na).array() += p.w_root_assist;
    nnls(ws.Q, ws.q, ws, ws.beta);
    // The torque limit: where the plan asks for more, the assist's price goes up until the plan fits the limit (the
    // smallest price found that does, by factors of 10 then bisection in log price), so the plan is made within the
    // limit rather than clipped after it (a clipped plan's body misses its accelerations; clipping alone: walk 60 s
    // at price 0.3, rms 58 N m and falls where it clipped).
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
    out.tau[k] += body.armature * out.qacc[k] + ws.c_full[dof] + body.damping * d.v[dof];
  }
  // The root rows are the assist's generalised force (J_root^T [tau_a; 0]), zero when off; after a clamp the root
  // gets the clamped torque and the body falls short of qacc there.
  ws.tau_assist.setZero(6);
  if (na > 0) {
    ws.tau_assist = (ws.G.topRows(6).rightCols(na) * ws.beta.tail(na)) * scale;
    out.root_residual = (out.tau.head<6>() - ws.tau_assist / scale).norm();
    out.tau.head<6>() = ws.tau_assist;
  } else {
    out.root_residual = out.tau.head<6>().norm();
    out.tau.head<6>().setZero();  // the floating base is unactuated
  }
}

}  // namespace eng::control
