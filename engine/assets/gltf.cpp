// glTF loading on top of Debian's shared tinygltf. TINYGLTF_IMPLEMENTATION lives in libtinygltf.so:
// never define it here. All validation of accessors, indices and the node graph is done here so a
// bad file becomes one eng::Error, never an out-of-bounds read.
#include "engine/assets/gltf.h"

#include "engine/assets/frame.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <iterator>
#include <optional>
#include <string_view>

namespace eng::assets {
namespace {

constexpr const char* kFix = ", re-export or regenerate it with scripts/content/ (e.g. make_boxer.py)";

// Thrown inside this file only; load_gltf turns it into an eng::Error.
struct BrokenGltf {
  std::string what;
};

[[noreturn]] void fail(std::string what) { throw BrokenGltf{std::move(what)}; }

nlohmann::json to_json(const tinygltf::Value& v, int depth = 0) {
  if (depth > 256) fail("extras nested too deeply");
  if (v.IsBool()) return v.Get<bool>();
  if (v.IsInt()) return v.Get<int>();
  if (v.IsReal()) return v.Get<double>();
  if (v.IsString()) return v.Get<std::string>();
  if (v.IsBinary()) {
    const auto& b = v.Get<std::vector<unsigned char>>();
    return nlohmann::json::binary(std::vector<std::uint8_t>(b.begin(), b.end()));
  }
  if (v.IsArray()) {
    nlohmann::json a = nlohmann::json::array();
    for (size_t i = 0; i < v.ArrayLen(); ++i) a.push_back(to_json(v.Get(static_cast<int>(i)), depth + 1));
    return a;
  }
  if (v.IsObject()) {
    nlohmann::json o = nlohmann::json::object();
    for (const auto& [k, child] : v.Get<tinygltf::Value::Object>()) o[k] = to_json(child, depth + 1);
    return o;
  }
  return nullptr;
}

const char* type_name(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "other";
  }
}

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
  }
}

int component_size(int ct) {
  switch (ct) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
    default: return 0;
  }
}

// A validated view of one accessor: element i, component c starts at base + i*stride + c*csize.
struct View {
  const unsigned char* base = nullptr;  // null: no bufferView, all zeros (glTF spec)
  size_t count = 0, stride = 0;
  int comps = 0, csize = 0, ctype = 0;
};

View accessor_view(const tinygltf::Model& m, int index, const std::string& what) {
  const std::string label = what + " (accessor " + std::to_string(index) + ")";
  if (index < 0 || index >= static_cast<int>(m.accessors.size()))
    fail(what + " refers to accessor " + std::to_string(index) + " but the file has " +
         std::to_string(m.accessors.size()));
  const tinygltf::Accessor& a = m.accessors[static_cast<size_t>(index)];
  if (a.sparse.isSparse) fail(label + " is sparse, which is not supported");
  View v;
  v.count = a.count;
  v.comps = component_count(a.type);
  v.csize = component_size(a.componentType);
  v.ctype = a.componentType;
  if (v.comps == 0) fail(label + " has an unknown type " + std::to_string(a.type));
  if (v.csize == 0) fail(label + " has an unknown componentType " + std::to_string(a.componentType));
  const size_t elem = static_cast<size_t>(v.comps) * static_cast<size_t>(v.csize);
  if (v.count > (size_t{1} << 26))  // 64 M elements: far beyond any content, protects the allocations below
    fail(label + " has an absurd count " + std::to_string(v.count));
  if (a.bufferView < 0) {  // no data: zeros
    v.stride = elem;
    return v;
  }
  if (a.bufferView >= static_cast<int>(m.bufferViews.size()))
    fail(label + " refers to bufferView " + std::to_string(a.bufferView) + " but the file has " +
         std::to_string(m.bufferViews.size()));
  const tinygltf::BufferView& bv = m.bufferViews[static_cast<size_t>(a.bufferView)];
  if (bv.buffer < 0 || bv.buffer >= static_cast<int>(m.buffers.size()))
    fail("bufferView " + std::to_string(a.bufferView) + " refers to buffer " + std::to_string(bv.buffer) +
         " but the file has " + std::to_string(m.buffers.size()));
  const std::vector<unsigned char>& data = m.buffers[static_cast<size_t>(bv.buffer)].data;
  if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
    fail("bufferView " + std::to_string(a.bufferView) + " (offset " + std::to_string(bv.byteOffset) +
         ", length " + std::to_string(bv.byteLength) + ") lies beyond its buffer of " +
         std::to_string(data.size()) + " bytes");
  v.stride = bv.byteStride ? bv.byteStride : elem;
  if (v.stride < elem) fail(label + " has byteStride " + std::to_string(v.stride) + " smaller than its element");
  if (v.count > 0) {
    const size_t need = a.byteOffset + v.stride * (v.count - 1) + elem;  // overflow-safe enough: checked below
    if (a.byteOffset > bv.byteLength || v.count > (bv.byteLength / v.stride) + 1 || need > bv.byteLength)
      fail(label + " reads " + std::to_string(v.count) + " elements beyond the end of bufferView " +
           std::to_string(a.bufferView) + " (" + std::to_string(bv.byteLength) + " bytes)");
  }
  v.base = data.data() + bv.byteOffset + a.byteOffset;
  return v;
}

