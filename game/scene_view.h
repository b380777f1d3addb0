#pragma once
// What the player sees: the world's bodies as render instances (crates, boxers' glTF meshes in team colours,
// loose crates), the optional ghost of the desired pose, debug lines, and the camera presets.
#include <vector>

#include "engine/render/frame.h"
#include "engine/render/renderer.h"
#include "game/world.h"

namespace boxing {

struct BonePart {
  int bone = 0;
  eng::render::MeshId mesh = 0;
  eng::render::Material material;
  bool team = false;  // takes the boxer's team colour
};

// What the debug drawing shows (the panel's checkboxes; keys 1-5).
struct DebugDrawFlags {
  bool contacts = false;       // contact points and their forces (1 m per 500 N)
  bool com = false;            // each boxer's centre of mass and its ground projection
  bool support = false;        // the support polygon: hull of the feet's ground contacts
  bool capture_point = false;  // the instantaneous capture point (Pratt et al. 2006): com + v / omega0 on the ground
  bool hits = true;            // hits on the boxers flash (punches, thrown objects)
};

struct SceneView {
  std::vector<eng::render::MeshId> crate_mesh;  // per arena crate
  std::vector<eng::render::MeshId> loose_mesh;  // per loose body
  std::vector<eng::render::MeshId> object_mesh;  // per object of the interaction's pool (beach balls, crates)
  std::vector<BonePart> boxer_parts;
  eng::render::MeshId ring_box{};  // a unit cube (the ring's posts and rope segments, scaled); only with a ring
  bool ghost = false;
  DebugDrawFlags debug;
};

// Uploads a glTF character's per-bone render meshes (materials named team / glove / shorts take a team colour).
std::vector<BonePart> upload_character_parts(const eng::assets::GltfScene& scene,
                                             const eng::assets::CharacterDesc& desc, eng::render::Renderer& r);
glm::mat4 pose_matrix(const Eigen::Quaterniond& q, const Eigen::Vector3d& p);

// Uploads every mesh the world needs (once).
SceneView make_scene_view(const World& w, eng::render::Renderer& r);

eng::render::Camera camera_preset(const std::string& name, const World& w);

// Fills the frame (instances, ghosts, debug lines) from the current physics state.
void fill_frame(const World& w, const SceneView& v, eng::render::FrameDesc& f);

}  // namespace boxing
