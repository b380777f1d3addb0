#pragma once
// Lifting a parent-space pose to world space, and the desired world angular velocity (paper section IV).
//
// "Each bone's target orientation frame is lifted from the parent space matrix P_d to world space matrix W_d
//  by recursively applying forward kinematics. The actual orientation of all bones except the root are
//  ignored by this transformation." -- the root orientation is the only actual/commanded input; every other
//  W_d comes from the desired pose alone, so errors do not propagate down long linkages.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "engine/anim/skeleton.h"

namespace eng::control {

// Forward kinematics of a parent-space pose, rotations and joint positions: W[0] = pose.rotation[0] normalised,
// P[0] = pose.root_position, W[i] = (W[parent] * pose.rotation[i]) normalised, P[i] = P[parent] + W[parent] offset[i].
// The desired pose's frames for the biped layer (feet, com, leg fitting). W, P resized to skel.size().
// (engine/anim's forward_kinematics is the same map except that it does not normalise the root: merging the two
// changes the last bits of every report, see docs/decisions/one-forward-kinematics.md.)
void pose_fk(const anim::Skeleton& skel, const anim::Pose& pose, std::vector<Eigen::Quaterniond>& W,
             std::vector<Eigen::Vector3d>& P);

// Forward kinematics of rotations only: W_d[0] = root_world, W_d[i] = W_d[parent[i]] * desired.rotation[i].
// desired.rotation[0] is NOT used (the caller chooses the root: world space = clip root, person space =
// person_space_root(...), see person_space.h). W_d is resized to skel.size() (no allocation once sized).
void lift_to_world(const anim::Skeleton& skel, const anim::Pose& desired, const Eigen::Quaterniond& root_world,
                   std::vector<Eigen::Quaterniond>& W_d);

// Preallocated scratch for the look-ahead (keeps the per-tick path allocation-free).
struct WorldPoseScratch {
  anim::Pose ahead;                          // the pose extrapolated to t + delta
  std::vector<Eigen::Quaterniond> W_now;     // W_d(t)
  std::vector<Eigen::Quaterniond> W_ahead;   // W_d(t + delta)
};

// Eq. 2 exactly, when the pose source can be sampled at t + delta:
//   omega_d = Delta(W_d(t + delta), W_d(t)) / delta,  both poses lifted from their own root orientations.
void desired_world_velocity_lookahead(const anim::Skeleton& skel, const anim::Pose& now,
                                      const Eigen::Quaterniond& root_now, const anim::Pose& ahead,
                                      const Eigen::Quaterniond& root_ahead, double delta,
                                      WorldPoseScratch& scratch, std::vector<Eigen::Vector3d>& omega_d);

enum class DesiredVelocityMode {
  LookAhead,  // the paper's choice (eq. 2): extrapolate the sample by delta and difference the lifted poses
  Analytic,   // instantaneous rate: compose the sample's relative rates through the chain
};

// omega_d for every bone from one PoseSample.
//  LookAhead: each joint's relative rotation is advanced at its constant sampled rate over delta
//             (q_i(t+delta) = exp(w_rel_i delta) q_i, w_rel_i in the parent frame), the root goes from
//             root_now to root_ahead; both poses are lifted and eq. 2 is applied. delta must be > 0; the paper
//             uses the mocap keyframe spacing, and at least one physics step ("that is when the effects of the
//             applied torque will be observed").
//  Analytic:  omega_0 = Delta(root_ahead, root_now)/delta (or 0 if delta <= 0),
//             omega_i = omega_parent + W_d[parent] * w_rel_i.
// root_ahead: the desired root at t + delta (world space: integrate_rotation(clip_root, w_0, delta);
// person space: person_space_root of that with the game's heading).
void desired_world_velocity(const anim::Skeleton& skel, const anim::PoseSample& now,
                            const Eigen::Quaterniond& root_now, const Eigen::Quaterniond& root_ahead,
                            double delta, DesiredVelocityMode mode, WorldPoseScratch& scratch,
                            std::vector<Eigen::Vector3d>& omega_d);

}  // namespace eng::control
