// Featherstone-style dynamics in world-aligned, origin-based spatial coordinates (see dynamics.h).
#include "engine/physics/dynamics.h"

#include <cmath>
#include <cstddef>

#include "engine/physics/spatial.h"

namespace eng::physics {

namespace {

// Spatial force of the user's applied force/torque (world, at the com): [T + c x F; F] about origin.
inline Vec6 applied_wrench(const Data& d, int i) {
  const Vec3& F = d.applied_force[i];
  return spatial(d.applied_torque[i] + d.com_world[i].cross(F), F);
}

inline Vec6 gravity_acc(const Model& m) { return spatial(Vec3::Zero(), -m.gravity); }  // RBDA 5.3

}  // namespace

void forward_kinematics(const Model& m, Data& d) {
  const int nb = static_cast<int>(m.bodies.size());
  d.x[0] = Pose{};
  d.v_body[0].setZero();
  d.com_world[0].setZero();
  d.cinert[0].setZero();
  for (int i = 1; i < nb; ++i) {
    const Body& b = m.bodies[i];
    const Pose& P = d.x[b.parent];
    const double* q = d.q.data() + b.q_index;
    Pose& X = d.x[i];
    switch (b.joint) {
      case JointType::Free: {
        X.R = quat_from(q + 3).normalized().toRotationMatrix();
        X.p = Vec3(q[0], q[1], q[2]);
        break;
      }
      case JointType::Ball: {
        const Pose Pt = P * b.X_tree;
        X.R = Pt.R * quat_from(q).normalized().toRotationMatrix();
        X.p = Pt.p;
        break;
      }
      case JointType::Hinge: {
        const Pose Pt = P * b.X_tree;
        X.R = Pt.R * Eigen::AngleAxisd(q[0], b.axis).toRotationMatrix();
        X.p = Pt.p;
        break;
      }
      case JointType::Fixed:
        X = P * b.X_tree;
        break;
    }
    d.com_world[i] = X.apply(b.com);
    d.cinert[i] = spatial_inertia(b.mass, d.com_world[i], X.R * b.inertia * X.R.transpose());
    // motion subspace columns S (RBDA Table 4.1) expressed in world coordinates at the origin:
    // a rotation about unit axis a through point o is [a; o x a]; a translation along e is [0; e].
    const Vec3& o = X.p;
    Vec6 vb = d.v_body[b.parent];
    const int v0 = b.v_index;
    if (b.joint == JointType::Free) {
      for (int k = 0; k < 3; ++k) {
        d.cdof[v0 + k] = spatial(Vec3::Zero(), Vec3::Unit(k));
        const Vec3 a = X.R.col(k);
        d.cdof[v0 + 3 + k] = spatial(a, o.cross(a));
      }
    } else if (b.joint == JointType::Ball) {
      for (int k = 0; k < 3; ++k) {
        const Vec3 a = X.R.col(k);
        d.cdof[v0 + k] = spatial(a, o.cross(a));
      }
    } else if (b.joint == JointType::Hinge) {
      const Vec3 a = X.R * b.axis;
      d.cdof[v0] = spatial(a, o.cross(a));
    }
    for (int k = 0; k < b.nv; ++k) vb += d.cdof[v0 + k] * d.v[v0 + k];  // v_i = v_p + S qdot (5.7)
    d.v_body[i] = vb;
    // Sdot: columns fixed in the body move with v_i (Sdot = v_i x S); the free joint's linear
    // columns are fixed in the world (Sdot = 0).
    for (int k = 0; k < b.nv; ++k) {
      if (b.joint == JointType::Free && k < 3)
        d.cdof_dot[v0 + k].setZero();
      else
        d.cdof_dot[v0 + k] = cross_motion(vb, d.cdof[v0 + k]);
    }
  }
}

// RNEA, RBDA Table 5.1 with X = 1 (absolute coordinates) and a_0 = -g (eq. 5.20 trick).
// kApplied = false leaves out the user's applied forces (rigid_bias_forces); the kApplied = true path is
// the original expression, unchanged.
template <bool kApplied>
void rnea_impl(const Model& m, const Data& d_in, const VecX& qacc, VecX& tau) {
  Data& d = const_cast<Data&>(d_in);  // workspace only (ws_a, ws_f); state untouched
  const int nb = static_cast<int>(m.bodies.size());
  d.ws_a[0] = gravity_acc(m);
  for (int i = 1; i < nb; ++i) {
    const Body& b = m.bodies[i];
    Vec6 a = d.ws_a[b.parent];
    for (int k = 0; k < b.nv; ++k) {
      const int j = b.v_index + k;
      a += d.cdof[j] * qacc[j] + d.cdof_dot[j] * d.v[j];
    }
    d.ws_a[i] = a;
    const Mat6& I = d.cinert[i];
    const Vec6& v = d.v_body[i];
    if constexpr (kApplied)
      d.ws_f[i] = I * a + cross_force(v, I * v) - applied_wrench(d, i);
    else
      d.ws_f[i] = I * a + cross_force(v, I * v);
  }
  for (int i = nb - 1; i >= 1; --i) {
    const Body& b = m.bodies[i];
    for (int k = 0; k < b.nv; ++k) tau[b.v_index + k] = d.cdof[b.v_index + k].dot(d.ws_f[i]);
    if (b.parent > 0) d.ws_f[b.parent] += d.ws_f[i];
  }
}

void rnea(const Model& m, const Data& d, const VecX& qacc, VecX& tau) { rnea_impl<true>(m, d, qacc, tau); }

void bias_forces(const Model& m, const Data& d, VecX& c) {
  Data& dd = const_cast<Data&>(d);
  dd.vtmp2.setZero();
  rnea(m, d, dd.vtmp2, c);
}

void rigid_bias_forces(const Model& m, const Data& d, VecX& c) {
  Data& dd = const_cast<Data&>(d);
  dd.vtmp2.setZero();
  rnea_impl<false>(m, d, dd.vtmp2, c);
}

// CRBA, RBDA Table 6.2 (X = 1): composite inertias, then M_kj = S_k . (Ic_i S_j) up the ancestor chain.
void crba(const Model& m, const Data& d_in, MatX& M) {
  Data& d = const_cast<Data&>(d_in);
  const int nb = static_cast<int>(m.bodies.size());
  for (int i = 0; i < nb; ++i) d.ws_Ic[i] = d.cinert[i];
  for (int i = nb - 1; i >= 1; --i) {
    const int p = m.bodies[i].parent;
    if (p > 0) d.ws_Ic[p] += d.ws_Ic[i];
  }
  // M is block diagonal over the DoF blocks (articulations): entries outside them are never written,
  // so a correctly sized M only needs its diagonal blocks cleared (O(sum block^2), not O(nv^2)).
  if (M.rows() != m.nv || M.cols() != m.nv) {
    M.setZero(m.nv, m.nv);
  } else {
    for (size_t b = 0; b + 1 < m.block_begin.size(); ++b) {
      const int b0 = m.block_begin[b], nb = m.block_begin[b + 1] - b0;
      M.block(b0, b0, nb, nb).setZero();
    }
  }
  for (int j = 0; j < m.nv; ++j) {
    const Vec6 F = d.ws_Ic[m.dof_body[j]] * d.cdof[j];
    for (int k = j; k >= 0; k = m.dof_parent[k]) {
      const double val = d.cdof[k].dot(F);
      M(k, j) = val;
      M(j, k) = val;
    }
  }
}

// ABA, RBDA Table 7.1 in absolute coordinates (X = 1, so the "I^a" and "p^a" pass to the parent
// unchanged). Joints have nd <= 6 DoFs: U = I^A S (6 x nd), D = S^T U, u = tau - S^T p^A.
void aba(const Model& m, Data& d, const VecX& tau, VecX& qacc) {
  const int nb = static_cast<int>(m.bodies.size());
  using Mat6N = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;
  using MatNN = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  using VecN = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
  for (int i = 1; i < nb; ++i) {  // pass 1: I^A = I, p^A = v x* I v - f_ext, c = Sdot qdot
    const Mat6& I = d.cinert[i];
    const Vec6& v = d.v_body[i];
    d.ws_Ic[i] = I;
    d.ws_p[i] = cross_force(v, I * v) - applied_wrench(d, i);
    Vec6 c = Vec6::Zero();
    const Body& b = m.bodies[i];
    for (int k = 0; k < b.nv; ++k) c += d.cdof_dot[b.v_index + k] * d.v[b.v_index + k];
    d.ws_c[i] = c;
  }
  for (int i = nb - 1; i >= 1; --i) {  // pass 2
    const Body& b = m.bodies[i];
    const int nd = b.nv;
    Mat6& IA = d.ws_Ic[i];
    Vec6& pA = d.ws_p[i];
    Mat6 Ia = IA;
    Vec6 pa = pA + IA * d.ws_c[i];
    if (nd > 0) {
      Mat6N S(6, nd);
      for (int k = 0; k < nd; ++k) S.col(k) = d.cdof[b.v_index + k];
      Mat6N U = IA * S;
      MatNN D = S.transpose() * U;
      MatNN Dinv = D.inverse();  // nd <= 6, fixed-capacity: no heap
      VecN u = tau.segment(b.v_index, nd) - S.transpose() * pA;
      d.ws_U[i].leftCols(nd) = U;
      d.ws_Dinv[i].topLeftCorner(nd, nd) = Dinv;
      d.ws_u[i].head(nd) = u;
      const Mat6N UD = U * Dinv;
      Ia.noalias() -= UD * U.transpose();
      pa = pA + Ia * d.ws_c[i] + UD * u;  // Table 7.1: p^a = p^A + I^a c + U D^-1 u
    }
    if (b.parent > 0) {
      d.ws_Ic[b.parent] += Ia;
      d.ws_p[b.parent] += pa;
    }
  }
  d.ws_a[0] = gravity_acc(m);
  for (int i = 1; i < nb; ++i) {  // pass 3
    const Body& b = m.bodies[i];
    const int nd = b.nv;
    Vec6 a = d.ws_a[b.parent] + d.ws_c[i];
    if (nd > 0) {
      const auto U = d.ws_U[i].leftCols(nd);
      VecN qdd = d.ws_Dinv[i].topLeftCorner(nd, nd) * (d.ws_u[i].head(nd) - U.transpose() * a);
      for (int k = 0; k < nd; ++k) {
        qacc[b.v_index + k] = qdd[k];
        a += d.cdof[b.v_index + k] * qdd[k];
      }
    }
    d.ws_a[i] = a;
  }
}

// RBDA Table 6.3: in-place L^T D L of the branch-sparse M (only ancestor entries are touched).
void factor_ltdl(const Model& m, const MatX& M, MatX& LD) {
  const int n = m.nv;
  if (LD.rows() != n || LD.cols() != n) LD.setZero(n, n);
  for (int k = 0; k < n; ++k)
    for (int i = k; i >= 0; i = m.dof_parent[i]) LD(k, i) = M(k, i);
  for (int k = n - 1; k >= 0; --k) {
    for (int i = m.dof_parent[k]; i >= 0; i = m.dof_parent[i]) {
      const double a = LD(k, i) / LD(k, k);
      for (int j = i; j >= 0; j = m.dof_parent[j]) LD(i, j) -= a * LD(k, j);
      LD(k, i) = a;
    }
  }
}

// RBDA Table 6.4 style solve of L^T D L x = b (ancestor lists from Model::dof_anc: no pointer chasing).
void solve_ltdl(const Model& m, const MatX& LD, double* x) {
  const int n = m.nv;
  const int* ab = m.dof_anc_begin.data();
  const int* an = m.dof_anc.data();
  const double* L = LD.data();  // column-major: L(i, j) = L[i + j n]
  for (int i = n - 1; i >= 0; --i) {  // x <- L^-T x
    const double xi = x[i];
    if (xi == 0.0) continue;  // sparse right-hand sides (constraint rows) stay sparse in this pass
    for (int k = ab[i]; k < ab[i + 1]; ++k) x[an[k]] -= L[i + an[k] * n] * xi;
  }
  for (int i = 0; i < n; ++i) x[i] /= L[i + i * n];  // x <- D^-1 x
  for (int i = 0; i < n; ++i) {  // x <- L^-1 x
    double xi = x[i];
    for (int k = ab[i]; k < ab[i + 1]; ++k) xi -= L[i + an[k] * n] * x[an[k]];
    x[i] = xi;
  }
}

void solve_ltdl_multi(const Model& m, const MatX& LD, double* X, int nrhs, int ld) {
  solve_ltdl_multi(m, LD, X, nrhs, ld, 0, m.nv);
}

void solve_ltdl_multi(const Model& m, const MatX& LD, double* X0, int nrhs, int ld, int j0, int j1) {
  const int n = m.nv;
  const int* ab = m.dof_anc_begin.data();
  const int* an = m.dof_anc.data();
  const double* L = LD.data();
  // row of DoF i: X0 + (i - j0) * ld (a block's ancestors stay inside [j0, j1))
  for (int i = j1 - 1; i >= j0; --i) {
    const double* xi = X0 + static_cast<ptrdiff_t>(i - j0) * ld;
    for (int k = ab[i]; k < ab[i + 1]; ++k) {
      const double l = L[i + static_cast<ptrdiff_t>(an[k]) * n];
      double* xj = X0 + static_cast<ptrdiff_t>(an[k] - j0) * ld;
      for (int r = 0; r < nrhs; ++r) xj[r] -= l * xi[r];
    }
  }
  for (int i = j0; i < j1; ++i) {
    const double dinv = 1.0 / L[i + static_cast<ptrdiff_t>(i) * n];
    double* xi = X0 + static_cast<ptrdiff_t>(i - j0) * ld;
    for (int r = 0; r < nrhs; ++r) xi[r] *= dinv;
  }
  for (int i = j0; i < j1; ++i) {
    double* xi = X0 + static_cast<ptrdiff_t>(i - j0) * ld;
    for (int k = ab[i]; k < ab[i + 1]; ++k) {
      const double l = L[i + static_cast<ptrdiff_t>(an[k]) * n];
      const double* xj = X0 + static_cast<ptrdiff_t>(an[k] - j0) * ld;
      for (int r = 0; r < nrhs; ++r) xi[r] -= l * xj[r];
    }
  }
}

void point_jacobian(const Model& m, const Data& d, int body, const Vec3& p, MatX& J) {
  J.setZero(3, m.nv);
  for (int k = m.body_last_dof[body]; k >= 0; k = m.dof_parent[k])
    J.col(k) = lin(d.cdof[k]) + ang(d.cdof[k]).cross(p);  // v_p = v_O + w x p
}

void body_jacobian(const Model& m, const Data& d, int body, const Vec3& p, MatX& J) {
  J.setZero(6, m.nv);
  for (int k = m.body_last_dof[body]; k >= 0; k = m.dof_parent[k]) {
    J.block<3, 1>(0, k) = ang(d.cdof[k]);
    J.block<3, 1>(3, k) = lin(d.cdof[k]) + ang(d.cdof[k]).cross(p);
  }
}

namespace {
inline bool in_subtree(const Model& m, int body, int root) {
  if (root == 0) return body != 0;
  for (int b = body; b > 0; b = m.bodies[b].parent)
    if (b == root) return true;
  return false;
}
}  // namespace

Vec3 subtree_com(const Model& m, const Data& d, int root) {
  double mass = 0.0;
  Vec3 c = Vec3::Zero();
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    if (!in_subtree(m, static_cast<int>(i), root)) continue;
    mass += m.bodies[i].mass;
    c += m.bodies[i].mass * d.com_world[i];
  }
  return mass > 0 ? Vec3(c / mass) : c;
}

