#pragma once
// Animation clips: sparse key poses (from content/clips/boxing_clips.gltf, authored as
// content/clips/src/*.clip and converted by scripts/content/make_clips.py) sampled with C1 splines.
//
// Interpolation (sample_clip):
//  * rotations: cubic Hermite on the unit sphere in Kim-Kim-Shin (1995) cumulative form,
//      q(u) = q0 Exp(r1 b1(u)) Exp(r2 b2(u)) Exp(r3 b3(u)),
//    with b1 = 1-(1-u)^3, b2 = 3u^2-2u^3, b3 = u^3 and Bezier control points
//    q1 = q0 Exp(w0 h/3), q2 = q3 Exp(-w3 h/3), r1 = Log(q0^-1 q1), r2 = Log(q1^-1 q2), r3 = Log(q2^-1 q3).
//    It passes through the keys and its body angular velocity at key k is w_k, shared by both
//    segments -> C1. w_k is the non-uniform Catmull-Rom (Bessel) tangent: the time-weighted average
//    of the neighbouring segment rates Log(q_{k-1}^-1 q_k)/h_{k-1} and Log(q_k^-1 q_{k+1})/h_k.
//  * root position: cubic Hermite with the same tangent rule (Catmull-Rom).
//  * end keys of non-looping clips get zero velocity (the clips start/end at rest in guard);
//    looping clips wrap (last key == first key) so the seam is C1.
//  * quaternion sign continuity: load_clips flips every key to the hemisphere of the previous key,
//    and every Log in the spline takes the shortest arc, so sign flips in the file are harmless.
// Angular velocities: a central difference of the spline itself with h = 1e-4 s
// (omega = Log(q(t+h) q(t-h)^-1) / 2h, parent frame; one-sided at the ends of non-looping clips).
// The truncation error is O(h^2) ~ 1e-8 relative, i.e. exact for control purposes, and it is by
// construction consistent with the interpolated orientation.
#include <string>
#include <vector>

#include "engine/anim/skeleton.h"
#include "engine/core/result.h"

namespace eng::assets {
struct GltfScene;
}

namespace eng::anim {

struct Clip {
  std::string name;
  std::vector<std::string> tags;  // free-form labels the game gives meaning to (steering, graph options)
  bool loop = false;
  int glove = -1;                 // striking bone index for strikes (extras.glove), else -1
  double impact_time = -1.0;      // strikes: seconds from the start to the impact (extras.impact), else -1
  std::vector<std::string> next;  // natural continuations: clips that may follow the clip's end (may be empty)
  std::vector<double> key_times;  // seconds, key_times[0] == 0, increasing
  std::vector<Pose> keys;         // one pose per key time
  // Derived from the keys by bake_spline (empty: computed per sample): per segment i and bone b, the rotation
  // spline's three control vectors r1, r2, r3 at [3 (i * bones + b) + k]. Editing keys after baking needs a rebake.
  std::vector<Eigen::Vector3d> spline;

  double duration() const { return key_times.empty() ? 0.0 : key_times.back(); }
  bool has_tag(const std::string& tag) const;
};

// Fills c.spline from c.keys: the per-segment constants of the rotation spline, so that a sample evaluates three
// exponentials per bone instead of also five logarithms and two exponentials (the same numbers, stored).
void bake_spline(Clip& c);

// Pose only (no derivatives). t is wrapped for looping clips, clamped otherwise.
Pose sample_clip_pose(const Clip& c, double t);
// Pose plus root velocity and per-bone angular velocity (PoseSample contract, see skeleton.h).
PoseSample sample_clip(const Clip& c, double t);
// The same into *out, reusing its storage: no allocation once *out has held a pose of this skeleton (per tick).
void sample_clip_pose(const Clip& c, double t, Pose* out);
void sample_clip(const Clip& c, double t, PoseSample* out);
// The root position alone (out->rotation left empty): the same number sample_clip_pose gives, without the bones.
void sample_clip_root(const Clip& c, double t, Pose* out);

// Angular velocity (parent/world frame) that takes qa to qb in dt: Log(qb qa^-1) / dt.
Eigen::Vector3d angular_velocity_between(const Eigen::Quaterniond& qa, const Eigen::Quaterniond& qb,
                                         double dt);

// Loads every glTF animation of the file as a Clip. Errors name the file and the problem: missing
// or broken file, a channel on a node that is not a skeleton bone, missing metadata (extras.tags,
// extras.loop; glove and impact come together), channels with different key times, no translation on the
// root bone.
eng::Result<std::vector<Clip>> load_clips(const std::string& gltf_path, const Skeleton& skeleton);
// The same from a loaded scene (its path names it in errors).
eng::Result<std::vector<Clip>> load_clips(const eng::assets::GltfScene& scene, const Skeleton& skeleton);

// Index of the clip with this name, -1 when none.
int find_clip(const std::vector<Clip>& clips, const std::string& name);

}  // namespace eng::anim
