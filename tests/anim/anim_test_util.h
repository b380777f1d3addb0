#pragma once
// Shared helpers for the anim tests.
#include <string>

#include "engine/anim/clip.h"
#include "engine/anim/skeleton.h"
#include "test_paths.h"

namespace anim_test {

// The 16-bone boxer skeleton (names/offsets as in content/boxer/boxer.gltf and
// content/clips/boxing_clips.gltf), for tests that do not load the character; the game reads it from content.
inline eng::anim::Skeleton boxer_skeleton() {
  using eng::anim::Skeleton;
  Skeleton s;
  auto add = [&](const char* n, int p, double x, double y, double z) {
    s.name.push_back(n);
    s.parent.push_back(p);
    s.offset.emplace_back(x, y, z);
  };
  add("pelvis", -1, 0, 0, 0.97);
  add("abdomen", 0, 0, 0, 0.10);
  add("chest", 1, 0, 0, 0.18);
  add("head", 2, 0, 0, 0.25);
  add("upper_arm_l", 2, 0, 0.19, 0.19);
  add("forearm_l", 4, 0, 0, -0.30);
  add("glove_l", 5, 0, 0, -0.26);
  add("upper_arm_r", 2, 0, -0.19, 0.19);
  add("forearm_r", 7, 0, 0, -0.30);
  add("glove_r", 8, 0, 0, -0.26);
  add("thigh_l", 0, 0, 0.09, -0.04);
  add("shank_l", 10, 0, 0, -0.43);
  add("foot_l", 11, 0, 0, -0.42);
  add("thigh_r", 0, 0, -0.09, -0.04);
  add("shank_r", 13, 0, 0, -0.43);
  add("foot_r", 14, 0, 0, -0.42);
  return s;
}

inline std::string clips_path() { return std::string(BOXING_SOURCE_DIR) + "/content/clips/boxing_clips.gltf"; }

// Loaded once per process (the tests only read it).
inline const std::vector<eng::anim::Clip>& content_clips() {
  static const std::vector<eng::anim::Clip> clips = [] {
    auto r = eng::anim::load_clips(clips_path(), boxer_skeleton());
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
