#pragma once
// The bones of a biped the control layer needs by index (legs and feet), resolved once from the skeleton's names at
// setup instead of by name lookups every tick.
#include "engine/anim/skeleton.h"

namespace eng::control {

struct LegBones {
  int thigh = -1, shank = -1, foot = -1;
};

struct BipedBones {
  int pelvis = 0;
  LegBones leg[2];      // [0] left (the orthodox lead), [1] right (rear)
  int foot[2] = {-1, -1};  // leg[k].foot
  bool valid() const { return foot[0] >= 0 && foot[1] >= 0 && leg[0].thigh >= 0 && leg[1].thigh >= 0; }
};

// thigh_l / shank_l / foot_l and thigh_r / shank_r / foot_r (content/boxer/boxer.gltf's names).
inline BipedBones biped_bones(const anim::Skeleton& s) {
  BipedBones b;
  b.leg[0] = {s.find("thigh_l"), s.find("shank_l"), s.find("foot_l")};
  b.leg[1] = {s.find("thigh_r"), s.find("shank_r"), s.find("foot_r")};
  b.foot[0] = b.leg[0].foot;
  b.foot[1] = b.leg[1].foot;
  return b;
}

}  // namespace eng::control
