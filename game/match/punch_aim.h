#pragma once
// Aimed punches: the striking glove goes for the opponent's actual head or body at the clip's impact frame, not for
// the point in space where the clip's glove was. The clip's arm is bent toward the target by a two-bone IK
// (engine/control/ik/two_bone_ik.h) on the desired pose, by a weight that rises from 0 at the punch's start to 1 at
// its impact frame and falls back to 0 over the retraction: the wrist goes to (1 - w) x the clip's wrist + w x the
// target's. The servo and the balance QP then track the bent arm like any desired pose (the arm's stiffness about
// the desired path is the servo's: in the spirit of Cartesian impedance control, macarena-controllers section 7,
// F = K (x_d - x) - B (v_d - v), here with x_d bent onto the target).
#include <Eigen/Core>
#include <vector>

#include "engine/anim/skeleton.h"
#include "engine/assets/character.h"

namespace boxing {

struct PunchAim {
  bool active = false;
  int glove = -1;                                    // the striking glove's bone
  Eigen::Vector3d target = Eigen::Vector3d::Zero();  // world point the glove's centre goes through at impact
  double weight = 0.0;                               // 0..1 this tick (aim_weight)
  double arm_gain = 1.0;  // the striking arm's servo natural frequency x this while aimed (balance QP; 1 = as any bone)
};

// The aim's weight t seconds into a punch whose clip strikes at `impact` and lasts `duration`: smooth 0 -> 1 over
// [0, 0.75 impact], 1 until the impact frame, 1 -> 0 over the first 60 % of the retraction.
double aim_weight(double t, double impact, double duration);

// Bends pose (world-placed) so the glove's centre moves toward aim.target by aim.weight. W, P: scratch.
void apply_punch_aim(const eng::assets::CharacterDesc& desc, const PunchAim& aim, eng::anim::Pose& pose,
                     std::vector<Eigen::Quaterniond>& W, std::vector<Eigen::Vector3d>& P);

}  // namespace boxing
