#pragma once
// Two-bone leg IK, and fitting a clip's legs to uneven ground. The clip was authored on a flat floor, the biped
// stands on terrain of different heights. Each leg is a two-bone chain (thigh, shank) solved analytically (law of
// cosines for the knee, then the thigh re-aimed at the ankle target by the smallest rotation); the foot keeps its
// world orientation so the sole stays flat.
#include "engine/anim/skeleton.h"
#include "engine/control/biped/biped_bones.h"
#include "engine/control/biped/ground.h"

namespace eng::control {

// pose: world-placed (root_position, rotation[0] world). base_top: the floor height the clip's root height is
// measured from. ground(x, y): the support height under a world point, sampled under the middle of each foot
// (foot_centre, foot frame). Modifies the leg rotations in place.
void fit_legs_to_ground(const anim::Skeleton& skel, const LegBones legs[2], double base_top, GroundHeight ground,
                        anim::Pose& pose, const Eigen::Vector3d& foot_centre = Eigen::Vector3d(0.05, 0.0, 0.0));

// The same two-bone solve with the ankles at given WORLD positions (e.g. where the physics feet actually are):
// the servo's leg targets then agree with the planted feet, so the two legs do not fight through the closed loop
// ground - left leg - pelvis - right leg - ground, and the legs carry the pelvis to its desired place.
void fit_legs_to_ankles(const anim::Skeleton& skel, const LegBones legs[2], const Eigen::Vector3d ankles[2],
                        anim::Pose& pose);

}  // namespace eng::control
