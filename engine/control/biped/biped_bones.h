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

// The skeleton's leg bone names, supplied by the game (the engine names no character's bones).
struct BipedBoneNames {
  const char* thigh[2];
  const char* shank[2];
  const char* foot[2];
};

inline BipedBones biped_bones(const anim::Skeleton& s, const BipedBoneNames& n) {
  BipedBones b;
  for (int k = 0; k < 2; ++k) b.leg[k] = {s.find(n.thigh[k]), s.find(n.shank[k]), s.find(n.foot[k])};
  b.foot[0] = b.leg[0].foot;
  b.foot[1] = b.leg[1].foot;
  return b;
}

}  // namespace eng::control
