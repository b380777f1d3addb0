#pragma once
// Effective inertia per bone, used to scale the servo gains (eq. 3's k1, k2) so ONE (omega_n, zeta) pair
// drives the whole body with a uniform response.
//
// Choice: I_i = scalar of the composite rigid-body inertia of bone i's SUBTREE (the bone and everything
// distal to it) about bone i's joint, in the rest pose. Why the subtree: a torque at joint i has to swing the
// whole distal chain (a shoulder torque moves the upper arm, forearm and glove), so with the parent held still
// the joint sees I_i. With k1 = I_i omega_n^2 and k2 = 2 zeta I_i omega_n each joint then behaves like
// I_i theta'' + k2 theta' + k1 theta = 0, i.e. the same natural frequency and damping ratio for a finger and a
// hip. Per-bone inertia alone would make proximal joints (carrying long chains) far too soft.
// The rest pose is used so the gains are constants (no per-tick recomputation, no gain jitter).
#include <Eigen/Core>
#include <vector>

#include "engine/anim/skeleton.h"

namespace eng::control {

enum class InertiaScalar {
  MeanPrincipal,  // trace / 3 (rotation-invariant average of the principal moments) -- default
  MaxPrincipal,   // largest principal moment (the swing axes of a limb; stiffer on the twist axis)
};

// mass[i] (kg), com[i] (centre of mass in bone i's frame, relative to bone i's joint, metres),
// inertia[i] (kg m^2 about the bone's own com, bone frame). At rest every bone frame is aligned with the root
// frame and joint i sits at joint(parent) + skel.offset[i].
// Returns I_eff per bone (bone 0: whole body about the root joint). If tensors_out is given it receives the
// full 3x3 composite tensors (rest/root frame, about each joint).
std::vector<double> composite_inertias(const anim::Skeleton& skel, const std::vector<double>& mass,
                                       const std::vector<Eigen::Vector3d>& com,
                                       const std::vector<Eigen::Matrix3d>& inertia,
                                       InertiaScalar mode = InertiaScalar::MeanPrincipal,
                                       std::vector<Eigen::Matrix3d>* tensors_out = nullptr);

// Subtree mass per bone (kg); [0] is the total mass. Handy for torque limits per kg and the meathook.
std::vector<double> subtree_masses(const anim::Skeleton& skel, const std::vector<double>& mass);

}  // namespace eng::control
