#pragma once
// Rigid multibody dynamics in reduced (joint) coordinates. One free function per stage.
// References: Featherstone, "Rigid Body Dynamics Algorithms" (RBDA, 2008); MuJoCo docs "Computation".
//
// All spatial quantities are world-aligned and taken about the WORLD ORIGIN ("absolute coordinates",
// RBDA Sec. 2.11 / MuJoCo's cdof+cinert): motion [w; v_O], force [n_O; F]. With that choice the
// recursions need no X_parent transforms (X = 1) and every Jacobian column is a ready-made cdof.
//
// Equation of motion: M(q) qacc + c(q, v) = tau + J^T f, with c including gravity, Coriolis/centrifugal
// terms and the user's applied forces (applied_force/applied_torque, sign: they reduce c).
#include "engine/physics/data.h"
#include "engine/physics/model.h"

namespace eng::physics {

// Body poses, com, spatial velocities, cdof (S) and cdof_dot, world spatial inertias. RBDA Sec. 4.4.
void forward_kinematics(const Model& m, Data& d);

// rnea / bias_forces / crba take `const Data&` for the state but use Data's preallocated scratch
// arrays (ws_*, vtmp2) internally: no allocation, not re-entrant on the same Data.
// Recursive Newton-Euler, RBDA Table 5.1: tau_out = M qacc + c (gravity, Coriolis, applied forces).
// Requires forward_kinematics. tau_out must have size nv.
void rnea(const Model& m, const Data& d, const VecX& qacc, VecX& tau_out);
// Bias forces c = rnea(qacc = 0).
void bias_forces(const Model& m, const Data& d, VecX& c);
// The rigid-body part of c only: gravity + Coriolis/centrifugal, WITHOUT the applied forces
// (= bias_forces with applied_force/applied_torque all zero). What a balance QP's M qacc + c = tau + J^T f
// needs; step1() stores it in Data::qfrc_bias.
void rigid_bias_forces(const Model& m, const Data& d, VecX& c);
// Composite Rigid Body Algorithm, RBDA Table 6.2: joint-space inertia M (nv x nv, symmetric).
// (Only the rigid-body part; armature / implicit damping are added by the step.)
void crba(const Model& m, const Data& d, MatX& M);
// Articulated Body Algorithm, RBDA Table 7.1: qacc = M^-1 (tau - c). Uses d's workspace.
void aba(const Model& m, Data& d, const VecX& tau, VecX& qacc);

// Sparse L^T D L factorisation exploiting the branch-induced sparsity of M (RBDA Sec. 6.5, Table 6.3).
// LD holds L (unit lower, strict part) and D (diagonal) in place; M is not modified.
void factor_ltdl(const Model& m, const MatX& M, MatX& LD);
// Solve M x = b in place with the factor (RBDA eq. 6.25-6.27: x = L^-1 D^-1 L^-T b).
void solve_ltdl(const Model& m, const MatX& LD, double* x);
inline void solve_ltdl(const Model& m, const MatX& LD, VecX& x) { solve_ltdl(m, LD, x.data()); }
// Same for nrhs right-hand sides at once, stored DoF-major: X[i * ld + r] (i = DoF, r = rhs). The
// inner loop over r has no dependency chain, so this is much faster than nrhs single solves.
void solve_ltdl_multi(const Model& m, const MatX& LD, double* X, int nrhs, int ld);
// Same restricted to the DoFs [j_begin, j_end), which must be a union of whole DoF blocks
// (Model::block_begin); X[(i - j_begin) * ld + r] holds DoF i. Cost O((j_end - j_begin) * depth * nrhs).
void solve_ltdl_multi(const Model& m, const MatX& LD, double* X, int nrhs, int ld, int j_begin, int j_end);

// Jacobians (world frame). J is resized to the stated size (allocation outside the step is fine).
// point_jacobian: 3 x nv, d(point velocity)/dv for a point fixed to `body` at world_point.
void point_jacobian(const Model& m, const Data& d, int body, const Vec3& world_point, MatX& J);
// body_jacobian: 6 x nv, rows [angular (world); linear velocity of the body-fixed point (world)].
void body_jacobian(const Model& m, const Data& d, int body, const Vec3& world_point, MatX& J);
// Velocity of the point fixed to `body` that is at world_point now: v_body's linear part (the motion of the body-fixed
// point at the world origin) plus omega x world_point (Featherstone: a motion vector's shift of reference point).
inline Vec3 point_velocity(const Data& d, int body, const Vec3& world_point) {
  const Vec6& v = d.v_body[body];
  return v.tail<3>() + v.head<3>().cross(world_point);
}
// com of the subtree rooted at root_body (root_body = 0: everything).
Vec3 subtree_com(const Model& m, const Data& d, int root_body);
// 3 x nv Jacobian of subtree_com.
void com_jacobian(const Model& m, const Data& d, int root_body, MatX& J);
// Spatial momentum [angular about the world origin; linear], world frame, of the subtree.
Vec6 spatial_momentum(const Model& m, const Data& d, int root_body);
double kinetic_energy(const Model& m, const Data& d);    // 1/2 v^T M v (rigid part)
double potential_energy(const Model& m, const Data& d);  // gravity + joint springs

}  // namespace eng::physics
