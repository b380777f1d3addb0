#pragma once
// glTF 2.0 loading (.gltf with embedded base64 or external .bin, and .glb) into plain engine structs.
// Uses Debian's shared tinygltf (TinyGLTF::TinyGLTF); never define TINYGLTF_IMPLEMENTATION.
// Every failure (missing file, broken JSON, accessor out of range, bad indices) becomes an
// eng::Error naming the file and the problem; load_gltf never crashes on bad input.
//
// Frames: glTF files are +Y up with the asset facing +Z (the spec); everything load_gltf returns is
// in the engine's frame, +Z up, facing +X (engine/assets/frame.h: an exact axis permutation). Extras
// are returned as stored (glTF axes): their readers (load_character) convert what they read.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "engine/core/result.h"

namespace eng::assets {

struct GltfNode {
  std::string name;
  int parent = -1;              // computed from the children lists; -1 for roots
  std::vector<int> children;
  glm::vec3 translation{0.f};
  glm::quat rotation{1.f, 0.f, 0.f, 0.f};  // glm order (w, x, y, z)
  glm::vec3 scale{1.f};
  int mesh = -1;
  nlohmann::json extras;        // null when the node has no extras
};

struct GltfPrimitive {
  std::vector<glm::vec3> positions, normals;  // normals empty when the file has none
  std::vector<uint32_t> indices;              // generated 0..n-1 when the primitive is not indexed
  int material = -1;
};

struct GltfMesh {
  std::string name;
  std::vector<GltfPrimitive> primitives;
};

struct GltfMaterial {
  std::string name;
  glm::vec4 base_color{1.f};
  float roughness = 1.f, metallic = 1.f;
};

struct GltfChannel {
  int node = -1;
  std::string path;           // "translation" | "rotation" | "scale"
  std::string interpolation;  // LINEAR | STEP | CUBICSPLINE
  std::vector<float> times;
  std::vector<float> values;  // flattened, 3 or 4 floats per key (xyzw for rotation, glTF's order; engine axes);
                              // CUBICSPLINE keeps glTF's (in-tangent, value, out-tangent) triplets
};

struct GltfAnimation {
  std::string name;
  std::vector<GltfChannel> channels;
  nlohmann::json extras;
};

struct GltfScene {
  std::string path;
  std::vector<GltfNode> nodes;
  std::vector<GltfMesh> meshes;
  std::vector<GltfMaterial> materials;
  std::vector<GltfAnimation> animations;
  nlohmann::json extras;  // first scene's extras

  // Index of the first node with this name, -1 when none.
  int find_node(const std::string& name) const;
  // Node-to-world matrix (T * R * S chained through parents); identity for an invalid index.
  glm::mat4 world_matrix(int node) const;
};

eng::Result<GltfScene> load_gltf(const std::string& path);  // .gltf (embedded base64 or external .bin) and .glb
// The same from bytes in memory (a .glb when they start with "glTF", else .gltf JSON); `name` stands for the path
// in errors and in GltfScene::path. Only embedded data is read (data: URIs, the GLB's BIN chunk): an external
// buffer is an error, no file is opened. The fuzz harnesses (tests/fuzz/) enter here.
eng::Result<GltfScene> load_gltf_memory(const unsigned char* data, size_t size, const std::string& name);

}  // namespace eng::assets