// Floats of an accessor that must be float of one of the allowed types.
std::vector<float> read_floats(const tinygltf::Model& m, int index, int type, const std::string& what) {
  View v = accessor_view(m, index, what);
  const tinygltf::Accessor& a = m.accessors[static_cast<size_t>(index)];
  if (a.type != type)
    fail(what + " (accessor " + std::to_string(index) + ") is " + type_name(a.type) + ", expected " +
         type_name(type));
  if (v.ctype != TINYGLTF_COMPONENT_TYPE_FLOAT)
    fail(what + " (accessor " + std::to_string(index) + ") must hold floats (componentType 5126), has " +
         std::to_string(v.ctype));
  std::vector<float> out(v.count * static_cast<size_t>(v.comps), 0.f);
  if (!v.base) return out;
  for (size_t i = 0; i < v.count; ++i)
    std::memcpy(&out[i * static_cast<size_t>(v.comps)], v.base + i * v.stride,
                sizeof(float) * static_cast<size_t>(v.comps));
  // The binary buffer can hold what JSON cannot; glTF allows finite numbers only (the validator's
  // ACCESSOR_INVALID_FLOAT), and one NaN key would turn a whole simulated body into NaN.
  for (size_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i]))
      fail(what + " (accessor " + std::to_string(index) + ") element " +
           std::to_string(i / static_cast<size_t>(v.comps)) + " is NaN or infinite (glTF allows finite numbers only)");
  return out;
}

std::vector<glm::vec3> read_vec3(const tinygltf::Model& m, int index, const std::string& what) {
  std::vector<float> f = read_floats(m, index, TINYGLTF_TYPE_VEC3, what);
  std::vector<glm::vec3> out(f.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = glm::vec3(f[3 * i], f[3 * i + 1], f[3 * i + 2]);
  return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& m, int index, const std::string& what) {
  View v = accessor_view(m, index, what);
  const tinygltf::Accessor& a = m.accessors[static_cast<size_t>(index)];
  if (a.type != TINYGLTF_TYPE_SCALAR)
    fail(what + " (accessor " + std::to_string(index) + ") is " + type_name(a.type) + ", expected SCALAR");
  std::vector<uint32_t> out(v.count, 0u);
  if (!v.base) return out;
  for (size_t i = 0; i < v.count; ++i) {
    const unsigned char* p = v.base + i * v.stride;
    switch (v.ctype) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[i] = *p; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t s;
        std::memcpy(&s, p, 2);
        out[i] = s;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(&out[i], p, 4); break;
      default:
        fail(what + " (accessor " + std::to_string(index) +
             ") must be unsigned byte/short/int (5121/5123/5125), has " + std::to_string(v.ctype));
    }
  }
  return out;
}

GltfPrimitive convert_primitive(const tinygltf::Model& m, const tinygltf::Primitive& p, const std::string& where) {
  GltfPrimitive out;
  auto pos = p.attributes.find("POSITION");
  if (pos == p.attributes.end()) fail(where + " has no POSITION attribute");
  out.positions = read_vec3(m, pos->second, where + " POSITION");
  for (glm::vec3& v : out.positions) v = frame::to_engine(v);
  auto nrm = p.attributes.find("NORMAL");
  if (nrm != p.attributes.end()) {
    out.normals = read_vec3(m, nrm->second, where + " NORMAL");
    for (glm::vec3& v : out.normals) v = frame::to_engine(v);
    if (out.normals.size() != out.positions.size())
      fail(where + " has " + std::to_string(out.normals.size()) + " normals for " +
           std::to_string(out.positions.size()) + " positions");
  }
  if (p.indices >= 0) {
    out.indices = read_indices(m, p.indices, where + " indices");
    for (size_t i = 0; i < out.indices.size(); ++i)
      if (out.indices[i] >= out.positions.size())
        fail(where + " index " + std::to_string(i) + " = " + std::to_string(out.indices[i]) +
             " is out of range (" + std::to_string(out.positions.size()) + " vertices)");
  } else {
    out.indices.resize(out.positions.size());
    for (size_t i = 0; i < out.indices.size(); ++i) out.indices[i] = static_cast<uint32_t>(i);
  }
  const bool triangles = p.mode == TINYGLTF_MODE_TRIANGLES || p.mode < 0;
  if (triangles && out.indices.size() % 3 != 0)
    fail(where + " is a triangle list with " + std::to_string(out.indices.size()) +
         " indices, not a multiple of 3");
  if (p.material < -1 || p.material >= static_cast<int>(m.materials.size()))
    fail(where + " refers to material " + std::to_string(p.material) + " but the file has " +
         std::to_string(m.materials.size()));
  out.material = p.material;
  return out;
}

