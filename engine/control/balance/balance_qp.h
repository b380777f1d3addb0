#pragma once
// Balance QP: joint torques for one floating-base articulation that keep the ground reaction inside the
// support (centre of pressure within the contact polygon, every contact force inside its friction cone) while
// tracking as much of the desired motion as that allows.
//
// WHY. The world-space servo (eq. 3, as implicit joint springs) plus a PD shift of the desired root holds
// quiet stances and 150 N pushes, but a punch's whole-body motion (a 5 cm lunge with the arm thrown forward)
// asks the feet for a ground reaction the soles cannot give: the feet roll onto an edge, the legs leave the
// support path and the boxer falls (README). What the body needs is Kudoh's balance QP
// (thesis sec. 2.5: centre-of-mass acceleration as PD toward its target, ZMP kept in the support area, joint
// accelerations as the unknowns): find the accelerations the ground CAN support, closest to the desired ones.
//
// FORMULATION (one QP). Unknowns: qacc and, per contact point c (normal n_c on the body, friction mu),
//       f_c = sum_k beta_ck u_ck, beta >= 0,  u_ck = n_c +- mu t1_c, n_c +- mu t2_c   (inner friction pyramid)
// so any beta >= 0 is a force inside the cone and the centre of pressure inside the contact points' hull:
// Kudoh's ZMP constraint (2.39) for any polygon. Minimise
//       sum_i w_i |J_i qacc + Jdot_i v - a_i|^2 + eps |qacc|^2                      (tracking)
//     + w_F |sum f_c - F_des|^2 + w_N |sum (p_c - com) x f_c - N_des|^2 + eps' |beta|^2   (ground reaction)
// (a_i: each bone's desired world angular acceleration -- the inertial servo's eq. 3 as an acceleration --,
// point accelerations, e.g. a swing foot, heavily weighted, two points' relative acceleration along a normal (two
// legs kept apart), zero acceleration of every contact point, and, near a joint limit the step will enforce, the
// limit coordinate's acceleration back inside it (w_limit);
// F_des = m (a_com_des - g), Kudoh's com acceleration as a PD target; N_des the desired rate of the centroidal
// angular momentum) subject to, exactly,
//       M_root qacc + c_root = (J^T f)_root      (Newton-Euler of the whole body: the floating base is unactuated;
//                                                 with the root assist, + J_root^T [tau_a; 0], tau_a priced, below).
// SOLVE. For a given beta the best qacc solves the equality-constrained least squares through its KKT system,
// so qacc = q0 + Q1 beta (one LU, K + 1 right-hand sides). Substituted back, the problem in beta alone is a
// non-negative least squares, solved exactly by Lawson & Hanson's active set. Then tau = M qacc + c - J^T f; its
// root rows vanish by construction. Where the desired com acceleration is not admissible the solution trades it
// against tracking inside the cones (arms and trunk take up the angular momentum: Kudoh's arm swing and waist
// bend), and the torques never ask the feet to pull or slide. (One QP, not two stages -- reaction first,
// accelerations after, as Lee & Goswami --: a reaction chosen blind to the tracking makes the arms flail.)
//
// All quantities world frame; the articulation is a contiguous DoF block [dof_begin, dof_end) whose first six
// DoFs are the free root joint. Uses forward_kinematics results (x, com_world, v_body, cdof, cdof_dot).
#include <Eigen/Cholesky>
#include <vector>

#include "engine/physics/data.h"
#include "engine/physics/model.h"

