#pragma once
// Our engine against MuJoCo on the same multibody system (MuJoCo's humanoid converted by humanoid_from_mujoco.h): at
// random states (root position and orientation, every hinge angle, every velocity) each MuJoCo body's pose, each
// geom's pose, the joint-space inertia M (ours + armature vs mj_fullM) and the bias forces c(q, v) (gravity, Coriolis,
// centrifugal; vs qfrc_bias). Both models share the q / v layout (free root, then MuJoCo's hinges in order), so the
// numbers compare one to one. Used by the ctest test tests/physics/mujoco_crosscheck_test.cpp and by
// bench_physics --check (scripts/bench).
#include <mujoco/mujoco.h>

namespace bench {

struct CrossCheck {
  int nq = 0, nv = 0;        // ours
  int mj_nq = 0, mj_nv = 0;  // MuJoCo's
  int states = 0;            // compared (0 when the layouts differ)
  // The largest difference over the states and bodies / geoms / entries, and the largest magnitude for scale.
  double body_pos = 0.0;     // m, MuJoCo body origin
  double body_rot = 0.0;     // max |R ours - R MuJoCo| entry
  double geom_pose = 0.0;    // m (centre), and |z axis difference| (the capsule axis)
  double M = 0.0, M_max = 0.0;
  double bias = 0.0, bias_max = 0.0;
  bool same_layout() const { return nq == mj_nq && nv == mj_nv; }
};

// `states` random states from a fixed LCG seeded with `seed` (uniform in [-1, 1): root +-0.5 m, a random unit
// quaternion, hinges +-0.8 rad, velocities +-2 per DoF).
CrossCheck crosscheck_mujoco(const mjModel* m, int states = 20, unsigned seed = 12345);

}  // namespace bench
