#pragma once
// Shared helpers for the anim tests.
#include <string>

#include "engine/anim/clip.h"

namespace anim_test {

inline std::string clips_path() { return std::string(BOXING_SOURCE_DIR) + "/content/clips/boxing_clips.gltf"; }

// Loaded once per process (the tests only read it).
inline const std::vector<eng::anim::Clip>& content_clips() {
  static const std::vector<eng::anim::Clip> clips = [] {
    auto r = eng::anim::load_clips(clips_path(), eng::anim::boxer_skeleton());
    return r ? *r : std::vector<eng::anim::Clip>{};
  }();
  return clips;
}

// Sole centre of a foot in world space (same point as make_clips.py's SOLE).
inline Eigen::Vector3d sole(const eng::anim::Skeleton& s, const eng::anim::Pose& p, int foot) {
  std::vector<Eigen::Vector3d> wp;
  std::vector<Eigen::Quaterniond> wr;
  eng::anim::forward_kinematics(s, p, &wp, &wr);
  return wp[foot] + wr[foot] * Eigen::Vector3d(0.04, 0, -0.08);
}

}  // namespace anim_test