void com_jacobian(const Model& m, const Data& d, int root, MatX& J) {
  J.setZero(3, m.nv);
  double mass = 0.0;
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    if (!in_subtree(m, static_cast<int>(i), root)) continue;
    const double mi = m.bodies[i].mass;
    mass += mi;
    const Vec3& c = d.com_world[i];
    for (int k = m.body_last_dof[i]; k >= 0; k = m.dof_parent[k])
      J.col(k) += mi * (lin(d.cdof[k]) + ang(d.cdof[k]).cross(c));
  }
  if (mass > 0) J /= mass;
}

Vec6 spatial_momentum(const Model& m, const Data& d, int root) {
  Vec6 h = Vec6::Zero();
  for (size_t i = 1; i < m.bodies.size(); ++i)
    if (in_subtree(m, static_cast<int>(i), root)) h += d.cinert[i] * d.v_body[i];  // h = I v (2.71)
  return h;
}

double kinetic_energy(const Model& m, const Data& d) {
  double T = 0.0;
  for (size_t i = 1; i < m.bodies.size(); ++i) T += 0.5 * d.v_body[i].dot(d.cinert[i] * d.v_body[i]);
  return T;
}

double potential_energy(const Model& m, const Data& d) {
  double U = 0.0;
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    U -= b.mass * m.gravity.dot(d.com_world[i]);
    if (b.stiffness > 0) {
      const bool has_ref = d.spring_ref.size() == m.nv;
      if (b.joint == JointType::Hinge) {
        const double e = d.q[b.q_index] - (has_ref ? d.spring_ref[b.v_index] : 0.0);
        U += 0.5 * b.stiffness * e * e;
      }
      if (b.joint == JointType::Ball) {
        const Quat qref = has_ref ? quat_exp(d.spring_ref.segment<3>(b.v_index)) : Quat::Identity();
        U += 0.5 * b.stiffness * quat_log(qref.conjugate() * quat_from(d.q.data() + b.q_index)).squaredNorm();
      }
    }
  }
  return U;
}

}  // namespace eng::physics
