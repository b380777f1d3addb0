#pragma once
// Time stepping. step() = step1() + step2() (as MuJoCo's mj_step1 / mj_step2), each a list of stages,
// every stage a free function (also callable on its own):
//
//   step1 (position stage; reads q, v):
//     forward_kinematics -> collide -> compute_constraints -> mass_matrix -> compute_bias
//   -- control may run here: it reads the step1 outputs below, writes tau / applied forces / spring_ref /
//      point_springs --
//   step2 (velocity stage; reads tau, applied forces, spring_ref, point_springs):
//     passive_forces -> unconstrained_velocity -> point_spring_constraints -> solve_constraints
//     (prepare_constraints -> warm_start -> solve_pgs -> store_impulses -> contact_events) -> integrate
// (The game still calls step() after its control: control then sees the LAST step's contacts. Running
// control between step1 and step2 shows it this step's contacts instead: a behaviour change.)
//
// STATE AFTER step1 (q, v, time unchanged): d.x / com_world / v_body / cdof / cdof_dot / cinert for the
// current q, v; d.contacts of the current q (with warm-start impulses of the last step) and their
// constraint rows (J; soft parameters come in solve_constraints' prepare stage); d.M_crba = M(q) (CRBA
// only), d.qfrc_bias = c(q, v) without applied forces, d.M = M_crba + armature + dt D + dt^2 K, d.LD its
// factor, d.bias = qfrc_bias. Anything that changes q or v between step1 and step2 makes these stale.
// STATE AFTER step2 / step(): q, v, time advanced; d.x / contacts / M ... are still those of the START of
// the step (as in MuJoCo's mj_step); call forward_kinematics(m, d) (or step1) if poses must match the new
// q. d.bias = the c actually used (with the applied forces). step() is bit-for-bit step1 + step2.
//
// FORMULATION (and why)
//  * Velocity-level, semi-implicit Euler (as Box2D, Bullet, PhysX, MuJoCo's Euler integrator):
//      (M + A + dt*D + dt^2*K) (v+ - v) = dt (tau - c - D v - K (q + dt v)) + J^T lambda
//    Joint damping D and springs K are implicit (added to the matrix), armature A on the diagonal,
//    so arbitrarily high damping / stiff servos are stable at 240 Hz.
//  * M is built by CRBA and factorised by the tree-sparse L^T D L (RBDA 6.5); the unconstrained
//    velocity v_free and the rows M^-1 J^T come from sparse solves; the Delassus diagonal
//    J M^-1 J^T is used by the solver.
//  * Constraints (contact normal + 2 friction rows, hinge / ball swing / ball twist limits) are solved
//    by projected Gauss-Seidel on impulses, warm started from the previous step (contacts matched by
//    (geom_a, geom_b, feature)). Each row keeps v consistent: v += (M^-1 J^T)_i dlambda_i.
//    M is block diagonal over independent articulations (Model::block_begin): each row stores
//    M^-1 J^T only over its DoF range [j_begin, j_end) and every solver pass is restricted to it, so
//    N articulations in one Model cost N times one (and evolve exactly as each would alone).
//  * Soft constraints use Box2D v3's soft step (Catto 2024, "Solver2D"): with omega = 2 pi hertz,
//    zeta = damping ratio, h = dt:  a1 = 2 zeta + h omega, a2 = h omega a1, a3 = 1/(1 + a2),
//    bias_rate = omega / a1, mass_scale = a2 a3, impulse_scale = a3, and
//    dlambda = -mass_scale * m_eff * (J v + bias) - impulse_scale * lambda,
//    bias = max(bias_rate * C, -max_depenetration_speed) for penetration C < 0 and C / h for a
//    speculative gap C > 0. Why: it is the implicit spring-damper (same family as MuJoCo's solref
//    timeconst/dampratio) but in a PGS-friendly impulse form, unconditionally stable, no tuning per
//    mass, and the push-out speed is capped so overlapping limbs separate calmly. No restitution.
//  * Each row's Delassus diagonal gets + solver.regularization (constraint force mixing, as MuJoCo's
//    R) so rows the DoFs can barely move (normal through joint axes) stay bounded.
//  * Per contact the (normal, t1, t2) rows are solved as one block: one pass for the three J v, the
//    normal update, the tangents corrected by J_t M^-1 J_n^T dlambda_n, one pass updating v.
//  * Friction: Coulomb, per contact two tangent rows; Cone (default) projects the tangential impulse
//    onto the disk |lambda_t| <= mu lambda_n, Pyramid clamps each row.
//  * Point springs (Box2D v3's mouse joint): 3 world-axis rows at the point, one block with the point's
//    inverse effective mass K = J M^-1 J^T (pseudo-inverse K^+: only directions the point can move),
//    the same soft step with the spring's hertz / damping ratio, m_eff = K^+, the accumulated impulse
//    clamped to max_force * dt. With the exact K this is implicit Euler of the spring-damper for any
//    mass (point_spring_test).
//  * Contact events (data.h): the touching geom pairs of this step against the last one's (begin / end)
//    and hit events for fast begins, from the solved contacts; approach speed from the velocities at
//    the start of the step.
//  * Quaternions are integrated on the manifold q <- q * exp(w_body dt / 2) and renormalised.
#include "engine/physics/data.h"
#include "engine/physics/model.h"

