#pragma once
// Aimed punches: the striking glove goes for the opponent's actual head or body at the clip's impact frame, not for
// the point in space where the clip's glove was. Two parts:
//  * the desired pose: the clip's arm is bent toward the target by a two-bone IK (engine/control/ik/two_bone_ik.h),
//    by a weight that rises from 0 at the punch's start to 1 at its impact frame and falls back to 0 over the
//    retraction (the wrist goes to (1 - w) x the clip's wrist + w x the target's): the servo and the balance QP track
//    the bent arm like any desired pose;
//  * the strike: a task-space goal on the glove's centre in the balance QP, Cartesian impedance in the manner of
//    macarena-controllers section 7, eq. 7-9 (F = K (x_d - x) - B (v_d - v), here the acceleration
//    B/m (v_d - v) with v_d a velocity field into the target: min(strike_speed, strike_rate x distance) toward it,
//    which holds the K term), on from a quarter of the way to the impact frame until the glove's first touch.
//    Without it the glove met the head at 3.5 m/s (median; real jabs 5.6 m/s, Walilko 2005): the servo lags the
//    clip, and past the impact frame the clip's velocities already retract the arm.
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
  // The strike: a task-space goal on the glove's centre in the balance QP (Cartesian impedance, macarena-controllers
  // section 7, eq. 7-9: F = K (x_d - x) - B (v_d - v), here as an acceleration), x_d the target and v_d a velocity
  // field toward it at the punch's speed: the bent desired pose alone brings the glove in at 3-4 m/s (the servo lags
  // it, and past the impact frame the clip's velocities already retract the arm).
  double strike = 0.0;         // 0..1 this tick (strike_weight): the glove task's share of its weight
  double strike_speed = 0.0;   // m/s, the glove's desired speed toward the target
  double strike_rate = 30.0;   // 1/s, the field's speed near the target: min(strike_speed, rate x distance)
  double strike_omega = 30.0;  // 1/s, B / m of the impedance: how fast the glove's velocity follows the field's
  double strike_weight = 2.0;  // the task's QP weight per kg of the striking arm (at strike = 1)
};

// The aim's weight t seconds into a punch whose clip strikes at `impact` and lasts `duration`: smooth 0 -> 1 over
// [0, 0.75 impact], 1 until the impact frame, 1 -> 0 over the first 60 % of the retraction.
double aim_weight(double t, double impact, double duration);

// The glove task's weight t seconds into a punch striking at `impact`: smooth 0 -> 1 over [0.25, 0.6] x impact, 1
// until `follow` seconds past the impact frame (the glove goes through), then 0 (the clip retracts the arm).
double strike_weight(double t, double impact, double follow);

// Bends pose (world-placed) so the glove's centre moves toward aim.target by aim.weight. W, P: scratch.
void apply_punch_aim(const eng::assets::CharacterDesc& desc, const PunchAim& aim, eng::anim::Pose& pose,
                     std::vector<Eigen::Quaterniond>& W, std::vector<Eigen::Vector3d>& P);

}  // namespace boxing