GltfNode convert_node(const tinygltf::Model& m, const tinygltf::Node& n, size_t index) {
  const std::string where = "node " + std::to_string(index) + " '" + n.name + "'";
  GltfNode out;
  out.name = n.name;
  out.mesh = n.mesh;
  if (n.mesh >= static_cast<int>(m.meshes.size()) || n.mesh < -1)
    fail(where + " refers to mesh " + std::to_string(n.mesh) + " but the file has " +
         std::to_string(m.meshes.size()));
  for (int c : n.children) {
    if (c < 0 || c >= static_cast<int>(m.nodes.size()))
      fail(where + " has child " + std::to_string(c) + " but the file has " + std::to_string(m.nodes.size()) +
           " nodes");
    out.children.push_back(c);
  }
  if (n.matrix.size() == 16) {
    glm::mat4 mat(1.f);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) mat[c][r] = static_cast<float>(n.matrix[static_cast<size_t>(4 * c + r)]);
    out.translation = glm::vec3(mat[3]);
    glm::vec3 sx(mat[0]), sy(mat[1]), sz(mat[2]);
    out.scale = glm::vec3(glm::length(sx), glm::length(sy), glm::length(sz));
    if (out.scale.x > 0.f && out.scale.y > 0.f && out.scale.z > 0.f) {
      glm::mat3 rot(sx / out.scale.x, sy / out.scale.y, sz / out.scale.z);
      if (glm::determinant(rot) < 0.f) {  // mirrored: put the reflection into the scale
        out.scale.x = -out.scale.x;
        rot[0] = -rot[0];
      }
      out.rotation = glm::normalize(glm::quat_cast(rot));
    }
  } else if (!n.matrix.empty()) {
    fail(where + " has a matrix of " + std::to_string(n.matrix.size()) + " numbers, expected 16");
  }
  if (!n.translation.empty()) {
    if (n.translation.size() != 3) fail(where + " translation must have 3 numbers");
    out.translation = glm::vec3(n.translation[0], n.translation[1], n.translation[2]);
  }
  if (!n.rotation.empty()) {
    if (n.rotation.size() != 4) fail(where + " rotation must have 4 numbers (x, y, z, w)");
    // glTF stores xyzw; glm::quat's constructor takes (w, x, y, z).
    out.rotation = glm::quat(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                             static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2]));
  }
  if (!n.scale.empty()) {
    if (n.scale.size() != 3) fail(where + " scale must have 3 numbers");
    out.scale = glm::vec3(n.scale[0], n.scale[1], n.scale[2]);
  }
  // The local transform in the engine's frame: P * (T R S) * P^-1 is T, R and S each turned by P.
  out.translation = frame::to_engine(out.translation);
  out.rotation = frame::to_engine(out.rotation);
  out.scale = frame::to_engine(out.scale);
  out.extras = to_json(n.extras);
  return out;
}