namespace eng::physics {

// Wall time of the step's stages (milliseconds, ADDED by every step given it; the caller resets), for profiling:
// step1 / step2 / step fill it when passed a non-null pointer and read no clock otherwise. The stages partition the
// step (engine/core/stage_laps.h), so they add up to its whole time. Reporting only: the step never reads it.
struct StageTimes {
  double collision = 0.0;    // collide: geom poses, AABBs, broadphase, narrowphase, warm-start matching
  double dynamics = 0.0;     // forward_kinematics, mass_matrix (CRBA + LTDL factor), compute_bias (RNEA),
                             // passive_forces, unconstrained_velocity (c with applied forces, the sparse solve)
  double solver = 0.0;       // compute_constraints + point_spring_constraints (rows, J) and solve_constraints
                             // (M^-1 J^T, Delassus, warm start, PGS, impulses stored, contact events)
  double integration = 0.0;  // integrate: q on the manifold, time
  double total() const { return collision + dynamics + solver + integration; }
};

void step(const Model& m, Data& d, StageTimes* profile = nullptr);   // = step1 + step2
// kinematics, contacts, rows, M, its factor, c(q, v)
void step1(const Model& m, Data& d, StageTimes* profile = nullptr);
// passive forces, v_free, constraint solve, integrate
void step2(const Model& m, Data& d, StageTimes* profile = nullptr);

// pipeline stages
void collide(const Model& m, Data& d);              // fills d.contacts (needs forward_kinematics)
// building blocks of collide(), public for custom contact sources / tests:
void begin_contacts(Data& d);  // d.prev_contacts <- d.contacts (for warm start), d.contacts cleared
// appends a contact (geom ids filled; bodies from the geoms), warm-started from the previous step's
// contact with the same (geom_a, geom_b, feature). Returns false when max_contacts is reached.
bool add_contact(const Model& m, Data& d, const ContactPoint& cp);
void compute_constraints(const Model& m, Data& d);  // rows, J, bias and soft params
// step1: d.M_crba = crba(); d.speed_damping (Body::max_speed); d.M = M_crba + armature + dt (D + speed damping)
// + dt^2 K; d.LD = factor_ltdl(d.M)
void mass_matrix(const Model& m, Data& d);
// step1: d.qfrc_bias = rigid_bias_forces() (no applied forces); d.bias = d.qfrc_bias
void compute_bias(const Model& m, Data& d);
void passive_forces(const Model& m, Data& d);       // d.passive = -(D + speed damping) v - K (q + dt v)
// step2: d.bias = c with the current applied forces; v_free = v + dt M^-1 (tau + passive - bias); qacc
void unconstrained_velocity(const Model& m, Data& d);
void forward_dynamics(const Model& m, Data& d);     // mass_matrix + compute_bias + unconstrained_velocity
// step2: rows for the active Data::point_springs (3 per spring, appended after compute_constraints'
// rows; the point and target as they are now, the kinematics of step1). Inactive springs: force = 0.
void point_spring_constraints(const Model& m, Data& d);
// step2: the constraint solve, Box2D v3's stages in order: prepare_constraints -> warm_start ->
// solve_pgs -> store_impulses. v_free -> d.v; contact impulses / forces; qacc.
void solve_constraints(const Model& m, Data& d);
//   prepare: d.v = v_free (d.vtmp = v at the start); soft params (bias, mass/impulse scale) from each
//   row's C; W = M^-1 J^T per row (packed over its DoF range); Delassus diagonal; friction coupling
void prepare_constraints(const Model& m, Data& d);
//   warm start: last step's impulses clamped into the feasible set, applied: v += W lambda
void warm_start(const Model& m, Data& d);
//   solve: solver.iterations projected Gauss-Seidel sweeps (soft step, Coulomb cone / pyramid)
void solve_pgs(const Model& m, Data& d);
//   store impulses: contact normal / friction impulses (next step's warm start) and forces; qacc;
//   then contact_events
void store_impulses(const Model& m, Data& d);
// d.contact_begin / contact_end / hit_events from d.contacts (after the solve) and the touching pairs
// of the previous call (d.touching -> d.prev_touching). See data.h (ContactEvent, HitEvent).
void contact_events(const Model& m, Data& d);
void integrate(const Model& m, Data& d);            // q += dt * v on the manifold; time += dt

// inputs (persist until clear_applied). apply_force_at_point uses d.com_world (last kinematics).
void apply_force_at_point(const Model& m, Data& d, int body, const Vec3& force_world,
                          const Vec3& point_world);
void apply_world_torque(Data& d, int body, const Vec3& torque_world);
// +torque on body, -torque on its parent (unless the parent is the world)
void apply_world_torque_with_reaction(const Model& m, Data& d, int body, const Vec3& torque_world);
void clear_applied(Data& d);

}  // namespace eng::physics
