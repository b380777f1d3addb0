#pragma once
// Multibody model: a kinematic tree of rigid bodies connected by joints (reduced coordinates), plus
// collision geoms and solver options. Featherstone RBDA Ch. 4 (model description: parent array lambda,
// X_tree, joint types) with MuJoCo's free-joint coordinate convention.
//
// CONVENTIONS
//  * World is Z-up, gravity (0,0,-9.81). bodies[0] is the static world (no joint, no DoF).
//  * Bodies are added in topological order: parent index < own index.
//  * Body frame: at q = 0 the body frame is X_tree expressed in the parent body's frame. The joint
//    origin is the body origin. com and inertia are in the body frame (inertia about the com).
//  * Joint coordinates (q index q_index, size nq; velocity index v_index, size nv):
//      Free : q = [p_world(3), quat w,x,y,z (4)] (body pose in WORLD; parent must be the world),
//             v = [linear velocity of the body origin in WORLD (3), angular velocity in BODY frame (3)]
//             (MuJoCo convention). nq = 7, nv = 6.
//      Ball : q = quat (w,x,y,z) of the body relative to X_tree, v = angular velocity in the body frame.
//             nq = 4, nv = 3.
//      Hinge: q = angle about `axis` (body frame), v = rate. nq = nv = 1.
//      Fixed: nq = nv = 0 (welded with X_tree).
//  * Per-DoF passive terms: damping (N m s/rad, or N s/m for free linear DoFs), armature (added to
//    the diagonal of M), stiffness (spring toward Data::spring_ref, default the rest pose q = 0 /
//    identity quat; ball uses the rotation vector).
//    Damping and stiffness are integrated implicitly (see step.h).
//  * Limits: hinge [lower, upper] (rad) when limited; ball swing cone half-angle swing_limit and twist
//    about the body Z axis |twist| <= twist_limit (rad, 0 = no limit). Free: no limits.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/physics/collision.h"
#include "engine/physics/types.h"

namespace eng::physics {

enum class JointType : uint8_t { Free, Ball, Hinge, Fixed };

struct Body {
  std::string name;
  int parent = 0;  // 0 = world
  JointType joint = JointType::Fixed;
  Pose X_tree;                   // body frame at q = 0, in the parent body's frame
  Vec3 axis = Vec3::UnitZ();     // hinge axis in the body frame (unit)
  double mass = 0.0;
  Vec3 com = Vec3::Zero();       // body frame
  Mat3 inertia = Mat3::Zero();   // about the com, body frame
  double damping = 0.0;          // per DoF
  double armature = 0.0;         // per DoF
  double stiffness = 0.0;        // spring toward Data::spring_ref (default rest), per DoF
  bool limited = false;          // hinge range
  double lower = 0.0, upper = 0.0;              // hinge limits (rad)
  double swing_limit = 0.0, twist_limit = 0.0;  // ball limits (rad), 0 = none; twist about body Z
  // Soft joint speed limit (rad/s; 0 = none). Past it the joint gets the implicit damping that brings its rate (a
  // ball: its angular velocity's norm) back to max_speed within the step when nothing else acts (step.h,
  // mass_matrix): D = M_kk / dt (|v| / max_speed - 1) on each of its DoFs, M_kk the DoF's diagonal of M. A passive
  // damper, so the contact solve sees it (a clamp after the solve pushed feet through the floor) and it only takes
  // energy. As PhysX's articulation maxJointVelocity or Jolt's max angular velocity: a guard that keeps a limb from
  // whipping faster than a body can (a limp arm flung by a strong drag), nothing a controller should meet.
  double max_speed = 0.0;
  // filled by Model::finalize()
  int q_index = 0, v_index = 0, nq = 0, nv = 0;
  int root = 0;  // articulation root body (child of the world); 0 for the world itself
};

struct Geom {
  Shape shape;
  int body = 0;   // 0 = static world geom (floor plane, crates)
  Pose local;     // geom frame in the body frame (for body 0: in the world)
  double friction = 0.8;  // Coulomb mu; a pair uses sqrt(mu_a * mu_b)
  // Newton restitution e (0 = no bounce, the default); a pair uses max(e_a, e_b), only for contacts approaching
  // faster than SolverOptions::restitution_threshold (step.h: the contact row's velocity target)
  double restitution = 0.0;
  uint32_t group = 1, mask = 0xffffffffu;  // pair collides iff (a.group & b.mask) && (b.group & a.mask)
  bool self_collide = true;  // two geoms of one articulation collide only if both have self_collide
};

enum class FrictionModel : uint8_t { Pyramid, Cone };

// Solver options. Soft constraints follow Box2D v3's "soft step" (Catto, "Solver2D", 2024):
// a constraint row behaves like a spring-damper of frequency `hertz` and `damping_ratio`, expressed
// as bias rate / mass scale / impulse scale so it is stable for any dt. See step.h.
struct SolverOptions {
  int iterations = 16;                  // PGS sweeps (warm started)
  double contact_hertz = 30.0;          // contact / limit softness (clamped to 0.25 / dt)
  double contact_damping_ratio = 10.0;  // heavily over-damped: no bounce, calm separation
  double limit_hertz = 60.0;            // joint limit softness
  double limit_damping_ratio = 5.0;
  double max_depenetration_speed = 0.5;  // m/s (and rad/s for limits) cap on position-correction bias
  double contact_margin = 0.04;         // speculative contact distance (m) given to the narrowphase
  FrictionModel friction = FrictionModel::Cone;
  bool warm_start = true;
  double regularization = 1e-3;  // added to each row's J M^-1 J^T (1/kg): bounds degenerate rows
  double restitution_threshold = 1.0;  // m/s: slower impacts do not bounce (Box2D's default), so objects settle
  int max_contacts = 512;  // capacity preallocated in make_data; extra contacts are dropped
};

struct Model {
  std::vector<Body> bodies;  // bodies[0] = static world (created by the constructor)
  std::vector<Geom> geoms;
  Vec3 gravity{0.0, 0.0, -9.81};
  double dt = 1.0 / 240.0;
  SolverOptions solver;
  // a contact begin (Data::contact_begin) whose approach speed exceeds this also gives a hit event, m/s
  double hit_event_threshold = 0.05;
  int nq = 0, nv = 0;
  // filled by finalize(): per velocity DoF, its body and its parent DoF in the tree (-1 = none),
  // i.e. Featherstone's lambda(i) expanded to DoFs (RBDA Sec. 6.5, eq. 6.21)
  std::vector<int> dof_body, dof_parent;
  std::vector<int> dof_anc_begin, dof_anc;  // CSR: ancestors of DoF i (nearest first), for solves
  std::vector<int> body_last_dof;  // per body: its last DoF, or its nearest ancestor's (-1 = none)
  // Independent DoF blocks: M is block diagonal over them (one block per articulation, or the union of
  // articulations whose DoF index ranges interleave). block_begin has nblocks + 1 entries (last = nv);
  // dof_block[i] = block of DoF i. Every block is closed under dof_parent, so solves can be restricted
  // to a block (or to any contiguous run of blocks). Constraint rows and the step work per block.
  std::vector<int> block_begin, dof_block;
  bool finalized = false;

  Model();
  int add_body(const Body& b);  // returns the body index; parent must already exist
  int add_geom(const Geom& g);  // returns the geom index
  void finalize();              // fills indices (q_index, v_index, nq, nv, root, dof arrays)
};

}  // namespace eng::physics
