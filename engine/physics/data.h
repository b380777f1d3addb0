#pragma once
// Simulation state + preallocated workspace. All arrays are sized by make_data(); step() performs
// no heap allocation once the capacities (contacts, broadphase pairs) have been reached.
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "engine/physics/collision.h"
#include "engine/physics/model.h"
#include "engine/physics/broadphase.h"
#include "engine/physics/types.h"

namespace eng::physics {

struct Contact {
  ContactPoint point;       // geom ids filled; normal from a to b (world)
  int body_a = 0, body_b = 0;
  Vec3 force = Vec3::Zero();  // world force on b from the last solve (a gets -force), N
  double normal_impulse = 0.0;  // N s, last solve
  Vec3 friction_impulse = Vec3::Zero();  // world tangential impulse on b (warm start), N s
  // relative normal speed of the two bodies at the point at the START of the step (before this step's
  // forces and the solve), m/s, > 0 approaching: -n . (v_b(p) - v_a(p)). Set by prepare_constraints.
  double approach_speed = 0.0;
};

// "Touching" (for contact events): the contact overlaps (depth >= kTouchDepth) or the solver pushed
// (normal impulse > 0; a speculative contact the bodies would have closed this step). A contact with a
// gap and no impulse is only speculative: not touching.
inline constexpr double kTouchDepth = 0.0;  // m
inline bool is_touching(const Contact& c) { return c.point.depth >= kTouchDepth || c.normal_impulse > 0.0; }

// Contact events are per GEOM PAIR (a body with several geoms can touch one object with several pairs);
// geom_a < geom_b as in Contact, normal from a to b. Box2D v3's begin / end touch and hit events as
// arrays filled by the solver (store_impulses), no callbacks.
struct ContactEvent {
  int geom_a = 0, geom_b = 0, body_a = 0, body_b = 0;
};
struct HitEvent {
  int geom_a = 0, geom_b = 0, body_a = 0, body_b = 0;
  Vec3 point = Vec3::Zero(), normal = Vec3::Zero();  // of the pair's touching point approaching fastest
  double approach_speed = 0.0;  // m/s, that point's Contact::approach_speed (> 0 approaching)
  double impulse = 0.0;         // N s, sum of the normal impulses over the pair's touching points
};

// A constraint row of the velocity-level solver (contact normal / friction, joint limit).
struct ConstraintRow {
  enum Kind : uint8_t { Normal, Friction, Limit, Spring } kind = Normal;
  int contact = -1;   // contact index (Normal / Friction), point spring index (Spring), -1 for limits
  int partner = -1;   // Friction: index of the other tangent row of the pair (first row of the pair)
  double C = 0.0;     // position error: gap (> 0 apart, < 0 violated) of a contact normal / limit row;
                      // Spring: (point - target) along the row's axis
  // soft parameters, set from C by solve_constraints' prepare stage (prepare_constraints)
  double bias = 0.0;  // target velocity term (J v + bias -> 0)
  double mass_scale = 1.0, impulse_scale = 0.0;  // Box2D v3 soft step
  double inv_diag = 0.0;  // 1 / ((J M^-1 J^T)_ii + solver.regularization)
  double lambda = 0.0;    // accumulated impulse
  double mu = 0.0;        // friction coefficient (Friction rows)
  double coupling = 0.0;  // Friction rows: J_t M^-1 J_n^T with the contact's normal row
  int nz_begin = 0, nz_count = 0;  // sparse J row: entries [nz_begin, nz_begin + nz_count) of J_idx/J_val
  // DoF range the row can affect: the DoF block(s) (Model::block_begin) of its body / bodies (for a
  // contact between two blocks, the span of both). J and W = M^-1 J^T are zero outside it, so W is
  // stored only over [j_begin, j_end), at MinvJT[w_off ...], and every solver pass is restricted to it.
  int j_begin = 0, j_end = 0;
  size_t w_off = 0;
};

// A point spring (Box2D v3's mouse joint): pulls the body-fixed point `local_point` (body frame) toward
// the world point `target` as a soft constraint of frequency `hertz` and damping ratio `damping_ratio`
// (Box2D v3 soft step on the 3 world-axis rows, with the point's true effective mass (J M^-1 J^T)^+,
// so the response is the same for any mass and implicit-stable), its impulse capped at max_force * dt.
// Solved inside step2 with the contacts (a drag that pushes a body into the floor is resisted).
struct PointSpring {
  // inputs (user-set; read by step2)
  int body = 0;
  Vec3 local_point = Vec3::Zero();  // body frame, m
  Vec3 target = Vec3::Zero();       // world, m
  double hertz = 5.0;               // Hz
  double damping_ratio = 0.7;
  double max_force = std::numeric_limits<double>::infinity();  // N
  bool active = false;
  // outputs of the last step (store_impulses); zero when inactive
  Vec3 force = Vec3::Zero();    // world force applied at the point over the step, N (= impulse / dt)
  Vec3 impulse = Vec3::Zero();  // N s (also the next step's warm start)
};
inline constexpr int kMaxPointSprings = 8;

struct Data {
  VecX q, v, qacc, tau;  // tau: joint torques, user-set, persistent until changed
  // Per-DoF reference of the implicit joint springs (Body::stiffness), user-set, default 0 = rest pose:
  // hinge: target angle; ball: target rotation vector (angle * axis, relative to X_tree); free: unused.
  // With stiffness + damping this is an unconditionally stable PD servo (integrated implicitly).
  VecX spring_ref;
  double time = 0.0;