GltfAnimation convert_animation(const tinygltf::Model& m, const tinygltf::Animation& a, size_t index) {
  const std::string where = "animation " + std::to_string(index) + " '" + a.name + "'";
  GltfAnimation out;
  out.name = a.name;
  out.extras = to_json(a.extras);
  for (size_t ci = 0; ci < a.channels.size(); ++ci) {
    const tinygltf::AnimationChannel& ch = a.channels[ci];
    const std::string cw = where + " channel " + std::to_string(ci);
    int comps = 0;
    if (ch.target_path == "translation" || ch.target_path == "scale")
      comps = 3;
    else if (ch.target_path == "rotation")
      comps = 4;
    else
      continue;  // "weights" (morph targets) and extension paths are not used by the engine
    if (ch.target_node < 0 || ch.target_node >= static_cast<int>(m.nodes.size()))
      fail(cw + " targets node " + std::to_string(ch.target_node) + " but the file has " +
           std::to_string(m.nodes.size()) + " nodes");
    if (ch.sampler < 0 || ch.sampler >= static_cast<int>(a.samplers.size()))
      fail(cw + " refers to sampler " + std::to_string(ch.sampler) + " but the animation has " +
           std::to_string(a.samplers.size()));
    const tinygltf::AnimationSampler& s = a.samplers[static_cast<size_t>(ch.sampler)];
    GltfChannel c;
    c.node = ch.target_node;
    c.path = ch.target_path;
    c.interpolation = s.interpolation.empty() ? "LINEAR" : s.interpolation;
    if (c.interpolation != "LINEAR" && c.interpolation != "STEP" && c.interpolation != "CUBICSPLINE")
      fail(cw + " has unknown interpolation '" + c.interpolation + "'");
    c.times = read_floats(m, s.input, TINYGLTF_TYPE_SCALAR, cw + " input (times)");
    c.values = read_floats(m, s.output, comps == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4, cw + " output");
    frame::values_to_engine(c.values.data(), c.values.size(), comps);  // CUBICSPLINE tangents turn alike
    const size_t per_key = static_cast<size_t>(comps) * (c.interpolation == "CUBICSPLINE" ? 3 : 1);
    if (c.values.size() != c.times.size() * per_key)
      fail(cw + " has " + std::to_string(c.times.size()) + " key times but " +
           std::to_string(c.values.size() / static_cast<size_t>(comps)) + " output values");
    for (size_t k = 1; k < c.times.size(); ++k)
      if (!(c.times[k] >= c.times[k - 1])) fail(cw + " key times are not increasing at key " + std::to_string(k));
    out.channels.push_back(std::move(c));
  }
  return out;
}

bool ignore_images(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                   void*) {
  return true;  // the engine does not use textures yet; don't decode them
}

GltfScene convert(const tinygltf::Model& m, const std::string& path) {
  GltfScene s;
  s.path = path;
  for (const auto& mat : m.materials) {
    GltfMaterial g;
    g.name = mat.name;
    const auto& pbr = mat.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
      g.base_color = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2],
                               pbr.baseColorFactor[3]);
    g.roughness = static_cast<float>(pbr.roughnessFactor);
    g.metallic = static_cast<float>(pbr.metallicFactor);
    s.materials.push_back(g);
  }
  for (size_t mi = 0; mi < m.meshes.size(); ++mi) {
    GltfMesh g;
    g.name = m.meshes[mi].name;
    for (size_t pi = 0; pi < m.meshes[mi].primitives.size(); ++pi)
      g.primitives.push_back(convert_primitive(
          m, m.meshes[mi].primitives[pi],
          "mesh " + std::to_string(mi) + " '" + g.name + "' primitive " + std::to_string(pi)));
    s.meshes.push_back(std::move(g));
  }
  for (size_t ni = 0; ni < m.nodes.size(); ++ni) s.nodes.push_back(convert_node(m, m.nodes[ni], ni));
  for (size_t ni = 0; ni < s.nodes.size(); ++ni)
    for (int c : s.nodes[ni].children) {
      GltfNode& child = s.nodes[static_cast<size_t>(c)];
      if (child.parent != -1 || c == static_cast<int>(ni))
        fail("node " + std::to_string(c) + " '" + child.name + "' has more than one parent");
      child.parent = static_cast<int>(ni);
    }
  for (size_t ni = 0; ni < s.nodes.size(); ++ni) {  // a cycle would make world_matrix loop forever
    int p = s.nodes[ni].parent;
    for (size_t steps = 0; p != -1; ++steps) {
      if (steps > s.nodes.size()) fail("node " + std::to_string(ni) + " '" + s.nodes[ni].name + "' is in a cycle");
      p = s.nodes[static_cast<size_t>(p)].parent;
    }
  }
  for (size_t ai = 0; ai < m.animations.size(); ++ai) s.animations.push_back(convert_animation(m, m.animations[ai], ai));
  if (!m.scenes.empty()) s.extras = to_json(m.scenes[0].extras);
  return s;
}

}  // namespace

int GltfScene::find_node(const std::string& name) const {
  for (size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].name == name) return static_cast<int>(i);
  return -1;
}

glm::mat4 GltfScene::world_matrix(int node) const {
  glm::mat4 world(1.f);
  for (size_t steps = 0; node >= 0 && node < static_cast<int>(nodes.size()) && steps <= nodes.size(); ++steps) {
    const GltfNode& n = nodes[static_cast<size_t>(node)];
    glm::mat4 local = glm::translate(glm::mat4(1.f), n.translation) * glm::mat4_cast(n.rotation) *
                      glm::scale(glm::mat4(1.f), n.scale);
    world = local * world;
    node = n.parent;
  }
  return world;
}

