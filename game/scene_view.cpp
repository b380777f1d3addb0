#include "game/scene_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include "engine/control/biped/capture_point.h"
#include "engine/control/biped/support_polygon.h"
#include "engine/physics/dynamics.h"
#include "game/hit_feedback.h"
#include "game/interaction/interaction.h"
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

glm::vec3 gv(const Eigen::Vector3d& p) { return glm::vec3(float(p.x()), float(p.y()), float(p.z())); }

void draw_spring(const World& w, int slot, eng::render::FrameDesc& f) {
  Eigen::Vector3d point, target;
  double force = 0.0, max_force = 1.0;
  if (!drag_state(w, slot, point, target, force, max_force)) return;
  const float k = float(std::clamp(force / max_force, 0.0, 1.0));
  const glm::vec4 c(0.2f + 0.8f * k, 0.9f * (1.0f - k) + 0.1f, 0.15f, 1.0f);
  f.lines.push_back({gv(point), gv(target), c});
  for (int i = 1; i < 16; ++i) f.points.push_back({gv(point + (target - point) * (i / 16.0)), 4.0f, c});  // thick
  f.points.push_back({gv(point), 10.0f, c});
  f.points.push_back({gv(target), 7.0f, glm::vec4(1.0f, 1.0f, 1.0f, 1.0f)});
}

// The drags' springs (the mouse's and scripted ones): the grabbed point, the target and the line between, green at
// no force to red at the cap.
void draw_interaction(const World& w, eng::render::FrameDesc& f) {
  for (int slot = 0; slot < int(w.interaction->drags.size()); ++slot) draw_spring(w, slot, f);
}

void draw_debug(const World& w, const DebugDrawFlags& dbg, eng::render::FrameDesc& f) {
  const auto& d = w.data;
  if (dbg.contacts)
    for (const eng::physics::Contact& c : d.contacts) {
      if (!eng::physics::is_touching(c)) continue;
      const Eigen::Vector3d p = c.point.position;
      f.points.push_back({gv(p), 4.0f, glm::vec4(1.0f, 0.95f, 0.2f, 1.0f)});
      f.lines.push_back({gv(p), gv(p + c.force / 500.0), glm::vec4(1.0f, 0.6f, 0.1f, 1.0f)});
    }
  for (const Boxer& b : w.boxers) {
    if (!(dbg.com || dbg.support || dbg.capture_point)) break;
    // Whole-body centre of mass and its velocity (the articulation's linear momentum over its mass).
    const int root = b.bodies.body[0];
    const Eigen::Vector3d com = eng::physics::subtree_com(w.model, d, root);
    double mass = 0.0;
    for (int body : b.bodies.body) mass += w.model.bodies[body].mass;
    const Eigen::Vector3d vcom = eng::physics::spatial_momentum(w.model, d, root).tail<3>() / std::max(mass, 1e-9);
    double ground = 0.0;
    int n = 0;
    std::vector<Eigen::Vector2d> pts, hull;
    for (int k = 0; k < 2; ++k)
      for (const Eigen::Vector2d& p : b.ctl.contacts.ground_points[k]) {
        pts.push_back(p);
        ground += w.arena.top_at(p.x(), p.y());
        ++n;
      }
    ground = n ? ground / n : w.arena.top_at(com.x(), com.y());
    const float gz = float(ground) + 0.01f;
    if (dbg.com) {
      f.points.push_back({gv(com), 10.0f, glm::vec4(0.1f, 1.0f, 0.4f, 1.0f)});
      f.lines.push_back({gv(com), glm::vec3(float(com.x()), float(com.y()), gz), glm::vec4(0.1f, 1.0f, 0.4f, 1.0f)});
    }
    if (dbg.support && pts.size() >= 2) {
      eng::control::convex_hull_2d(pts, hull);
      for (size_t i = 0; i < hull.size(); ++i) {
        const Eigen::Vector2d& a = hull[i];
        const Eigen::Vector2d& c = hull[(i + 1) % hull.size()];
        f.lines.push_back({glm::vec3(float(a.x()), float(a.y()), gz), glm::vec3(float(c.x()), float(c.y()), gz),
                           glm::vec4(0.2f, 0.8f, 1.0f, 1.0f)});
      }
    }
    if (dbg.capture_point && com.z() - ground > 0.1) {
      // The point to step on to come to rest (Pratt et al. 2006, eq. 7; engine/control/biped/capture_point.h).
      const Eigen::Vector2d xi = eng::control::capture_point(com.head<2>(), vcom.head<2>(), com.z() - ground);
      const glm::vec3 at(float(xi.x()), float(xi.y()), gz);
      f.points.push_back({at, 11.0f, glm::vec4(1.0f, 0.25f, 0.85f, 1.0f)});
      f.lines.push_back({glm::vec3(float(com.x()), float(com.y()), gz), at, glm::vec4(1.0f, 0.25f, 0.85f, 1.0f)});
    }
  }
  if (dbg.hits)  // sparks that leave the hit, sized by its impulse (hit_feedback.h)
    for (const Interaction::Flash& fl : w.interaction->flashes) hit_sparks(fl, d.time, f);
}

