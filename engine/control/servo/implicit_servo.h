#pragma once
// Eq. 3 of Jenkins, Wrotek & McGuire written as an IMPLICIT joint spring-damper, rooted at the support.
//
// WHY. Applied explicitly (+tau on bone i, -tau on its parent), eq. 3's damping k2 (omega_d - omega_a) with k2
// scaled by a heavy subtree reacts on a light parent (abdomen servo, I ~ 4 kg m^2, on the pelvis, I ~ 0.1):
// k2 dt / I_parent >> 1 and the explicit loop diverges at 240 Hz for omega_n >~ 14 even without gravity; the
// single-body "stable PD" divisor (1 + 2 zeta omega_n dt) does not see the parent. And with every servo torque
// internal and the feet leaves of the tree, the only torque that reaches the ground is the foot servo's, whose
// error is ~0 while the foot lies flat: nothing resists toppling about the ankles.
//
// WHAT. The torque eq. 3 puts on a joint is a function of ONE bone's world orientation error. Holding the
// other bone of the joint at its actual orientation, the same torque is the joint spring
//   tau = K (q_ref - q) + D (v_ref - v),   q_ref: the joint rotation that puts the controlled bone at W_d,
//                                          v_ref: the relative rate that gives it omega_d,
// to first order identical to eq. 3's spring (K = k1), but the engine integrates it implicitly
// (dt D + dt^2 K on M's diagonal, Data::spring_ref). The velocity target is folded into the spring reference
// (shift (D/K + dt) v_ref), so only Body::stiffness/damping (set once at build time) and spring_ref (per tick)
// are needed. DEVIATION from eq. 3's damper: v_ref = the DESIRED relative rate (omega_d[i] - omega_d[parent]),
// i.e. the damper acts on the joint's relative velocity only (fully implicit). Eq. 3's remainder
// k2 (omega_d[parent] - omega_a[parent]) would be explicit on the (often light) other bone -- the instability
// of the explicit servo (abdomen servo on the 0.1 kg m^2 pelvis) -- and is dropped. The spring still reads the
// other bone's ACTUAL orientation (explicit, position level): loop gain K dt^2 / I_other, which bounds omega_n
// (~25 rad/s for the abdomen on the pelvis; the game default is 15).
//
// SUPPORT PATH. Eq. 3 rooted at the pelvis leaves the ankle unactuated (see above). For a leg whose foot is
// planted, the joints are servoed from the ground up: joint i (between parent p and bone i on the path
// pelvis -> foot) controls the world orientation of the bone ABOVE it (the parent p: shank over the ankle,
// thigh over the knee, pelvis over the hip) with the reaction on bone i. The servo law (eq. 3) is unchanged;
// only which side of the joint it measures changes, exactly as if the tree were rooted at the foot. The ankle
// then holds the shank upright in world space against the whole body's weight: balance with no root help.
// A support hip's twist about the thigh axis (the leg's swivel) keeps the free-bone law (thigh from the actual
// pelvis): otherwise only the planted foot's torsional grip resists it and the feet spin on the crates.
// LATERAL BALANCE. With every support joint controlling the bone above it, a sideways sway of both legs with the
// pelvis kept level (the parallelogram ground - leg - pelvis - leg) changes no servoed world orientation except the
// shanks', so only the ankles' roll resists it, and a 10 cm wide sole takes ~Fn x 5 cm before it rolls onto its
// edge. A support hip's ROLL (ab/adduction, bone x axis) therefore also keeps the free-bone law (free_roll): the
// hips then hold the legs' sideways lean against the pelvis (hip strategy: load moves between the legs); without
// it the ankles' roll alone holds the sway and the world and person servos let the boxer fall sideways.
// PLANTED TWIST. The contacts have no torsional friction: a full-strength twist on a planted foot spins it on its
// crate. The planted ankle's twist (foot z) error is scaled by twist_scale (game: 0.6; much less lets the body
// creep round on its feet until it falls, full strength spins the foot).
// The game switches a leg to the support law only while its foot touches the ground (boxer.cpp) and aims the
// leg targets at the actual ankles (stance_ik.h fit_legs_to_ankles) so the two legs agree through the loop.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "engine/anim/skeleton.h"

