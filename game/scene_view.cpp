#include "game/scene_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include "game/stance_ik.h"

namespace boxing {

using eng::render::Instance;
using eng::render::Material;

namespace {

glm::mat4 to_mat4(const Eigen::Matrix3d& R, const Eigen::Vector3d& p) {
  glm::mat4 m(1.0f);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] = static_cast<float>(R(r, c));
  m[3] = glm::vec4(float(p.x()), float(p.y()), float(p.z()), 1.0f);
  return m;
}

glm::vec4 rgba(const Eigen::Vector3f& c, float a = 1.0f) { return {c.x(), c.y(), c.z(), a}; }

// A body that blew up (NaN or far away) is not drawn: the rasteriser must never see non-finite vertices.
bool drawable(const eng::physics::Pose& x) { return x.p.allFinite() && x.R.allFinite() && x.p.norm() < 1e4; }

}  // namespace

std::vector<BonePart> upload_character_parts(const eng::assets::GltfScene& scene,
                                             const eng::assets::CharacterDesc& desc, eng::render::Renderer& r) {
  std::vector<BonePart> parts;
  // The character's render meshes hang off its bone nodes, in the bone's frame.
  for (int bone = 0; bone < desc.skeleton.size(); ++bone) {
    const auto& node = scene.nodes[desc.bone_node[bone]];
    if (node.mesh < 0) continue;
    for (const auto& prim : scene.meshes[node.mesh].primitives) {
      eng::render::MeshData md;
      md.vertices.resize(prim.positions.size());
      for (size_t i = 0; i < prim.positions.size(); ++i)
        md.vertices[i] = {prim.positions[i], i < prim.normals.size() ? prim.normals[i] : glm::vec3(0, 0, 1)};
      md.indices = prim.indices;
      BonePart part;
      part.bone = bone;
      part.mesh = r.upload_mesh(md);
      if (prim.material >= 0) {
        const auto& mat = scene.materials[prim.material];
        part.material.base_color = mat.base_color;
        part.material.roughness = mat.roughness;
        part.material.metallic = mat.metallic;
        part.team = mat.name == "team" || mat.name == "glove" || mat.name == "shorts";
      }
      parts.push_back(part);
    }
  }
  return parts;
}

glm::mat4 pose_matrix(const Eigen::Quaterniond& q, const Eigen::Vector3d& p) { return to_mat4(q.toRotationMatrix(), p); }

SceneView make_scene_view(const World& w, eng::render::Renderer& r) {
  SceneView v;
  for (const Crate& c : w.arena.crates)
    v.crate_mesh.push_back(r.upload_mesh(eng::render::make_box_mesh(
        glm::vec3(float(c.half_extents.x()), float(c.half_extents.y()), float(c.half_extents.z())))));
  for (const LooseBody& l : w.loose)
    v.loose_mesh.push_back(r.upload_mesh(eng::render::make_box_mesh(glm::vec3(
        float(l.shape.half_extents.x()), float(l.shape.half_extents.y()), float(l.shape.half_extents.z())))));
  v.boxer_parts = upload_character_parts(w.boxer_scene, w.boxer_desc, r);
  v.ghost = w.options.ghost;
  return v;
}

eng::render::Camera camera_preset(const std::string& name, const World& w) {
  eng::render::Camera c;
  c.fov_y_deg = 40.0f;
  if (name == "closeup") {
    // Boxer 0 from the front-left, chest height.
    const auto& s = w.arena.stances[0];
    const float base = float(std::min(s.lead_top, s.rear_top));
    const glm::vec3 at(float(s.position.x()), float(s.position.y()), base + 1.05f);
    c.target = at;
    c.eye = at + glm::vec3(1.3f, -2.3f, 0.15f);
  } else if (name == "side") {
    c.target = {0.0f, 0.0f, 1.0f};
    c.eye = {0.0f, -4.8f, 1.4f};
  } else if (name == "top") {
    c.target = {0.0f, 0.0f, 0.3f};
    c.eye = {0.01f, -0.6f, 6.5f};
  } else {
    c.target = {0.0f, 0.0f, 0.85f};
    c.eye = {2.6f, -4.4f, 2.3f};
  }
  return c;
}

void fill_frame(const World& w, const SceneView& v, eng::render::FrameDesc& f) {
  f.opaque.clear();
  f.ghosts.clear();
  f.lines.clear();
  f.points.clear();
  for (size_t i = 0; i < w.arena.crates.size(); ++i) {
    const Crate& c = w.arena.crates[i];
    Instance in;
    in.mesh = v.crate_mesh[i];
    in.model = to_mat4(Eigen::Matrix3d::Identity(), c.center);
    in.material.base_color = rgba(c.color);
    in.material.roughness = 0.8f;
    f.opaque.push_back(in);
  }
  for (size_t i = 0; i < w.loose.size(); ++i) {
    const auto& x = w.data.x[w.loose[i].body];
    if (!drawable(x)) continue;
    Instance in;
    in.mesh = v.loose_mesh[i];
    in.model = to_mat4(x.R, x.p);
    in.material.base_color = rgba(w.loose[i].color);
    in.material.roughness = 0.8f;
    f.opaque.push_back(in);
  }
  std::vector<Eigen::Quaterniond> W;
  std::vector<Eigen::Vector3d> P;
  for (const Boxer& b : w.boxers) {
    for (const BonePart& part : v.boxer_parts) {
      const auto& x = w.data.x[b.bodies.body[part.bone]];
      if (!drawable(x)) continue;
      Instance in;
      in.mesh = part.mesh;
      in.model = to_mat4(x.R, x.p);
      in.material = part.material;
      if (part.team) in.material.base_color = rgba(b.team_color);
      f.opaque.push_back(in);
    }
    if (v.ghost && !b.limp && !b.desired.pose.rotation.empty()) {
      pose_fk(w.boxer_desc.skeleton, b.desired.pose, W, P);
      for (const BonePart& part : v.boxer_parts) {
        Instance in;
        in.mesh = part.mesh;
        in.model = to_mat4(W[part.bone].toRotationMatrix(), P[part.bone]);
        in.material.base_color = glm::vec4(0.55f, 0.8f, 1.0f, 0.28f);
        in.material.roughness = 0.4f;
        f.ghosts.push_back(in);
      }
    }
  }
  if (w.push_active && !w.boxers.empty()) {
    const Boxer& b = w.boxers[0];
    const int chest = b.bodies.body[w.boxer_desc.skeleton.find("chest")];
    const Eigen::Vector3d p = w.data.com_world[chest];
    const double a = b.stance.heading + w.options.push_dir_deg * M_PI / 180.0;
    const Eigen::Vector3d from = p - 0.6 * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
    f.lines.push_back({glm::vec3(from.x(), from.y(), from.z()), glm::vec3(p.x(), p.y(), p.z()),
                       glm::vec4(1.0f, 0.9f, 0.1f, 1.0f)});
  }
}

}  // namespace boxing
