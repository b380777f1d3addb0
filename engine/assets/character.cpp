#include "engine/assets/character.h"

#include "engine/assets/frame.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace eng::assets {
namespace {

// GltfNode stores float translations; the file holds decimals like 0.19. Widen through the shortest
// decimal that round-trips the float so the skeleton gets the double nearest the authored value
// (0.19, not 0.189999998).
double widen(float f) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof(buf) - 1, f);
  if (res.ec != std::errc()) return static_cast<double>(f);
  *res.ptr = '\0';
  return std::strtod(buf, nullptr);
}

// A number as the user wrote it (shortest form: 1e+30, 11, 0.5).
std::string number_text(double x) {
  char buf[32];
  auto res = std::to_chars(buf, buf + sizeof(buf) - 1, x);
  *res.ptr = '\0';
  return buf;
}

// A bone's offset from its parent beyond this (m) is an error: no character is that large.
constexpr double kMaxBoneOffset = 10.0;

struct Bad {
  std::string what;
};

[[noreturn]] void fail(const std::string& node, const std::string& field, const std::string& what) {
  throw Bad{"node '" + node + "' extras.physics" + (field.empty() ? "" : "." + field) + " " + what};
}

const nlohmann::json* member(const nlohmann::json& o, const char* key) {
  auto it = o.find(key);
  return it == o.end() || it->is_null() ? nullptr : &*it;
}

double number(const nlohmann::json& o, const char* key, const std::string& node, const std::string& prefix,
              bool required, double fallback = 0.0) {
  const nlohmann::json* v = member(o, key);
  if (!v) {
    if (required) fail(node, prefix + key, "is missing");
    return fallback;
  }
  if (!v->is_number()) fail(node, prefix + key, "must be a number, got " + v->dump());
  double d = v->get<double>();
  if (!std::isfinite(d)) fail(node, prefix + key, "must be finite");
  return d;
}

template <int N>
Eigen::Matrix<double, N, 1> vec(const nlohmann::json& o, const char* key, const std::string& node,
                                const std::string& prefix, bool required,
                                const Eigen::Matrix<double, N, 1>& fallback) {
  const nlohmann::json* v = member(o, key);
  if (!v) {
    if (required) fail(node, prefix + key, "is missing");
    return fallback;
  }
  if (!v->is_array() || v->size() != N)
    fail(node, prefix + key, "must be an array of " + std::to_string(N) + " numbers, got " + v->dump());
  Eigen::Matrix<double, N, 1> out;
  for (int i = 0; i < N; ++i) {
    const auto& e = (*v)[static_cast<size_t>(i)];
    if (!e.is_number() || !std::isfinite(e.get<double>()))
      fail(node, prefix + key, "must be an array of " + std::to_string(N) + " numbers, got " + v->dump());
    out[i] = e.get<double>();
  }
  return out;
}

BoneShape parse_shape(const nlohmann::json& s, const std::string& node, size_t index) {
  const std::string pre = "shapes[" + std::to_string(index) + "].";
  if (!s.is_object()) fail(node, "shapes[" + std::to_string(index) + "]", "must be an object");
  const nlohmann::json* t = member(s, "type");
  if (!t || !t->is_string()) fail(node, pre + "type", "must be \"capsule\", \"sphere\" or \"box\"");
  const std::string type = t->get<std::string>();
  BoneShape b;
  using eng::physics::ShapeType;
  if (type == "sphere") {
    b.shape.type = ShapeType::Sphere;
    b.shape.radius = number(s, "radius", node, pre, true);
    if (!(b.shape.radius > 0)) fail(node, pre + "radius", "must be positive");
  } else if (type == "capsule") {
    b.shape.type = ShapeType::Capsule;
    b.shape.radius = number(s, "radius", node, pre, true);
    b.shape.half_length = number(s, "half_length", node, pre, true);
    if (!(b.shape.radius > 0)) fail(node, pre + "radius", "must be positive");
    if (!(b.shape.half_length >= 0)) fail(node, pre + "half_length", "must not be negative");
  } else if (type == "box") {
    b.shape.type = ShapeType::Box;
    b.shape.half_extents = frame::to_engine(vec<3>(s, "half_extents", node, pre, true, Eigen::Vector3d::Zero()));
    if (!(b.shape.half_extents.minCoeff() > 0)) fail(node, pre + "half_extents", "must all be positive");
  } else {
    fail(node, pre + "type", "is '" + type + "'; expected \"capsule\", \"sphere\" or \"box\"");
  }
  b.pos = frame::to_engine(vec<3>(s, "pos", node, pre, false, Eigen::Vector3d::Zero()));
  Eigen::Vector4d q = vec<4>(s, "quat", node, pre, false, Eigen::Vector4d(1, 0, 0, 0));  // [w, x, y, z]
  q.tail<3>() = frame::to_engine(Eigen::Vector3d(q.tail<3>()));  // before normalising: same sums as authored
  if (!(q.norm() > 1e-9)) fail(node, pre + "quat", "must be a non-zero quaternion [w, x, y, z]");
  q.normalize();
  b.quat = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  return b;
}