  // kinematics (forward_kinematics)
  std::vector<Pose> x;            // world pose of each body frame
  std::vector<Vec3> com_world;    // world com of each body
  std::vector<Vec6> v_body;       // spatial velocity of each body, world coords at the world origin
  std::vector<Vec6> cdof;         // per DoF motion subspace column S (world coords, at the origin)
  std::vector<Vec6> cdof_dot;     // per DoF  d/dt S  (so c_i = sum cdof_dot * qdot, RBDA eq. 5.7 term)
  std::vector<Mat6> cinert;       // spatial inertia of each body (world coords, at the origin)

  // inputs
  std::vector<Vec3> applied_force, applied_torque;  // world, at the body's com; clear_applied()
  std::array<PointSpring, kMaxPointSprings> point_springs;  // set `active` to use one (see PointSpring)

  // contacts of the current step (and the previous one, for warm start)
  std::vector<Contact> contacts, prev_contacts;
  int warm_cursor = 0;  // add_contact: where the warm-start search in prev_contacts resumes

  // contact events of the last step (cleared by step1, filled by store_impulses; capacity
  // solver.max_contacts each, preallocated): geom pairs that started / stopped touching (is_touching)
  // this step, and a hit for each begin whose approach speed exceeds Model::hit_event_threshold.
  std::vector<ContactEvent> contact_begin, contact_end;
  std::vector<HitEvent> hit_events;
  // geom pairs touching after this / the last step, sorted by (geom_a, geom_b), with their hit data
  std::vector<HitEvent> touching, prev_touching;

  // ---- workspace (preallocated) ----
  std::vector<Vec6> ws_a, ws_f;         // spatial accelerations / forces per body
  std::vector<Mat6> ws_Ic;              // composite / articulated inertias per body
  std::vector<Vec6> ws_p;               // articulated bias forces per body
  std::vector<Mat6> ws_U, ws_Dinv;      // ABA: U = I^A S, D^-1 (top-left nd x nd) per body
  std::vector<Vec6> ws_u, ws_c;         // ABA: u = tau - S^T p^A, c = Sdot qdot per body
  // ---- filled by step1() (mass_matrix, compute_bias), for the state q, v at the START of the step ----
  // Physical quantities a controller (balance QP, inverse dynamics) reads between step1 and step2:
  MatX M_crba;     // joint-space inertia M(q) by CRBA only (no armature, no implicit terms), nv x nv;
                   // zero outside the DoF blocks (Model::block_begin)
  VecX qfrc_bias;  // c(q, v): gravity + Coriolis/centrifugal, WITHOUT applied forces (rigid_bias_forces)
  // What the step itself solves with:
  MatX M;          // M_crba + armature + dt D + dt^2 K (implicit damping / springs, step.h)
  MatX LD;         // LTDL factor of M (RBDA 6.5): strict lower L, diagonal D
  VecX bias;       // after step1: = qfrc_bias; after step2: c including the applied forces (what was used)
  VecX vtmp, vtmp2, v_free, passive;
  VecX speed_damping;  // per DoF: the soft speed limit's implicit damping this step (Body::max_speed; 0 below it)
  // constraint rows: J sparse (only ancestor DoFs of the two bodies are nonzero; an index may repeat
  // when the bodies share ancestors), M^-1 J^T dense over each row's [j_begin, j_end) (packed; capacity
  // max_rows x nv)
  std::vector<ConstraintRow> rows;
  // per point spring: K = J M^-1 J^T of its 3 rows and K^+ (pseudo-inverse), set by prepare_constraints
  std::array<Mat3, kMaxPointSprings> spring_K, spring_Kpinv;
  std::vector<int> row_order;    // scratch: rows grouped by DoF range for the multi-RHS solve
  std::vector<int> J_idx;
  std::vector<double> J_val, MinvJT;
  std::vector<double> MinvJT_T;  // DoF-major scratch for the multi-RHS solve of one row group
  int max_rows = 0;
  // collision workspace
  std::vector<Aabb> aabbs;
  std::vector<unsigned char> geom_fixed;  // 1 for a static geom (its body has no DoF): no pairs among these
  std::vector<Pose> geom_x;             // world pose of each geom
  std::vector<std::pair<int, int>> pairs;
  std::vector<ContactPoint> cp_tmp;
};

// Build the model (add_body/add_geom), finalize(), then make_data (throws if not finalized).
// q at rest: identity quats, zero angles, free bodies at their X_tree; v = 0.
Data make_data(const Model& m);

}  // namespace eng::physics