namespace eng::control {

enum class JointKind { None, Ball, Hinge };

struct ImplicitServoJoint {
  JointKind kind = JointKind::None;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // hinge axis (bone frame)
  bool support = false;  // controls the parent's world orientation (bone on the planted foot's path)
  // The planted foot itself (support joint at the end of the path, the ankle): the reference takes the foot at
  // its DESIRED (flat) orientation instead of its actual one. While the sole lies flat the two are the same (the
  // ankle holds the shank upright in world space), but the foot is 1 kg on soft contacts: measured from its actual
  // orientation the ankle torque would not drop when the foot starts to tip, and it tips over its edge. With the
  // desired one the ankle torque falls as the foot tilts (the centre of pressure limit comes for free).
  bool planted = false;
  // Support hip only: its ROLL (rotation about the bone's x axis, forward: ab/adduction) also keeps the free-bone
  // law (thigh toward its own W_d from the actual pelvis). See LATERAL BALANCE above.
  bool free_roll = false;
  // Planted foot only: the spring's twist (about the foot's z axis, vertical while the sole is flat) is scaled by
  // this (1 = the plain eq. 3 spring). The contacts have no torsional friction, so a stiff twist reaction spins the
  // foot on its crate.
  double twist_scale = 1.0;
  double K = 0.0;        // joint stiffness  (N m/rad) = I omega_n^2
  double D = 0.0;        // joint damping    (N m s/rad) = 2 zeta I omega_n
  double limit = 0.0;    // |K (q_ref - q)| <= limit (N m); 0 = none
};

// Bones whose subtree contains one of `feet` (the support path: thigh, shank, foot of each leg).
std::vector<bool> support_path(const anim::Skeleton& skel, const std::vector<int>& feet);

// THE GAIN RULE. Per joint i the inertia the servo has to move, about joint i's rest position:
//  * free bones:        the composite inertia of bone i's subtree (composite_inertias, as before);
//  * support bones:     the LOAD side: every body NOT in bone i's subtree (the rest of the body carried by that
//                       joint), divided by the number of support legs (the legs share the load in parallel).
// Scalar = trace / 3. Then K_i = I_i omega_n^2, D_i = 2 zeta I_i omega_n (ONE omega_n, zeta for the body).
std::vector<double> servo_inertias(const anim::Skeleton& skel, const std::vector<double>& mass,
                                   const std::vector<Eigen::Vector3d>& com,
                                   const std::vector<Eigen::Matrix3d>& inertia, const std::vector<bool>& support,
                                   int support_legs);

// Per bone joint spring references, into ref[i] (ball: rotation vector of the joint quaternion relative to the
// rest frame, the engine's spring_ref convention; hinge: angle in ref[i].x()). Inputs are world frame:
// W_d / omega_d the lifted desired pose (eq. 2), W_a / omega_a the actual bones (after forward kinematics),
// q_a the actual joint rotations (W_a[parent]^-1 W_a[i] for a ball; the hinge angle in .x()). Bone 0 (root)
// and JointKind::None bones get ref = 0. dt: physics step.
void implicit_servo_refs(const anim::Skeleton& skel, const std::vector<ImplicitServoJoint>& joints,
                         const std::vector<Eigen::Quaterniond>& W_d, const std::vector<Eigen::Vector3d>& omega_d,
                         const std::vector<Eigen::Quaterniond>& W_a, const std::vector<Eigen::Vector3d>& omega_a,
                         const std::vector<Eigen::Vector3d>& q_a, double dt, std::vector<Eigen::Vector3d>& ref);

// The world torque on bone i (and, negated, on its parent) that joint i's spring applies for a given reference
// and actual state, explicitly evaluated (for tests and reports): R_i (K (ref - q) + D (v_ref - v)) with the
// velocity folded into ref; here v = 0 i.e. the spring part only.
Eigen::Vector3d implicit_servo_spring_torque(const ImplicitServoJoint& j, const Eigen::Quaterniond& W_child,
                                             const Eigen::Vector3d& ref, const Eigen::Vector3d& q_a);

}  // namespace eng::control
