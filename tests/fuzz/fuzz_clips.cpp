// libFuzzer harness: the clip loader (engine/anim/clip.h) on arbitrary glTF bytes, against the boxer's skeleton
// (content/boxer/boxer.gltf, loaded once), then the spline sampler on every clip it accepts.
// Promise checked: an accepted clip has increasing finite key times from 0, one pose per key, unit finite
// rotations and finite root positions, and sampling it anywhere gives finite poses and velocities.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "engine/anim/clip.h"
#include "engine/assets/character.h"
#include "engine/assets/gltf.h"
#include "tests/fuzz/fuzz_check.h"

namespace {
eng::anim::Skeleton g_skeleton;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  auto scene = eng::assets::load_gltf(BOXING_SOURCE_DIR "/content/boxer/boxer.gltf");
  if (!scene) {
    std::fprintf(stderr, "fuzz_clips: cannot load the boxer: %s\n", scene.error().c_str());
    std::exit(1);
  }
  auto desc = eng::assets::load_character(*scene);
  if (!desc) {
    std::fprintf(stderr, "fuzz_clips: cannot load the boxer: %s\n", desc.error().c_str());
    std::exit(1);
  }
  g_skeleton = desc->skeleton;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto scene = eng::assets::load_gltf_memory(data, size, "fuzz.gltf");
  if (!scene) return 0;
  auto clips = eng::anim::load_clips(*scene, g_skeleton);
  if (!clips) {
    fuzz::check(!clips.error().empty(), "an error without a message");
    return 0;
  }
  const size_t bones = static_cast<size_t>(g_skeleton.size());
  for (const auto& c : *clips) {
    fuzz::check(c.key_times.size() >= 2 && c.keys.size() == c.key_times.size(), "key count");
    fuzz::check(c.key_times[0] == 0.0, "first key at 0");
    for (size_t k = 0; k < c.keys.size(); ++k) {
      fuzz::check(std::isfinite(c.key_times[k]) && (k == 0 || c.key_times[k] > c.key_times[k - 1]), "key times");
      fuzz::check(c.keys[k].rotation.size() == bones, "rotation count");
      fuzz::check(fuzz::finite(c.keys[k].root_position), "root position not finite");
      for (const auto& q : c.keys[k].rotation)
        fuzz::check(fuzz::finite(q.coeffs()) && std::abs(q.norm() - 1.0) < 1e-9, "rotation not a unit quaternion");
    }
    fuzz::check(c.glove < static_cast<int>(bones), "glove bone");
    eng::anim::PoseSample s;
    const double d = c.duration();
    for (double t : {-1.0, 0.0, 0.37 * d, 0.5 * d, d, d + 1.0}) {
      eng::anim::sample_clip(c, t, &s);
      fuzz::check(s.pose.rotation.size() == bones && s.angular_velocity.size() == bones, "sample size");
      fuzz::check(fuzz::finite(s.pose.root_position) && fuzz::finite(s.root_velocity), "sampled root not finite");
      for (size_t b = 0; b < bones; ++b)
        fuzz::check(fuzz::finite(s.pose.rotation[b].coeffs()) && fuzz::finite(s.angular_velocity[b]),
                    "sampled rotation / angular velocity not finite");
    }
  }
  for (const auto& c : *clips)
    for (const auto& n : c.next) fuzz::check(eng::anim::find_clip(*clips, n) >= 0, "next names an unknown clip");
  return 0;
}
