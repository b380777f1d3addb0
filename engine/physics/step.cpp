// The step pipeline (see step.h for the formulation and why).
#include "engine/physics/step.h"

#include <algorithm>
#include <bit>
#include <cstdint>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "engine/core/stage_laps.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/spatial.h"
#include "engine/physics/broadphase.h"
#include "engine/physics/narrowphase.h"

namespace eng::physics {

namespace {

// Box2D v3 soft step coefficients (Catto, Solver2D 2024).
struct Softness {
  double bias_rate, mass_scale, impulse_scale;
};
inline Softness make_soft(double hertz, double zeta, double h) {
  if (hertz <= 0.0) return {0.0, 1.0, 0.0};
  const double omega = 2.0 * M_PI * hertz;
  const double a1 = 2.0 * zeta + h * omega;
  const double a2 = h * omega * a1;
  const double a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

inline void tangent_basis(const Vec3& n, Vec3& t1, Vec3& t2) {
  t1 = std::abs(n.x()) < 0.57 ? n.cross(Vec3::UnitX()) : n.cross(Vec3::UnitY());
  t1.normalize();
  t2 = n.cross(t1);
}

inline bool is_static(const Model& m, int body) { return m.body_last_dof[body] < 0; }

// Sparse J row of direction `dir` (world) at world point p: dir^T (J_p(b) - J_p(a)); entries are
// appended at d.J_idx/J_val[begin...]; returns the count.
inline int contact_row(const Model& m, Data& d, int ba, int bb, const Vec3& p, const Vec3& dir, int begin) {
  int n = 0;
  int* idx = d.J_idx.data() + begin;
  double* val = d.J_val.data() + begin;
  for (int k = m.body_last_dof[bb]; k >= 0; k = m.dof_parent[k]) {
    idx[n] = k;
    val[n++] = dir.dot(lin(d.cdof[k]) + ang(d.cdof[k]).cross(p));
  }
  for (int k = m.body_last_dof[ba]; k >= 0; k = m.dof_parent[k]) {
    idx[n] = k;
    val[n++] = -dir.dot(lin(d.cdof[k]) + ang(d.cdof[k]).cross(p));
  }
  return n;
}

// DoF range of a row touching bodies ba, bb: the span of their DoF blocks (empty for static bodies).
inline void row_range(const Model& m, int ba, int bb, ConstraintRow& r) {
  int jb = m.nv, je = 0;
  for (const int b : {ba, bb}) {
    const int k = m.body_last_dof[b];
    if (k < 0) continue;
    const int blk = m.dof_block[k];
    jb = std::min(jb, m.block_begin[blk]);
    je = std::max(je, m.block_begin[blk + 1]);
  }
  if (je <= jb) jb = je = 0;
  r.j_begin = jb;
  r.j_end = je;
}

// sum val[k] * W[idx[k] - off]: sparse J row times a W stored from DoF `off`
inline double sparse_dot_off(const int* idx, const double* val, int n, const double* W, int off) {
  double s0 = 0.0, s1 = 0.0;
  int i = 0;
  for (; i + 1 < n; i += 2) {
    s0 += val[i] * W[idx[i] - off];
    s1 += val[i + 1] * W[idx[i + 1] - off];
  }
  if (i < n) s0 += val[i] * W[idx[i] - off];
  return s0 + s1;
}

inline double sparse_dot(const int* idx, const double* val, int n, const double* x) {
  double s0 = 0.0, s1 = 0.0;  // two chains: halves the FP-add latency (fixed order: deterministic)
  int i = 0;
  for (; i + 1 < n; i += 2) {
    s0 += val[i] * x[idx[i]];
    s1 += val[i + 1] * x[idx[i + 1]];
  }
  if (i < n) s0 += val[i] * x[idx[i]];
  return s0 + s1;
}

inline void axpy_n(double s, const double* x, double* y, int n) {
  for (int i = 0; i < n; ++i) y[i] += s * x[i];
}

}  // namespace

void begin_contacts(Data& d) {
  std::swap(d.contacts, d.prev_contacts);  // swaps buffers: capacities are kept, no allocation
  d.contacts.clear();
  d.warm_cursor = 0;
}

bool add_contact(const Model& m, Data& d, const ContactPoint& cp) {
  if (static_cast<int>(d.contacts.size()) >= m.solver.max_contacts) return false;
  Contact c;
  c.point = cp;
  c.body_a = m.geoms[cp.geom_a].body;
  c.body_b = m.geoms[cp.geom_b].body;
  // warm start: match last step's contact by (geom_a, geom_b, feature). Both lists come in the same
  // deterministic (pair-sorted) order, so the scan resumes after the previous match and wraps around:
  // O(1) per contact when the contact set is stable (a full scan from 0 would be O(contacts^2) per step).
  const int np = static_cast<int>(d.prev_contacts.size());
  for (int s = 0; s < np; ++s) {
    int k = d.warm_cursor + s;
    if (k >= np) k -= np;
    const Contact& pc = d.prev_contacts[k];
    if (pc.point.geom_a == cp.geom_a && pc.point.geom_b == cp.geom_b && pc.point.feature == cp.feature) {
      c.normal_impulse = pc.normal_impulse;
      c.friction_impulse = pc.friction_impulse;
      d.warm_cursor = k + 1 < np ? k + 1 : 0;
      break;
    }
  }
  d.contacts.push_back(c);
  return true;
}

void collide(const Model& m, Data& d) {
  begin_contacts(d);
  const int ng = static_cast<int>(m.geoms.size());
  const double margin = m.solver.contact_margin;
  for (int g = 0; g < ng; ++g) {
    const Geom& G = m.geoms[g];
    d.geom_x[g] = d.x[G.body] * G.local;
    d.aabbs[g] = shape_aabb(G.shape, d.geom_x[g], margin);
  }
  broadphase_pairs(d.aabbs.data(), d.geom_fixed.data(), ng, d.pairs);
  for (const auto& pr : d.pairs) {
    const Geom& ga = m.geoms[pr.first];
    const Geom& gb = m.geoms[pr.second];
    const int ba = ga.body, bb = gb.body;
    if (ba == bb) continue;                                  // never the same body
    if (is_static(m, ba) && is_static(m, bb)) continue;      // never two static geoms
    // never parent/child (the world is not a "parent" here: bodies jointed to it still hit static geoms)
    if ((bb > 0 && m.bodies[ba].parent == bb) || (ba > 0 && m.bodies[bb].parent == ba)) continue;
    if (!((ga.group & gb.mask) && (gb.group & ga.mask))) continue;
    const int ra = m.bodies[ba].root, rb = m.bodies[bb].root;
    if (ra == rb && ra != 0 && !(ga.self_collide && gb.self_collide)) continue;
    const int np = collide_shapes(ga.shape, d.geom_x[pr.first], gb.shape, d.geom_x[pr.second], margin,
                                  d.cp_tmp.data(), 4);
    for (int k = 0; k < np; ++k) {
      ContactPoint cp = d.cp_tmp[k];
      cp.geom_a = pr.first;
      cp.geom_b = pr.second;
      if (!add_contact(m, d, cp)) return;
    }
  }
}

namespace {

// Appends constraint rows to d.rows, each with its run of sparse Jacobian entries (d.J_idx / d.J_val from nz on).
struct RowWriter {
  Data& d;
  int nz = 0;  // next free sparse entry
  void add_row(ConstraintRow r, int count) {
    r.nz_begin = nz;
    r.nz_count = count;
    nz += count;
    d.rows.push_back(r);
  }
  void add_unit_row(ConstraintRow r, int dof, double value) {
    d.J_idx[nz] = dof;
    d.J_val[nz] = value;
    add_row(r, 1);
  }
};

// Each contact's normal row and its two friction rows (warm-started from the contact's stored impulses).
void add_contact_rows(const Model& m, Data& d, RowWriter& w) {
  const bool warm = m.solver.warm_start;
  for (int ci = 0; ci < static_cast<int>(d.contacts.size()); ++ci) {
    Contact& c = d.contacts[ci];
    const Vec3& n = c.point.normal;
    const Vec3& p = c.point.position;
    Vec3 t1, t2;
    tangent_basis(n, t1, t2);
    ConstraintRow rn;
    rn.kind = ConstraintRow::Normal;
    rn.contact = ci;
    rn.C = -c.point.depth;
    rn.lambda = warm ? c.normal_impulse : 0.0;
    row_range(m, c.body_a, c.body_b, rn);
    w.add_row(rn, contact_row(m, d, c.body_a, c.body_b, p, n, w.nz));
    const double mu = std::sqrt(m.geoms[c.point.geom_a].friction * m.geoms[c.point.geom_b].friction);
    const int first = static_cast<int>(d.rows.size());
    for (int k = 0; k < 2; ++k) {
      ConstraintRow rt;
      rt.kind = ConstraintRow::Friction;
      rt.contact = ci;
      rt.partner = first;
      rt.mu = mu;
      rt.j_begin = rn.j_begin;
      rt.j_end = rn.j_end;
      const Vec3& t = k == 0 ? t1 : t2;
      rt.lambda = warm ? c.friction_impulse.dot(t) : 0.0;
      w.add_row(rt, contact_row(m, d, c.body_a, c.body_b, p, t, w.nz));
    }
  }
}

// A ball joint's swing and twist limit rows, within `act` of the limit.
void add_ball_limit_rows(const Model& m, Data& d, RowWriter& w, size_t i, double act) {
  const Body& b = m.bodies[i];
  const Quat qr = quat_from(d.q.data() + b.q_index).normalized();
  const Mat3 R = qr.toRotationMatrix();
  if (b.swing_limit > 0) {
    // swing: angle between the body Z axis and the rest Z axis; d(theta)/dt = w_parent . nhat,
    // nhat = (ez x z)/|ez x z|, and w_parent = R w_body.
    const Vec3 z = R.col(2);
    const Vec3 axis = Vec3::UnitZ().cross(z);
    const double s = axis.norm();
    const double theta = std::atan2(s, z.z());
    const double C = b.swing_limit - theta;
    if (C < act && s > 1e-9) {
      ConstraintRow r;
      r.kind = ConstraintRow::Limit;
      r.C = C;
      row_range(m, static_cast<int>(i), 0, r);
      const Vec3 jb = -(R.transpose() * (axis / s));
      for (int k = 0; k < 3; ++k) {
        d.J_idx[w.nz + k] = b.v_index + k;
        d.J_val[w.nz + k] = jb[k];
      }
      w.add_row(r, 3);
    }
  }
  if (b.twist_limit > 0) {
    // swing-twist decomposition q = swing * twist(about body Z); twist rate ~ w_body.z
    double tw = 2.0 * std::atan2(qr.z(), qr.w());
    if (tw > M_PI) tw -= 2.0 * M_PI;
    if (tw < -M_PI) tw += 2.0 * M_PI;
    const double C = b.twist_limit - std::abs(tw);
    if (C < act) {
      ConstraintRow r;
      r.kind = ConstraintRow::Limit;
      r.C = C;
      row_range(m, static_cast<int>(i), 0, r);
      w.add_unit_row(r, b.v_index + 2, tw >= 0 ? -1.0 : 1.0);
    }
  }
}

// Joint limits (RBDA-style unilateral constraints on joint coordinates).
void add_limit_rows(const Model& m, Data& d, RowWriter& w) {
  const double act = 0.2;  // activation distance (rad) for speculative limit rows
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    if (b.joint == JointType::Hinge && b.limited) {
      const double q = d.q[b.q_index];
      const double lo = q - b.lower, hi = b.upper - q;
      const bool use_lo = lo < hi;
      const double C = use_lo ? lo : hi;
      if (C > act) continue;
      ConstraintRow r;
      r.kind = ConstraintRow::Limit;
      r.C = C;
      row_range(m, static_cast<int>(i), 0, r);
      w.add_unit_row(r, b.v_index, use_lo ? 1.0 : -1.0);
    } else if (b.joint == JointType::Ball && (b.swing_limit > 0 || b.twist_limit > 0)) {
      add_ball_limit_rows(m, d, w, i, act);
    }
  }
}

}  // namespace

void compute_constraints(const Model& m, Data& d) {
  d.rows.clear();
  if (m.nv == 0) return;
  RowWriter w{d};
  add_contact_rows(m, d, w);
  add_limit_rows(m, d, w);
}

void point_spring_constraints(const Model& m, Data& d) {
  if (m.nv == 0) return;
  int nz = 0;  // next free sparse entry: after compute_constraints' rows
  if (!d.rows.empty()) nz = d.rows.back().nz_begin + d.rows.back().nz_count;
  for (int s = 0; s < kMaxPointSprings; ++s) {
    PointSpring& ps = d.point_springs[s];
    if (!ps.active || ps.body <= 0 || ps.body >= static_cast<int>(m.bodies.size()) || is_static(m, ps.body)) {
      ps.force.setZero();
      ps.impulse.setZero();
      continue;
    }
    // the point where the kinematics of step1 put it (start of the step)
    const Vec3 p = d.x[ps.body].R * ps.local_point + d.x[ps.body].p;
    const Vec3 err = p - ps.target;
    for (int k = 0; k < 3; ++k) {
      ConstraintRow r;
      r.kind = ConstraintRow::Spring;
      r.contact = s;
      r.C = err[k];
      r.lambda = m.solver.warm_start ? ps.impulse[k] : 0.0;
      row_range(m, 0, ps.body, r);
      r.nz_begin = nz;
      r.nz_count = contact_row(m, d, 0, ps.body, p, Vec3::Unit(k), nz);
      nz += r.nz_count;
      d.rows.push_back(r);
    }
  }
}

void passive_forces(const Model& m, Data& d) {
  const double h = m.dt;
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    for (int k = 0; k < b.nv; ++k)
      d.passive[b.v_index + k] = -(b.damping + d.speed_damping[b.v_index + k]) * d.v[b.v_index + k];
    if (b.stiffness > 0) {
      if (b.joint == JointType::Hinge) {
        const double e = d.q[b.q_index] - d.spring_ref[b.v_index];
        d.passive[b.v_index] -= b.stiffness * (e + h * d.v[b.v_index]);
      } else if (b.joint == JointType::Ball) {
        // error rotation (body frame): log(q_ref^-1 q)
        const Quat qref = quat_exp(d.spring_ref.segment<3>(b.v_index));
        const Vec3 rv = quat_log(qref.conjugate() * quat_from(d.q.data() + b.q_index));
        for (int k = 0; k < 3; ++k)
          d.passive[b.v_index + k] -= b.stiffness * (rv[k] + h * d.v[b.v_index + k]);
      }
    }
  }
}

