#pragma once
// Converts a MuJoCo model (mjModel, e.g. /usr/share/mujoco/model/humanoid/humanoid.xml) into our
// eng::physics::Model, for the MuJoCo comparison benchmark (tests/bench/physics_bench.cpp) and the cross-check test
// (tests/physics/mujoco_crosscheck_test.cpp, through mujoco_crosscheck.h).
//
// CONVERSION RULES
//  * Bodies keep MuJoCo's tree. A MuJoCo body with k hinges (abdomen, hips, ankles, shoulders) becomes a
//    CHAIN of k bodies, one hinge each, in MuJoCo's joint order. All chain bodies but the last are massless
//    (mass 0, zero inertia: every hinge has armature and a massive subtree, so M stays positive definite).
//    Chain body k has its origin at jnt_pos[k] (our joint origin is the body origin) and the orientation of
//    the MuJoCo body frame, which reproduces MuJoCo's sequential joint transforms (each hinge rotates the
//    frame about its own anchor). The DoF count is unchanged (humanoid: 6 + 21 = 27).
//  * The last chain body carries body_mass, com (body_ipos) and inertia (body_inertia rotated by
//    body_iquat into the body frame); everything attached to it (com, geoms, child bodies) is shifted by
//    the last hinge's jnt_pos, since that is where our body origin sits.
//  * Per hinge: axis (jnt_axis, normalised), damping (dof_damping), armature (dof_armature), stiffness
//    (jnt_stiffness, toward 0 = MuJoCo's qpos_spring = qpos0), limits (jnt_range when jnt_limited).
//    Free joint: damping / armature of its first DoF.
//  * Geoms: capsule (geom_size[0] radius, geom_size[1] half length along local Z), sphere, box; pose
//    geom_pos/geom_quat; friction geom_friction[0]. World planes become one static Plane geom (added once
//    per Model by add_mujoco_floor).
//  * Gravity and timestep from mjModel::opt (the caller may override dt).
//
// KNOWN DIFFERENCES (documented, not bugs of the conversion)
//  * Self collision is OFF for converted geoms (floor and humanoid-vs-humanoid contacts only): our
//    parent/child pair filter sees the massless chain bodies between e.g. pelvis and thigh, so the
//    overlapping hip capsules would collide. MuJoCo collides non-adjacent bodies of one humanoid.
//  * Pair friction: ours sqrt(mu_a mu_b) (0.84 body on floor), MuJoCo max(mu_a, mu_b) (1.0).
//  * Solver: ours soft PGS (engine/physics/step.h), MuJoCo its default Newton solver with solref/solimp.
#include <mujoco/mujoco.h>

#include <vector>

#include "engine/physics/model.h"

namespace bench {

// Where a MuJoCo body's frame lives in the converted model: our body index and the MuJoCo body origin
// expressed in that body's frame (= -jnt_pos of the last hinge: our origin sits on the joint anchor; same
// orientation).
struct MappedBody {
  int body = 0;
  eng::physics::Vec3 offset = eng::physics::Vec3::Zero();
};

// Appends all MuJoCo bodies but the world (and their geoms) to `out`, the root translated by `shift`.
// Returns the mapping for every MuJoCo body id (entry 0 = world). Throws on unsupported joints/geoms.
std::vector<MappedBody> append_mujoco_bodies(const mjModel* m, eng::physics::Model& out,
                                             const eng::physics::Vec3& shift);

// Adds the world plane geoms of `m` (the floor) as static Plane geoms of `out`.
void add_mujoco_floor(const mjModel* m, eng::physics::Model& out);

// Full conversion: floor + `count` copies of the MuJoCo tree spaced `spacing` m apart along world Y,
// gravity and dt from m->opt, finalized. Returns the mapping of each copy.
std::vector<std::vector<MappedBody>> convert_mujoco_model(const mjModel* m, eng::physics::Model& out,
                                                          int count = 1, double spacing = 1.5);

}  // namespace bench