namespace {

// One tinygltf load (`load` calls the loader's ...FromFile or ...FromMemory) and its conversion; every failure,
// thrown or returned, becomes one eng::Error naming `name`.
template <class Load>
eng::Result<GltfScene> parse_with(const std::string& name, Load&& load) {
  try {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&ignore_images, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    if (!load(loader, &model, &err, &warn)) {
      while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
      for (char& c : err)
        if (c == '\n') c = ';';
      return eng::make_error("broken glTF '" + name + "': " + (err.empty() ? "tinygltf could not parse it" : err) +
                             kFix);
    }
    return convert(model, name);
  } catch (const BrokenGltf& e) {
    return eng::make_error("broken glTF '" + name + "': " + e.what + kFix);
  } catch (const std::exception& e) {  // nlohmann parse/type errors thrown inside tinygltf
    return eng::make_error("broken glTF '" + name + "': invalid JSON or structure (" + e.what() + ")" + kFix);
  } catch (...) {
    return eng::make_error("broken glTF '" + name + "': unknown parse failure" + std::string(kFix));
  }
}

// File system callbacks for bytes in memory: no file exists, so an external buffer or image is an error.
bool no_file_exists(const std::string&, void*) { return false; }
std::string same_path(const std::string& path, void*) { return path; }
bool no_file_read(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
  if (err) *err += "external file '" + path + "' is not read when loading from memory\n";
  return false;
}
bool no_file_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "no file is written\n";
  return false;
}

}  // namespace

namespace {

// tinygltf turns the parsed JSON into its own values recursively, one call per level: nesting deep enough
// ("extras": [[[[...) overflows the stack, e.g. 20,000 levels (a 40 kB file) under ASan. The depth is counted before
// parsing (brackets outside strings); the committed content nests 8 deep at most.
constexpr int kMaxJsonDepth = 512;

bool json_too_deep(std::string_view json) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (in_string) {
      if (c == '\\') ++i;  // the escaped character
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

// The JSON of a .gltf, or the first chunk of a .glb (its declared length clamped to the bytes there; tinygltf
// checks the header itself).
std::string_view json_text(const unsigned char* data, size_t size, bool binary) {
  const char* text = reinterpret_cast<const char*>(data);
  if (!binary) return {text, size};
  if (size < 20) return {};
  uint32_t length = 0;
  std::memcpy(&length, data + 12, 4);
  return {text + 20, std::min<size_t>(length, size - 20)};
}

// Both entry points end here. base_dir: where external buffers are read from; nullopt: none is read (from memory).
eng::Result<GltfScene> parse_bytes(const unsigned char* data, size_t size, const std::string& name,
                                   const std::optional<std::string>& base_dir) {
  if (size == 0) return eng::make_error("broken glTF '" + name + "': the file is empty" + kFix);
  if (size > (size_t{1} << 30))  // tinygltf takes an unsigned int size; content is a few MB
    return eng::make_error("broken glTF '" + name + "': " + std::to_string(size) + " bytes is too large" + kFix);
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  if (json_too_deep(json_text(data, size, binary)))
    return eng::make_error("broken glTF '" + name + "': JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                           " levels" + kFix);
  return parse_with(name, [&](tinygltf::TinyGLTF& loader, tinygltf::Model* model, std::string* err, std::string* warn) {
    if (!base_dir) loader.SetFsCallbacks({&no_file_exists, &same_path, &no_file_read, &no_file_write, nullptr});
    const std::string dir = base_dir.value_or("");
    const auto n = static_cast<unsigned int>(size);
    return binary ? loader.LoadBinaryFromMemory(model, err, warn, data, n, dir)
                  : loader.LoadASCIIFromString(model, err, warn, reinterpret_cast<const char*>(data), n, dir);
  });
}

}  // namespace

eng::Result<GltfScene> load_gltf(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return eng::make_error("cannot open content file '" + path +
                           "': file not found (run from the repo root or pass the right path)");
  std::ifstream f(path, std::ios::binary);
  if (!f) return eng::make_error("cannot open content file '" + path + "': cannot read it (check permissions)");
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  // What tinygltf's Load...FromFile do: read the file, then parse it with external files relative to its folder.
  return parse_bytes(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), path,
                     std::filesystem::path(path).parent_path().string());
}

eng::Result<GltfScene> load_gltf_memory(const unsigned char* data, size_t size, const std::string& name) {
  return parse_bytes(data, size, name, std::nullopt);
}

}  // namespace eng::assets