void mass_matrix(const Model& m, Data& d) {
  if (m.nv == 0) return;
  const double h = m.dt;
  crba(m, d, d.M_crba);
  // M = M_crba + implicit terms. crba writes only the DoF blocks (zero elsewhere in both matrices), so
  // copying the blocks is the whole copy; the values are bit-for-bit those crba would write into M.
  for (size_t blk = 0; blk + 1 < m.block_begin.size(); ++blk) {
    const int b0 = m.block_begin[blk], nb = m.block_begin[blk + 1] - b0;
    d.M.block(b0, b0, nb, nb) = d.M_crba.block(b0, b0, nb, nb);
  }
  // implicit damping / springs and armature on the diagonal (see step.h)
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    const double add = b.armature + h * b.damping + h * h * b.stiffness;
    for (int k = 0; k < b.nv; ++k) d.M(b.v_index + k, b.v_index + k) += add;
    // The soft speed limit (Body::max_speed): for one DoF of inertia M_kk alone, (M_kk + h D) v+ = M_kk v gives
    // |v+| = max_speed exactly with D = M_kk / h (|v| / max_speed - 1). Written every step, 0 where there is no
    // limit: a limit turned off while the joint was past it leaves no stale damping in passive_forces.
    const bool capped = b.max_speed > 0.0 && (b.joint == JointType::Hinge || b.joint == JointType::Ball);
    const double s = capped ? d.v.segment(b.v_index, b.nv).norm() : 0.0;
    for (int k = 0; k < b.nv; ++k) {
      const int j = b.v_index + k;
      const double D = capped && s > b.max_speed ? d.M_crba(j, j) / h * (s / b.max_speed - 1.0) : 0.0;
      d.speed_damping[j] = D;
      d.M(j, j) += h * D;
    }
  }
  factor_ltdl(m, d.M, d.LD);
}