BonePhysics parse_bone(const nlohmann::json& extras, const std::string& node, bool is_root) {
  if (!extras.is_object() || !extras.contains("physics"))
    throw Bad{"node '" + node + "' has no extras.physics (every node under the character root is a bone)"};
  const nlohmann::json& p = extras["physics"];
  if (!p.is_object()) fail(node, "", "must be an object");
  BonePhysics b;
  const nlohmann::json* j = member(p, "joint");
  if (!j || !j->is_string()) fail(node, "joint", "is missing (expected \"free\", \"ball\", \"hinge\" or \"fixed\")");
  b.joint = j->get<std::string>();
  if (b.joint != "free" && b.joint != "ball" && b.joint != "hinge" && b.joint != "fixed")
    fail(node, "joint", "is '" + b.joint + "'; expected \"free\", \"ball\", \"hinge\" or \"fixed\"");
  if (is_root && b.joint != "free") fail(node, "joint", "of the root bone must be \"free\", is '" + b.joint + "'");
  if (!is_root && b.joint == "free") fail(node, "joint", "\"free\" is only allowed on the root bone");
  if (b.joint == "hinge") {
    b.axis = frame::to_engine(vec<3>(p, "axis", node, "", true, Eigen::Vector3d::UnitX()));
    if (!(b.axis.norm() > 1e-9)) fail(node, "axis", "must be a non-zero vector");
    b.axis.normalize();
    Eigen::Vector2d r = vec<2>(p, "range", node, "", true, Eigen::Vector2d::Zero());
    if (!(r[0] <= r[1])) fail(node, "range", "must be [lower, upper] with lower <= upper");
    b.lower = r[0];
    b.upper = r[1];
  } else if (b.joint == "ball") {
    b.swing_limit = number(p, "swing_limit", node, "", true);
    b.twist_limit = number(p, "twist_limit", node, "", true);
    if (!(b.swing_limit > 0)) fail(node, "swing_limit", "must be positive (radians)");
    if (!(b.twist_limit > 0)) fail(node, "twist_limit", "must be positive (radians)");
  }
  b.mass = number(p, "mass", node, "", true);
  if (!(b.mass > 0)) fail(node, "mass", "must be positive (kg), got " + std::to_string(b.mass));
  b.com = frame::to_engine(vec<3>(p, "com", node, "", true, Eigen::Vector3d::Zero()));
  // Principal moments about the bone frame's axes: they follow the axes (frame.h).
  b.inertia_diag = frame::to_engine(vec<3>(p, "inertia", node, "", true, Eigen::Vector3d::Zero()));
  if (!(b.inertia_diag.minCoeff() > 0)) fail(node, "inertia", "must be three positive principal moments");
  const Eigen::Vector3d& I = b.inertia_diag;
  const double tol = 1e-6 * I.sum();
  if (I[0] + I[1] < I[2] - tol || I[1] + I[2] < I[0] - tol || I[0] + I[2] < I[1] - tol)
    fail(node, "inertia", "violates the triangle inequality (not a physical body)");
  b.damping = number(p, "damping", node, "", false, 0.0);
  b.armature = number(p, "armature", node, "", false, 0.0);
  if (b.damping < 0) fail(node, "damping", "must not be negative");
  if (b.armature < 0) fail(node, "armature", "must not be negative");
  const nlohmann::json* shapes = member(p, "shapes");
  if (!shapes || !shapes->is_array() || shapes->empty()) fail(node, "shapes", "must list at least one shape");
  for (size_t i = 0; i < shapes->size(); ++i) b.shapes.push_back(parse_shape((*shapes)[i], node, i));
  return b;
}

