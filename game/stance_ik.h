#pragma once
// Fits a clip's leg pose to uneven ground: the clip was authored on a flat floor, the boxer stands on crates of
// different heights. Each leg is a two-bone chain (thigh, shank) solved analytically (law of cosines for the knee,
// then the thigh re-aimed at the ankle target by the smallest rotation); the foot keeps its world orientation so
// the sole stays flat on its crate.
#include <functional>

#include "engine/anim/skeleton.h"

namespace boxing {

struct LegBones {
  int thigh, shank, foot;
};

// pose: world-placed (root_position, rotation[0] world). base_top: the floor height the clip's root height is
// measured from. ground(x, y): the support height under a world point. Modifies the leg rotations in place.
void fit_legs_to_ground(const eng::anim::Skeleton& skel, const LegBones legs[2], double base_top,
                        const std::function<double(double, double)>& ground, eng::anim::Pose& pose);

// The same two-bone solve with the ankles at given WORLD positions (e.g. where the physics feet actually are):
// the servo's leg targets then agree with the planted feet, so the two legs do not fight through the closed loop
// ground - left leg - pelvis - right leg - ground, and the legs carry the pelvis to its desired place.
void fit_legs_to_ankles(const eng::anim::Skeleton& skel, const LegBones legs[2], const Eigen::Vector3d ankles[2],
                        eng::anim::Pose& pose);

// Forward kinematics of a parent-space pose: world orientation and joint position per bone.
void pose_fk(const eng::anim::Skeleton& skel, const eng::anim::Pose& pose, std::vector<Eigen::Quaterniond>& W,
             std::vector<Eigen::Vector3d>& P);

}  // namespace boxing