void compute_bias(const Model& m, Data& d) {
  if (m.nv == 0) return;
  rigid_bias_forces(m, d, d.qfrc_bias);
  d.bias = d.qfrc_bias;
}

namespace {
// true when every applied force / torque is +0.0 bit for bit (clear_applied's value): then
// bias_forces() = rigid_bias_forces() exactly (x - (+0) == x for every double x, including -0), so the
// second RNEA can be skipped without changing a bit.
bool no_applied(const Data& d) {
  for (size_t i = 0; i < d.applied_force.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (std::bit_cast<uint64_t>(d.applied_force[i][k]) != 0 || std::bit_cast<uint64_t>(d.applied_torque[i][k]) != 0)
        return false;
  return true;
}
}  // namespace

void unconstrained_velocity(const Model& m, Data& d) {
  if (m.nv == 0) return;
  const double h = m.dt;
  // c with the applied forces as they are now (written by control after step1)
  if (no_applied(d))
    d.bias = d.qfrc_bias;
  else
    bias_forces(m, d, d.bias);
  for (int k = 0; k < m.nv; ++k) d.v_free[k] = h * (d.tau[k] + d.passive[k] - d.bias[k]);
  solve_ltdl(m, d.LD, d.v_free);
  for (int k = 0; k < m.nv; ++k) {
    d.qacc[k] = d.v_free[k] / h;
    d.v_free[k] += d.v[k];
  }
}

void forward_dynamics(const Model& m, Data& d) {
  mass_matrix(m, d);
  compute_bias(m, d);
  unconstrained_velocity(m, d);
}

// ---- solve_constraints: Box2D v3's solver stages (prepare, warm start, solve, store impulses) ----

void prepare_constraints(const Model& m, Data& d) {
  const int nr = static_cast<int>(d.rows.size());
  const double h = m.dt;
  d.vtmp = d.v;  // velocity at the start of the step (for qacc)
  d.v = d.v_free;
  // Soft parameters from each row's position error C (Box2D v3 soft step, step.h). A unilateral row with
  // gap C > 0 (apart) is speculative: bias C / h lets it close exactly the gap in this step, rigidly;
  // C <= 0 (violated) is soft with its push-out speed capped.
  const SolverOptions& so = m.solver;
  const Softness cs = make_soft(std::min(so.contact_hertz, 0.25 / h), so.contact_damping_ratio, h);
  const Softness ls = make_soft(std::min(so.limit_hertz, 0.25 / h), so.limit_damping_ratio, h);
  const double vmax = so.max_depenetration_speed;
  for (int r = 0; r < nr; ++r) {
    ConstraintRow& row = d.rows[r];
    if (row.kind != ConstraintRow::Normal && row.kind != ConstraintRow::Limit) continue;
    const Softness& s = row.kind == ConstraintRow::Normal ? cs : ls;
    if (row.C > 0.0) {
      row.bias = row.C / h;
      row.mass_scale = 1.0;
      row.impulse_scale = 0.0;
    } else {
      row.bias = std::max(s.bias_rate * row.C, -vmax);
      row.mass_scale = s.mass_scale;
      row.impulse_scale = s.impulse_scale;
    }
  }
  // approach speed of each contact before the solve (for hit events): -J_n v at the start of the step
  for (int r = 0; r < nr; ++r) {
    ConstraintRow& row = d.rows[r];
    if (row.kind != ConstraintRow::Normal) continue;
    Contact& c = d.contacts[row.contact];
    c.approach_speed =
        -sparse_dot(d.J_idx.data() + row.nz_begin, d.J_val.data() + row.nz_begin, row.nz_count, d.vtmp.data());
    // Restitution as a velocity target (Catto, "Iterative Dynamics", GDC 2005): a fast approach leaves at
    // e times its speed, rigidly (J v = e * approach); slow contacts keep the soft row above so they settle.
    const double e = std::max(m.geoms[c.point.geom_a].restitution, m.geoms[c.point.geom_b].restitution);
    if (e > 0.0 && c.approach_speed > so.restitution_threshold && row.C <= c.approach_speed * h) {
      row.bias = std::min(row.bias, -e * c.approach_speed);
      row.mass_scale = 1.0;
      row.impulse_scale = 0.0;
    }
  }
  // Each row only reaches the DoFs of its block(s) [j_begin, j_end) (M is block diagonal over the
  // articulations), so W_r = M^-1 J_r^T is stored packed over that range and every pass below costs
  // O(range), not O(nv): N independent articulations cost N times one.
  size_t off = 0;
  for (int r = 0; r < nr; ++r) {
    ConstraintRow& row = d.rows[r];
    row.w_off = off;
    off += static_cast<size_t>(row.j_end - row.j_begin);
  }
  // M^-1 J^T: rows grouped by range (sorted by (j_begin, j_end, index): deterministic), one multi-RHS
  // block-restricted sparse solve per group (DoF-major scratch), then transposed so each row's W_r is
  // contiguous for the PGS updates; Delassus diagonal J_r W_r.
  int* order = d.row_order.data();
  for (int r = 0; r < nr; ++r) order[r] = r;
  std::sort(order, order + nr, [&](int x, int y) {
    const ConstraintRow& rx = d.rows[x];
    const ConstraintRow& ry = d.rows[y];
    if (rx.j_begin != ry.j_begin) return rx.j_begin < ry.j_begin;
    if (rx.j_end != ry.j_end) return rx.j_end < ry.j_end;
    return x < y;
  });
  double* X = d.MinvJT_T.data();
  for (int g0 = 0; g0 < nr;) {
    const int jb = d.rows[order[g0]].j_begin, je = d.rows[order[g0]].j_end;
    int g1 = g0 + 1;
    while (g1 < nr && d.rows[order[g1]].j_begin == jb && d.rows[order[g1]].j_end == je) ++g1;
    const int ng = g1 - g0, nb = je - jb;
    std::fill(X, X + static_cast<size_t>(nb) * ng, 0.0);
    for (int gi = 0; gi < ng; ++gi) {
      const ConstraintRow& row = d.rows[order[g0 + gi]];
      for (int k = 0; k < row.nz_count; ++k)
        X[static_cast<size_t>(d.J_idx[row.nz_begin + k] - jb) * ng + gi] += d.J_val[row.nz_begin + k];
    }
    if (nb > 0) solve_ltdl_multi(m, d.LD, X, ng, ng, jb, je);
    for (int gi = 0; gi < ng; ++gi) {
      ConstraintRow& row = d.rows[order[g0 + gi]];
      double* W = d.MinvJT.data() + row.w_off;
      for (int i = 0; i < nb; ++i) W[i] = X[static_cast<size_t>(i) * ng + gi];
      const double a =
          sparse_dot_off(d.J_idx.data() + row.nz_begin, d.J_val.data() + row.nz_begin, row.nz_count, W, jb);
      // a (Delassus diagonal) ~ 0 means the DoFs can barely move along this row (contact normal through
      // the joint axes): regularise (constraint force mixing, like MuJoCo's R) so the push-out impulse
      // and the velocity it injects stay bounded.
      row.inv_diag = a > 1e-12 ? 1.0 / (a + m.solver.regularization) : 0.0;
    }
    g0 = g1;
  }
  // Point springs (3 consecutive rows, equal sparse pattern and range): soft params from the spring's
  // own hertz / damping ratio (not clamped: the soft step is stable at any stiffness, and the bias is
  // not capped: max_force bounds it), K = J M^-1 J^T (3 x 3) and its pseudo-inverse. K is singular when
  // the body cannot move the point along some direction (a hinged link: only tangentially); K^+ gives
  // zero effective mass there, so the spring pushes only where the point can move (no impulse lost on
  // a joint's reaction, none reported as force).
  for (int r = 0; r < nr; ++r) {
    if (d.rows[r].kind != ConstraintRow::Spring) continue;
    const int si = d.rows[r].contact;
    const PointSpring& ps = d.point_springs[si];
    const Softness ss = make_soft(ps.hertz, ps.damping_ratio, h);
    Mat3 K;
    for (int a = 0; a < 3; ++a) {
      ConstraintRow& ra = d.rows[r + a];
      ra.bias = ss.bias_rate * ra.C;
      ra.mass_scale = ss.mass_scale;
      ra.impulse_scale = ss.impulse_scale;
      for (int b = 0; b < 3; ++b) {
        const ConstraintRow& rb = d.rows[r + b];
        K(a, b) = sparse_dot_off(d.J_idx.data() + ra.nz_begin, d.J_val.data() + ra.nz_begin, ra.nz_count,
                                 d.MinvJT.data() + rb.w_off, rb.j_begin);
      }
    }
    K = 0.5 * (K + K.transpose()).eval();
    const Eigen::SelfAdjointEigenSolver<Mat3> es(K);
    const Vec3 ev = es.eigenvalues();
    const double tol = 1e-9 * std::max(ev.cwiseAbs().maxCoeff(), 1e-300);
    Vec3 inv_ev;
    for (int k = 0; k < 3; ++k) inv_ev[k] = ev[k] > tol ? 1.0 / ev[k] : 0.0;
    d.spring_K[si] = K;
    d.spring_Kpinv[si] = es.eigenvectors() * inv_ev.asDiagonal() * es.eigenvectors().transpose();
    r += 2;
  }
  // Friction rows: coupling J_t M^-1 J_n^T with their normal row, so the fused contact block in
  // solve_pgs is exactly Gauss-Seidel order n -> t1 -> t2.
  for (int r = 0; r < nr; ++r) {
    ConstraintRow& row = d.rows[r];
    if (row.kind == ConstraintRow::Friction) {
      const ConstraintRow& rn = d.rows[row.partner - 1];
      row.coupling = sparse_dot_off(d.J_idx.data() + row.nz_begin, d.J_val.data() + row.nz_begin,
                                    row.nz_count, d.MinvJT.data() + rn.w_off, rn.j_begin);
    }
  }
}

void warm_start(const Model& m, Data& d) {
  const int nr = static_cast<int>(d.rows.size());
  // clamp last step's impulses into the current feasible set, then apply them: v += W lambda
  for (int r = 0; r < nr; ++r) {
    ConstraintRow& row = d.rows[r];
    if (row.kind == ConstraintRow::Spring) {
      // last impulse projected on the directions the point can move (K^+ K), capped at max_force dt
      const int si = row.contact;
      Vec3 l(row.lambda, d.rows[r + 1].lambda, d.rows[r + 2].lambda);
      l = d.spring_Kpinv[si] * (d.spring_K[si] * l);
      const double lmax = d.point_springs[si].max_force * m.dt;
      if (l.squaredNorm() > lmax * lmax) l *= lmax / l.norm();
      for (int k = 0; k < 3; ++k) d.rows[r + k].lambda = l[k];
      r += 2;
    } else if (row.kind != ConstraintRow::Friction) {
      row.lambda = std::max(row.lambda, 0.0);
    } else if (row.partner == r) {
      ConstraintRow& r2 = d.rows[r + 1];
      const double bound = row.mu * d.rows[r - 1].lambda;
      const double nrm = std::sqrt(row.lambda * row.lambda + r2.lambda * r2.lambda);
      if (nrm > bound && nrm > 0) {
        row.lambda *= bound / nrm;
        r2.lambda *= bound / nrm;
      }
    }
  }
  for (int r = 0; r < nr; ++r) {
    const ConstraintRow& row = d.rows[r];
    if (row.lambda != 0.0)
      axpy_n(row.lambda, d.MinvJT.data() + row.w_off, d.v.data() + row.j_begin, row.j_end - row.j_begin);
  }
}

namespace {

// One projected Gauss-Seidel update of a joint limit row (lambda >= 0), v updated by the change.
inline void solve_limit_row(Data& d, ConstraintRow& row, double* v) {
  const int* ji = d.J_idx.data() + row.nz_begin;
  const double* jx = d.J_val.data() + row.nz_begin;
  const double* W = d.MinvJT.data() + row.w_off;
  const int nb = row.j_end - row.j_begin;
  double* vb = v + row.j_begin;
  const double jv = sparse_dot(ji, jx, row.nz_count, v);
  const double dl = -row.inv_diag * row.mass_scale * (jv + row.bias) - row.impulse_scale * row.lambda;
  const double nl = std::max(row.lambda + dl, 0.0);
  if (nl != row.lambda) axpy_n(nl - row.lambda, W, vb, nb);  // inactive speculative rows: no pass
  row.lambda = nl;
}

// Box2D v3 mouse joint as a 3-row block (rows r, r+1, r+2): lambda += -mass_scale K^+ (J v + bias) - impulse_scale
// lambda, then |lambda| <= max_force dt (the accumulated impulse is clamped, as Box2D does).
inline void solve_spring_block(const Model& m, Data& d, int r, double* v) {
  ConstraintRow& row = d.rows[r];
  const int* ji = d.J_idx.data() + row.nz_begin;
  const double* jx = d.J_val.data() + row.nz_begin;
  const double* W = d.MinvJT.data() + row.w_off;
  const int nb = row.j_end - row.j_begin;
  double* vb = v + row.j_begin;
  const int si = row.contact;
  ConstraintRow& r1 = d.rows[r + 1];
  ConstraintRow& r2 = d.rows[r + 2];
  const int cnt = row.nz_count;
  const Vec3 jv(sparse_dot(ji, jx, cnt, v), sparse_dot(ji, d.J_val.data() + r1.nz_begin, cnt, v),
                sparse_dot(ji, d.J_val.data() + r2.nz_begin, cnt, v));
  const Vec3 l0(row.lambda, r1.lambda, r2.lambda);
  const Vec3 rhs = jv + Vec3(row.bias, r1.bias, r2.bias);
  Vec3 l = l0 - row.mass_scale * (d.spring_Kpinv[si] * rhs) - row.impulse_scale * l0;
  const double lmax = d.point_springs[si].max_force * m.dt;
  if (l.squaredNorm() > lmax * lmax) l *= lmax / l.norm();
  const Vec3 dl = l - l0;
  row.lambda = l[0];
  r1.lambda = l[1];
  r2.lambda = l[2];
  const double* W1 = W + nb;
  const double* W2 = W1 + nb;
  for (int i = 0; i < nb; ++i) vb[i] += dl[0] * W[i] + dl[1] * W1[i] + dl[2] * W2[i];
}

// A contact's normal row r followed by its two friction rows: one fused pass for the three J.v products, the normal
// update, the tangent updates corrected by the normal's effect (J_t . W_n, precomputed: exactly Gauss-Seidel order
// n -> t) within the friction cone (or box), and one fused pass updating v.
inline void solve_contact_block(Data& d, int r, bool cone, double* v) {
  ConstraintRow& row = d.rows[r];
  const int* ji = d.J_idx.data() + row.nz_begin;
  const double* jx = d.J_val.data() + row.nz_begin;
  const double* W = d.MinvJT.data() + row.w_off;
  const int nb = row.j_end - row.j_begin;
  double* vb = v + row.j_begin;
  ConstraintRow& f1 = d.rows[r + 1];
  ConstraintRow& f2 = d.rows[r + 2];
  const double* jx1 = d.J_val.data() + f1.nz_begin;
  const double* jx2 = d.J_val.data() + f2.nz_begin;
  const int cnt = row.nz_count;
  const double jn = sparse_dot(ji, jx, cnt, v);
  const double dl = -row.inv_diag * row.mass_scale * (jn + row.bias) - row.impulse_scale * row.lambda;
  const double nl = std::max(row.lambda + dl, 0.0);
  const double dn = nl - row.lambda;
  row.lambda = nl;
  // nl == 0 (separated / speculative contact): the friction bound is 0, so both tangents are 0
  // whatever J_t v is: skip their products.
  double l1 = 0.0, l2 = 0.0;
  if (nl > 0.0) {
    double j1 = 0.0, j2 = 0.0, j1b = 0.0, j2b = 0.0;  // 2 chains each
    int k = 0;
    for (; k + 1 < cnt; k += 2) {
      const double va = v[ji[k]], vb2 = v[ji[k + 1]];
      j1 += jx1[k] * va;
      j2 += jx2[k] * va;
      j1b += jx1[k + 1] * vb2;
      j2b += jx2[k + 1] * vb2;
    }
    if (k < cnt) {
      const double va = v[ji[k]];
      j1 += jx1[k] * va;
      j2 += jx2[k] * va;
    }
    j1 += j1b;
    j2 += j2b;
    j1 += f1.coupling * dn;
    j2 += f2.coupling * dn;
    const double bound = f1.mu * nl;
    l1 = f1.lambda - f1.inv_diag * j1;
    l2 = f2.lambda - f2.inv_diag * j2;
    if (cone) {
      const double n2 = l1 * l1 + l2 * l2;
      if (n2 > bound * bound) {  // sticking contacts skip the sqrt
        const double nrm = std::sqrt(n2);
        const double sc = nrm > 0 ? bound / nrm : 0.0;
        l1 *= sc;
        l2 *= sc;
      }
    } else {
      l1 = std::clamp(l1, -bound, bound);
      l2 = std::clamp(l2, -bound, bound);
    }
  }
  const double d1 = l1 - f1.lambda, d2 = l2 - f2.lambda;
  f1.lambda = l1;
  f2.lambda = l2;
  const double* W1 = W + nb;  // the contact's three rows are consecutive with equal ranges
  const double* W2 = W1 + nb;
  if (dn != 0.0 || d1 != 0.0 || d2 != 0.0)  // separated (speculative) contacts: no pass
    for (int i = 0; i < nb; ++i) vb[i] += dn * W[i] + d1 * W1[i] + d2 * W2[i];  // one pass over v
}

}  // namespace

void solve_pgs(const Model& m, Data& d) {
  const int nr = static_cast<int>(d.rows.size());
  const bool cone = m.solver.friction == FrictionModel::Cone;
  double* v = d.v.data();
  // Rows in order: a limit row alone; a spring's or a contact's three rows as one block.
  for (int it = 0; it < m.solver.iterations; ++it) {
    for (int r = 0; r < nr; ++r) {
      ConstraintRow& row = d.rows[r];
      if (row.kind == ConstraintRow::Limit) {
        solve_limit_row(d, row, v);
        continue;
      }
      if (row.kind == ConstraintRow::Spring)
        solve_spring_block(m, d, r, v);
      else
        solve_contact_block(d, r, cone, v);
      r += 2;
    }
  }
}

void store_impulses(const Model& m, Data& d) {
  const int nv = m.nv;
  const int nr = static_cast<int>(d.rows.size());
  // impulses back into the contacts: reported forces, and next step's warm start (add_contact)
  for (int r = 0; r < nr; ++r) {
    const ConstraintRow& row = d.rows[r];
    if (row.kind == ConstraintRow::Spring) {
      PointSpring& ps = d.point_springs[row.contact];
      ps.impulse = Vec3(row.lambda, d.rows[r + 1].lambda, d.rows[r + 2].lambda);
      ps.force = ps.impulse / m.dt;
      r += 2;
      continue;
    }
    if (row.kind != ConstraintRow::Normal) continue;
    Contact& c = d.contacts[row.contact];
    Vec3 t1, t2;
    tangent_basis(c.point.normal, t1, t2);
    c.normal_impulse = row.lambda;
    c.friction_impulse = d.rows[r + 1].lambda * t1 + d.rows[r + 2].lambda * t2;
    c.force = (row.lambda * c.point.normal + c.friction_impulse) / m.dt;
  }
  for (int k = 0; k < nv; ++k) d.qacc[k] = (d.v[k] - d.vtmp[k]) / m.dt;
  contact_events(m, d);
}

namespace {
bool pair_less(const HitEvent& x, const HitEvent& y) {
  return x.geom_a != y.geom_a ? x.geom_a < y.geom_a : x.geom_b < y.geom_b;
}
bool same_pair(const HitEvent& x, const HitEvent& y) { return x.geom_a == y.geom_a && x.geom_b == y.geom_b; }
// x absorbs y (same pair): impulses add, the faster-approaching point wins
void merge_touch(HitEvent& x, const HitEvent& y) {
  x.impulse += y.impulse;
  if (y.approach_speed > x.approach_speed) {
    x.approach_speed = y.approach_speed;
    x.point = y.point;
    x.normal = y.normal;
  }
}
ContactEvent pair_of(const HitEvent& t) { return {t.geom_a, t.geom_b, t.body_a, t.body_b}; }
}  // namespace

void contact_events(const Model& m, Data& d) {
  d.contact_begin.clear();
  d.contact_end.clear();
  d.hit_events.clear();
  std::swap(d.touching, d.prev_touching);  // buffers swap: no allocation
  d.touching.clear();
  // touching geom pairs of this step, one entry per pair (collide emits a pair's points consecutively and
  // pairs in sorted order; other contact sources are sorted and merged below)
  for (const Contact& c : d.contacts) {
    if (!is_touching(c)) continue;
    HitEvent t;
    t.geom_a = c.point.geom_a;
    t.geom_b = c.point.geom_b;
    t.body_a = c.body_a;
    t.body_b = c.body_b;
    t.point = c.point.position;
    t.normal = c.point.normal;
    t.approach_speed = c.approach_speed;
    t.impulse = c.normal_impulse;
    if (!d.touching.empty() && same_pair(d.touching.back(), t))
      merge_touch(d.touching.back(), t);
    else
      d.touching.push_back(t);
  }
  if (!std::is_sorted(d.touching.begin(), d.touching.end(), pair_less)) {
    std::sort(d.touching.begin(), d.touching.end(), pair_less);
    size_t w = 0;
    for (size_t i = 1; i < d.touching.size(); ++i) {
      if (same_pair(d.touching[w], d.touching[i]))
        merge_touch(d.touching[w], d.touching[i]);
      else
        d.touching[++w] = d.touching[i];
    }
    if (!d.touching.empty()) d.touching.resize(w + 1);
  }
  // sorted merge of this step's and the last step's touching pairs: new ones begin, missing ones end
  size_t i = 0, j = 0;
  const size_t ni = d.touching.size(), nj = d.prev_touching.size();
  while (i < ni || j < nj) {
    if (j == nj || (i < ni && pair_less(d.touching[i], d.prev_touching[j]))) {
      const HitEvent& t = d.touching[i++];
      d.contact_begin.push_back(pair_of(t));
      if (t.approach_speed > m.hit_event_threshold) d.hit_events.push_back(t);
    } else if (i == ni || pair_less(d.prev_touching[j], d.touching[i])) {
      d.contact_end.push_back(pair_of(d.prev_touching[j++]));
    } else {
      ++i, ++j;
    }
  }
}

void solve_constraints(const Model& m, Data& d) {
  if (m.nv == 0) return;
  prepare_constraints(m, d);
  warm_start(m, d);
  solve_pgs(m, d);
  store_impulses(m, d);
}

void integrate(const Model& m, Data& d) {
  const double h = m.dt;
  for (size_t i = 1; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    double* q = d.q.data() + b.q_index;
    const double* v = d.v.data() + b.v_index;
    switch (b.joint) {
      case JointType::Free: {
        for (int k = 0; k < 3; ++k) q[k] += h * v[k];
        const Quat r = (quat_from(q + 3) * quat_exp(h * Vec3(v[3], v[4], v[5]))).normalized();
        quat_store(r, q + 3);
        break;
      }
      case JointType::Ball: {
        const Quat r = (quat_from(q) * quat_exp(h * Vec3(v[0], v[1], v[2]))).normalized();
        quat_store(r, q);
        break;
      }
      case JointType::Hinge: q[0] += h * v[0]; break;
      case JointType::Fixed: break;
    }
  }
  d.time += h;
}

// Each stage's lap goes to its StageTimes field (step.h); with no profile the laps read no clock.
void step1(const Model& m, Data& d, StageTimes* profile) {
  eng::core::StageLaps<StageTimes> laps(profile);
  d.contact_begin.clear();  // events are per step (filled again by store_impulses)
  d.contact_end.clear();
  d.hit_events.clear();
  forward_kinematics(m, d);
  laps.lap(&StageTimes::dynamics);
  collide(m, d);
  laps.lap(&StageTimes::collision);
  compute_constraints(m, d);
  laps.lap(&StageTimes::solver);
  mass_matrix(m, d);
  compute_bias(m, d);
  laps.lap(&StageTimes::dynamics);
}

void step2(const Model& m, Data& d, StageTimes* profile) {
  eng::core::StageLaps<StageTimes> laps(profile);
  passive_forces(m, d);
  unconstrained_velocity(m, d);
  laps.lap(&StageTimes::dynamics);
  point_spring_constraints(m, d);
  solve_constraints(m, d);
  laps.lap(&StageTimes::solver);
  integrate(m, d);
  laps.lap(&StageTimes::integration);
}

void step(const Model& m, Data& d, StageTimes* profile) {
  step1(m, d, profile);
  step2(m, d, profile);
}

void apply_force_at_point(const Model& m, Data& d, int body, const Vec3& f, const Vec3& p) {
  d.applied_force[body] += f;
  d.applied_torque[body] += (p - d.com_world[body]).cross(f);
}

void apply_world_torque(Data& d, int body, const Vec3& t) { d.applied_torque[body] += t; }

void apply_world_torque_with_reaction(const Model& m, Data& d, int body, const Vec3& t) {
  d.applied_torque[body] += t;
  const int p = m.bodies[body].parent;
  if (p > 0) d.applied_torque[p] -= t;
}

void clear_applied(Data& d) {
  for (auto& f : d.applied_force) f.setZero();
  for (auto& t : d.applied_torque) t.setZero();
}

}  // namespace eng::physics