// A box of the unit cube mesh stretched from a to b, `thick` m square across (a rope's segment, a post).
Instance stretched_box(eng::render::MeshId mesh, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double thick,
                       const glm::vec4& color) {
  const Eigen::Vector3d d = b - a;
  const double len = d.norm();
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  if (len > 1e-9) {
    const Eigen::Vector3d x = d / len;
    const Eigen::Vector3d up = std::abs(x.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d y = up.cross(x).normalized();
    R.col(0) = x, R.col(1) = y, R.col(2) = x.cross(y);
  }
  Instance in;
  in.mesh = mesh;
  in.model = glm::scale(to_mat4(R, 0.5 * (a + b)), glm::vec3(float(len), float(thick), float(thick)));
  in.material.base_color = color;
  in.material.roughness = 0.6f;
  return in;
}

// The ring's posts (red, blue and the two neutral corners' white) and its three ropes a side, each bent out where a
// boxer pushes it this tick (RingRopesState::side) and otherwise sagging a little at its middle.
void draw_ring(const World& w, const SceneView& v, eng::render::FrameDesc& f) {
  const Ring& r = w.arena.ring;
  if (!r.present) return;
  static const glm::vec4 kPost[4] = {{0.8f, 0.1f, 0.1f, 1}, {0.1f, 0.2f, 0.8f, 1}, {0.9f, 0.9f, 0.9f, 1},
                                     {0.9f, 0.9f, 0.9f, 1}};
  const double top = r.top_mean + r.post_height;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d c(r.corners[k].x(), r.corners[k].y(), 0.0);
    f.opaque.push_back(stretched_box(v.ring_box, c, c + Eigen::Vector3d(0, 0, top), 2.0 * r.post_half, kPost[k]));
  }
  const double h = r.half_inside;
  for (int s = 0; s < 4; ++s) {
    const Eigen::Vector2d n = rope_side_normal(s);
    const Eigen::Vector2d t(-n.y(), n.x());  // along the side
    const RopeSideDeflection& dfl = w.ropes.side[s];
    for (int i = 0; i < 3; ++i) {
      const double z = r.top_mean + r.rope_heights[i];
      const Eigen::Vector2d a2 = h * n - h * t, b2 = h * n + h * t;
      const double along = dfl.depth > 0.0 ? std::clamp(dfl.along * (s < 2 ? t.y() : t.x()), -0.9 * h, 0.9 * h) : 0.0;
      // Pushed: the rope nearest the pushing point goes out with it, the others less the farther they are.
      const double out = dfl.depth > 0.0 ? dfl.depth * std::max(0.0, 1.0 - std::abs(dfl.z - z) / 0.5) : 0.0;
      const Eigen::Vector2d m2 = h * n + along * t + out * n;
      const Eigen::Vector3d a(a2.x(), a2.y(), z), b(b2.x(), b2.y(), z), m(m2.x(), m2.y(), z - 0.02);
      const glm::vec4 color = i == 1 ? glm::vec4(0.85f, 0.1f, 0.1f, 1) : glm::vec4(0.92f, 0.92f, 0.9f, 1);
      f.opaque.push_back(stretched_box(v.ring_box, a, m, 0.035, color));
      f.opaque.push_back(stretched_box(v.ring_box, m, b, 0.035, color));
    }
  }
}

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
  for (const ThrownObject& o : w.interaction->objects) {
    if (o.group == 0) continue;  // not from the pool: drawn as a loose body
    v.object_mesh.push_back(o.kind == ObjectKind::Ball
                                ? r.upload_mesh(eng::render::make_sphere_mesh(float(kBall.radius), 24))
                                : r.upload_mesh(eng::render::make_box_mesh(glm::vec3(float(kCrate.half)))));
  }
  v.boxer_parts = upload_character_parts(w.boxer_scene, w.boxer_desc, r);
  if (w.arena.ring.present) v.ring_box = r.upload_mesh(eng::render::make_box_mesh(glm::vec3(0.5f)));
  v.ghost = w.options.ghost;
  const std::string& dbg = w.options.debug_draw;  // --debug: a comma-separated list (cli.cpp checked the names)
  auto has = [&](const char* name) { return ("," + dbg + ",").find("," + std::string(name) + ",") != std::string::npos; };
  if (!dbg.empty()) {
    v.debug.contacts = has("contacts"), v.debug.com = has("com"), v.debug.support = has("support");
    v.debug.capture_point = has("capture"), v.debug.hits = has("hits");
  }
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
  } else if (w.arena.ring.present) {
    // The whole ring (6 m with its apron) from a corner's side, above the top rope.
    c.target = {0.0f, 0.0f, 0.6f};
    c.eye = {4.4f, -7.6f, 3.9f};
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
  draw_ring(w, v, f);
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
  // The interaction's thrown objects (pool order: balls in bright colours, crates in a paler wood).
  for (size_t i = 0, mesh = 0; i < w.interaction->objects.size(); ++i) {
    const ThrownObject& o = w.interaction->objects[i];
    if (o.group == 0) continue;
    const size_t m = mesh++;
    if (!o.live || m >= v.object_mesh.size()) continue;
    const auto& x = w.data.x[o.body];
    if (!drawable(x)) continue;
    static const glm::vec4 kBallColors[] = {{0.95f, 0.2f, 0.2f, 1}, {0.98f, 0.85f, 0.15f, 1}, {0.2f, 0.55f, 0.95f, 1},
                                            {0.95f, 0.95f, 0.95f, 1}, {0.3f, 0.8f, 0.35f, 1}, {0.95f, 0.5f, 0.1f, 1}};
    Instance in;
    in.mesh = v.object_mesh[m];
    in.model = to_mat4(x.R, x.p);
    in.material.base_color = o.kind == ObjectKind::Ball ? kBallColors[i % 6] : glm::vec4(0.62f, 0.45f, 0.26f, 1.0f);
    in.material.roughness = o.kind == ObjectKind::Ball ? 0.35f : 0.85f;
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
  f.debug_on_top = true;  // the drag's spring and the debug drawing show through the bodies they sit in
  draw_interaction(w, f);
  draw_debug(w, v.debug, f);
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