namespace eng::control {

using physics::MatX;
using physics::Vec3;
using physics::Vec6;
using physics::VecX;

struct QpContact {
  int body = 0;
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit, the direction the ground pushes the body
  double mu = 0.6;
};

// Desired world angular acceleration of a body (rad/s^2), weight per (rad/s^2)^2.
struct QpAngularTask {
  int body = 0;
  Vec3 alpha = Vec3::Zero();
  double weight = 1.0;
};

// Desired classical acceleration of a point fixed to a body (m/s^2).
struct QpPointTask {
  int body = 0;
  Vec3 point = Vec3::Zero();
  Vec3 acc = Vec3::Zero();
  double weight = 1.0;
  // ref_body >= 0 (an ancestor of body, e.g. the root): the task is on the point's acceleration relative to ref_point
  // fixed to ref_body, acc = a_point - a_ref: a swing foot driven by its own leg. (On its world acceleration, with the
  // com priced low during a balance step, the plan carries the whole body after the foot.)
  int ref_body = -1;
  Vec3 ref_point = Vec3::Zero();
};

// Desired relative acceleration, along one direction, of two points fixed to two bodies of the articulation (m/s^2):
// normal . (a_b(point_b) - a_a(point_a)) = acc, one row. Neither body need be the other's ancestor (a left shank and a
// right one): the row spans the union of their chains' DoFs.
struct QpSeparationTask {
  int body_a = 0, body_b = 0;
  Vec3 point_a = Vec3::Zero(), point_b = Vec3::Zero();
  Vec3 normal = Vec3::UnitX();  // unit, from a toward b
  double acc = 0.0;
  double weight = 1.0;
};

struct BalanceQpInput {
  int dof_begin = 0, dof_end = 0;  // the articulation's DoFs (first six: the free root)
  int root_body = 0;               // its root body (subtree for com / momentum)
  Vec3 com_acc = Vec3::Zero();     // desired com acceleration (world, m/s^2)
  Vec3 momentum_rate = Vec3::Zero();  // desired rate of centroidal angular momentum (N m)
  std::vector<QpContact> contacts;
  std::vector<QpAngularTask> angular;
  std::vector<QpPointTask> points;
  std::vector<QpSeparationTask> separations;
  // Bodies whose joint limits the plan keeps off (BalanceQpParams::w_limit); empty: every joint of the articulation.
  std::vector<int> limit_bodies;
  void clear() {
    contacts.clear(), angular.clear(), points.clear(), separations.clear(), limit_bodies.clear();
  }
};

struct BalanceQpParams {
  double w_force = 1.0;     // weight on the net ground force error (per N^2)
  double w_moment = 1.0;    // weight on the ground moment error about the com (per (N m)^2)
  double reg_beta = 1e-6;   // ridge on beta relative to the reduced problem's mean diagonal (spreads the load)
  double reg_qacc = 1e-4;   // damping of qacc (per (unit acceleration)^2), keeps the KKT system regular
  double w_torque = 0.0;    // weight on the joint torques (per (N m)^2): minimum effort, bounds internal forces
  double w_hold = 1e4;      // weight of "contact points do not accelerate" (per (m/s^2)^2)
  double hold_damping = 20.0;  // 1/s: the held points' target acceleration is -hold_damping * their velocity
  // Joint limits (step1's limit rows: a ball joint's swing cone and twist, a hinge's range), which the step enforces
  // with an impulse the plan does not count on (docs/decisions/foot-slide.md). A joint within limit_margin of a limit
  // gets a task: its limit coordinate C accelerates at limit_kp (limit_margin - C) - limit_kd dC/dt.
  double w_limit = 0.0;        // per (rad/s^2)^2 (no task where that target is negative: moving off); 0 = off
  double limit_margin = 0.05;  // rad
  double limit_kp = 400.0;     // 1/s^2
  double limit_kd = 40.0;      // 1/s
  // Root assist (the paper's root spring, section V, torque limited) as an unknown of the QP: an external torque on
  // the root body, so the plan takes it only where the ground reaction cannot give the com and momentum targets.
  double w_root_assist = 0.0;      // per (N m)^2; 0 = off (the floating base unactuated)
  double max_root_assist = 100.0;  // N m (asked for more, the price is raised until it fits; a final clamp takes the rest)
};

struct BalanceQpResult {
  VecX qacc, tau;          // over the block (tau's first six: the root assist's generalised force, zero when off)
  Vec3 force = Vec3::Zero();   // planned net ground force (N)
  Vec3 moment = Vec3::Zero();  // planned moment about the com (N m)
  Vec3 cop = Vec3::Zero();     // planned centre of pressure (force-weighted contact point; com if no force)
  std::vector<Vec3> contact_force;  // per input contact
  Vec3 root_assist = Vec3::Zero();  // the root assist torque (world, N m; after the clamp), zero when off
  bool assist_clamped = false;      // even at the raised price the plan asked for more than max_root_assist
  // |tau_root - assist| (N, N m): how exactly the solve met the Newton-Euler rows (tau's root rows are the assist's
  // generalised force, zero when off)
  double root_residual = 0.0;
};

// Workspace: Eigen matrices with compile-time maximum sizes (storage inside the struct), so no solve allocates
// whatever the number of contacts (no per-tick allocation: tests/game/world_alloc_test.cpp). Limits: an
// articulation of at most kQpMaxDofs DoFs; contacts past kQpMaxContacts are left out of the plan (the first ones
// kept; a standing boxer has 8).
inline constexpr int kQpMaxDofs = 64;
inline constexpr int kQpMaxContacts = 30;  // Q (126 x 126) within Eigen's 128 KiB fixed-size limit
inline constexpr int kQpMaxUnknowns = 4 * kQpMaxContacts + 6;  // pyramid edges + the root assist's six
using QpMatNN = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kQpMaxDofs, kQpMaxDofs>;
using QpMatNK = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kQpMaxDofs, kQpMaxUnknowns + 1>;
using QpMatKK = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kQpMaxUnknowns, kQpMaxUnknowns>;
using QpMat6K = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kQpMaxUnknowns>;
using QpMat6N = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kQpMaxDofs>;
using QpMatN6 = Eigen::Matrix<double, Eigen::Dynamic, 6, 0, kQpMaxDofs, 6>;
using QpVecK = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kQpMaxUnknowns, 1>;
using QpVecN = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kQpMaxDofs, 1>;

struct BalanceQp {
  QpMat6N J;     // a task's Jacobian, compacted to its columns
  QpMat6N J_ref;              // a relative point task's reference Jacobian ...
  std::vector<int> cols_ref;  // ... and its columns
  QpMatNN H;
  QpMat6K A;     // the pyramid edges' wrench about the com
  QpMatNK G;     // generalised force of each pyramid edge (J_c^T u), n x K
  QpMatKK Q;     // the reduced problem in beta
  QpMatNK sol;   // [q0 Q1]: qacc = q0 + Q1 beta
  QpMatNK T1;    // joint torques as an affine function of beta: T1 beta + t0 (rows: joints)
  QpMatN6 HQ1;   // M_joints Y
  // the equality-constrained solve (range-space method): E = root rows of M, Y = H^-1 E^T, S = E Y, SF = S^-1 F
  QpMat6N E;
  QpMatN6 Y;
  Eigen::Matrix<double, 6, 6> S;
  QpMat6K SF;
  Eigen::Matrix<double, 6, 1> lambda;
  QpMatNN L_H;   // H's Cholesky factor (lower triangle; dense_cholesky)
  Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt_S;
  QpVecK beta, q, beta_fit, z, wk;  // wk: the NNLS gradient q - Q x
  QpVecN g, w, t0, tau_assist;
  QpVecN row;    // a separation task's row over the block
  Eigen::Matrix<double, 6, 1> b;
  std::vector<Vec3> basis;
  // the active-set NNLS in beta
  std::vector<int> passive;
  std::vector<char> in_passive;
  QpMatKK L;     // Cholesky factor of Q over the passive set (nnls)
  std::vector<int> warm;  // the last solve's passive set and its problem size (nnls warm start)
  int warm_K = -1;
  std::vector<int> cols;  // a task's Jacobian columns (block indices of its body's ancestor DoFs)
  BalanceQp() {
    basis.reserve(kQpMaxUnknowns), passive.reserve(kQpMaxUnknowns), in_passive.reserve(kQpMaxUnknowns);
    warm.reserve(kQpMaxUnknowns), cols.reserve(kQpMaxDofs);
  }
};

// Reads the articulation's blocks of d.M_crba and d.qfrc_bias: call it between physics::step1 and step2 (or after
// physics::mass_matrix + compute_bias at the current state), with the kinematics of the current q, v.
void balance_qp_solve(const physics::Model& m, const physics::Data& d, const BalanceQpInput& in,
                      const BalanceQpParams& p, BalanceQp& ws, BalanceQpResult& out);

// Helpers (also used by the tests). Velocity-product ("bias") accelerations with qacc = 0, world frame:
// a body's angular acceleration, and the classical acceleration of a point fixed to it.
Vec3 bias_angular_acceleration(const physics::Model& m, const physics::Data& d, int body);
Vec3 bias_point_acceleration(const physics::Model& m, const physics::Data& d, int body, const Vec3& point);

}  // namespace eng::control
