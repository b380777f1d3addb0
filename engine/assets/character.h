#pragma once
// Character descriptions from glTF content: the skeleton plus per-bone physics read from each bone
// node's extras["physics"] (schema in content/README.md). Engine-generic: no boxing knowledge here.
// The extras are stored in glTF's axes like the rest of the file; everything below is in the engine's
// frame (Z up), converted on load by engine/assets/frame.h.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <utility>
#include <vector>

#include "engine/anim/skeleton.h"
#include "engine/assets/gltf.h"
#include "engine/core/result.h"
#include "engine/physics/collision.h"

namespace eng::assets {

struct BoneShape {
  eng::physics::Shape shape;                               // capsules along local Z of (pos, quat)
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();           // shape centre in the bone frame
  Eigen::Quaterniond quat = Eigen::Quaterniond::Identity();  // shape orientation in the bone frame
};

struct BonePhysics {
  std::string joint;  // "free" | "ball" | "hinge" | "fixed" (joint to the parent; the root is "free")
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();  // hinge axis in the bone frame (unit)
  double lower = 0.0, upper = 0.0;                  // hinge range (rad)
  double swing_limit = 0.0, twist_limit = 0.0;      // ball cone / twist about the bone axis (rad)
  double mass = 0.0;                                // kg
  Eigen::Vector3d com = Eigen::Vector3d::Zero();    // bone frame
  Eigen::Vector3d inertia_diag = Eigen::Vector3d::Zero();  // principal, about com, bone frame axes
  double damping = 0.0, armature = 0.0;
  std::vector<BoneShape> shapes;
};

struct CharacterDesc {
  eng::anim::Skeleton skeleton;  // bone 0 = root, parent[i] < i
  std::vector<BonePhysics> bones;
  std::vector<int> bone_node;  // glTF node index per bone
  // From the first scene's extras.character.collision (optional there): the collision group bit all
  // bones of the character share, and bone pairs (a < b) that must not collide besides
  // parent/child pairs, which the engine always excludes.
  int collision_group_bit = 1;
  std::vector<std::pair<int, int>> exclude_pairs;
  // Number of degrees of freedom: free 6, ball 3, hinge 1, fixed 0.
  int dof() const;
  double total_mass() const;
};

// Walks the node hierarchy from root_node depth-first (pre-order, children in file order), so
// parent[i] < i. Every node under the root is a bone and must carry extras.physics with a known
// joint type, positive mass and inertia and at least one shape; bones must have identity rest
// rotation and unit scale (offset = node translation). Errors name the file, node and field.
// root_node empty: the file's first root node (the first node without a parent).
eng::Result<CharacterDesc> load_character(const GltfScene& scene, const std::string& root_node = {});

}  // namespace eng::assets
