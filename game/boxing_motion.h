#pragma once
// What the boxing clips mean to the engine's motion graph (engine/anim/motion_graph.h knows no character):
//  * feature points beyond the 16 joints: the glove centres, the toes and the top of the head, so the window
//    distance sees where the fists and feet are, not only the wrists and ankles (21 points);
//  * fall, down, getup and reaction clips are entered only by force (a hit or a knockdown, force_clip) or a
//    natural continuation: a boxer must not flinch or fall without being hit; fall and down clips are never
//    left by a random transition (only by their continuations: down -> getup -> guard);
//  * fall and reaction clips get the knockdown edges from guard, so pruning keeps them reachable;
//  * guard is the home clip: walks start there and a non-looping clip without extras.next returns to it.
#include "engine/anim/motion_graph.h"
#include "engine/control/biped/biped_bones.h"
#include "engine/anim/skeleton.h"

namespace boxing {

// The home clip of every boxing walk.
inline constexpr const char* kGuardClip = "guard";

// A boxing walk's heading hold (GraphWalker::heading_hold, 1/s: a 5 s time constant): holding the walk's heading keeps
// the rear foot's slide down on long graph walks (docs/decisions/foot-slide.md).
inline constexpr double kHeadingHold = 0.2;

// The boxer's leg bones as content/boxer/boxer.gltf names them ([0] left, the orthodox lead; [1] right).
inline constexpr eng::control::BipedBoneNames kBoxerLegs{{"thigh_l", "thigh_r"}, {"shank_l", "shank_r"}, {"foot_l", "foot_r"}};

// The boxing graph options for this skeleton (feature points on bones it lacks are left out).
eng::anim::MotionGraphOptions boxing_graph_options(const eng::anim::Skeleton& skeleton);

}  // namespace boxing