void parse_collision(const nlohmann::json& extras, CharacterDesc* d) {
  if (!extras.is_object() || !extras.contains("character")) return;
  const nlohmann::json& ch = extras["character"];
  if (!ch.is_object() || !ch.contains("collision")) return;
  const nlohmann::json& col = ch["collision"];
  const std::string field = "scene extras.character.collision";
  if (!col.is_object()) throw Bad{field + " must be an object"};
  if (const nlohmann::json* bit = member(col, "group_bit")) {
    if (!bit->is_number_integer() || bit->get<int64_t>() < 0 || bit->get<int64_t>() > 31)
      throw Bad{field + ".group_bit must be an integer bit index 0..31, got " + bit->dump()};
    d->collision_group_bit = bit->get<int>();
  }
  const nlohmann::json* pairs = member(col, "exclude_pairs");
  if (!pairs) return;
  if (!pairs->is_array()) throw Bad{field + ".exclude_pairs must be an array of [bone, bone] name pairs"};
  for (const auto& pr : *pairs) {
    if (!pr.is_array() || pr.size() != 2 || !pr[0].is_string() || !pr[1].is_string())
      throw Bad{field + ".exclude_pairs entry " + pr.dump() + " must be [\"bone\", \"bone\"]"};
    int a = d->skeleton.find(pr[0].get<std::string>());
    int b = d->skeleton.find(pr[1].get<std::string>());
    if (a < 0 || b < 0)
      throw Bad{field + ".exclude_pairs entry " + pr.dump() + " names a bone that is not in the character"};
    if (a == b) throw Bad{field + ".exclude_pairs entry " + pr.dump() + " pairs a bone with itself"};
    d->exclude_pairs.emplace_back(std::min(a, b), std::max(a, b));
  }
}

}  // namespace

int CharacterDesc::dof() const {
  int n = 0;
  for (const auto& b : bones) n += b.joint == "free" ? 6 : b.joint == "ball" ? 3 : b.joint == "hinge" ? 1 : 0;
  return n;
}

double CharacterDesc::total_mass() const {
  double m = 0;
  for (const auto& b : bones) m += b.mass;
  return m;
}

eng::Result<CharacterDesc> load_character(const GltfScene& scene, const std::string& root_node) {
  const std::string where = "character in '" + scene.path + "': ";
  int root = -1;
  if (root_node.empty()) {
    for (size_t i = 0; i < scene.nodes.size() && root < 0; ++i)
      if (scene.nodes[i].parent < 0) root = static_cast<int>(i);
    if (root < 0) return eng::make_error(where + "no root node (the character root)");
  } else {
    root = scene.find_node(root_node);
    if (root < 0) return eng::make_error(where + "no node named '" + root_node + "' (the character root)");
  }
  CharacterDesc d;
  try {
    // Depth-first pre-order with an explicit stack: (node, parent bone index).
    std::vector<std::pair<int, int>> stack{{root, -1}};
    while (!stack.empty()) {
      auto [ni, parent_bone] = stack.back();
      stack.pop_back();
      if (ni < 0 || ni >= static_cast<int>(scene.nodes.size()))
        throw Bad{"node index " + std::to_string(ni) + " out of range"};
      if (d.bone_node.size() > scene.nodes.size()) throw Bad{"node hierarchy has a cycle"};
      const GltfNode& n = scene.nodes[static_cast<size_t>(ni)];
      const std::string name = n.name.empty() ? "#" + std::to_string(ni) : n.name;
      if (d.skeleton.find(name) >= 0) throw Bad{"two bones are named '" + name + "'"};
      const glm::quat& q = n.rotation;
      if (std::abs(std::abs(q.w) - 1.f) > 1e-5f)
        throw Bad{"node '" + name + "' has a rest rotation; bones must have identity rest rotation"};
      if (glm::length(n.scale - glm::vec3(1.f)) > 1e-5f)
        throw Bad{"node '" + name + "' has a scale; bones must have unit scale"};
      // A joint offset beyond any body's size is a unit or export mistake (glTF is in metres): it is an error, not a
      // limb simulated 1e30 m away (scripts/bad-input tries one).
      const Eigen::Vector3d offset(widen(n.translation.x), widen(n.translation.y), widen(n.translation.z));
      if (!(offset.norm() <= kMaxBoneOffset))
        throw Bad{"node '" + name + "' sits " + number_text(offset.norm()) + " m from its parent; a bone's offset must be " +
                  "under " + number_text(kMaxBoneOffset) + " m (glTF is in metres)"};
      BonePhysics b = parse_bone(n.extras, name, parent_bone < 0);
      const int bone = d.skeleton.size();
      d.skeleton.name.push_back(name);
      d.skeleton.parent.push_back(parent_bone);
      d.skeleton.offset.push_back(offset);
      d.bones.push_back(std::move(b));
      d.bone_node.push_back(ni);
      for (auto it = n.children.rbegin(); it != n.children.rend(); ++it) stack.emplace_back(*it, bone);
    }
    parse_collision(scene.extras, &d);
  } catch (const Bad& e) {
    return eng::make_error(where + e.what);
  } catch (const std::exception& e) {
    return eng::make_error(where + e.what());
  }
  return d;
}

}  // namespace eng::assets
