#include "engine/assets/gltf.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <iterator>
#include <limits>
#include <string>
#include <vector>
#include "test_paths.h"

namespace {

using eng::assets::load_gltf;

std::string data(const std::string& name) { return std::string(BOXING_SOURCE_DIR) + "/tests/assets/data/" + name; }

void expect_cube(const eng::assets::GltfScene& s) {
  ASSERT_EQ(s.nodes.size(), 1u);
  EXPECT_EQ(s.nodes[0].name, "cube");
  EXPECT_EQ(s.nodes[0].mesh, 0);
  EXPECT_EQ(s.nodes[0].parent, -1);
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(s.meshes[0].primitives.size(), 1u);
  const auto& p = s.meshes[0].primitives[0];
  ASSERT_EQ(p.positions.size(), 24u);
  ASSERT_EQ(p.normals.size(), 24u);
  ASSERT_EQ(p.indices.size(), 36u);
  EXPECT_EQ(p.material, 0);
  for (const auto& v : p.positions) {
    EXPECT_FLOAT_EQ(std::abs(v.x), 0.5f);
    EXPECT_FLOAT_EQ(std::abs(v.y), 0.5f);
    EXPECT_FLOAT_EQ(std::abs(v.z), 0.5f);
  }
  // First face is the file's +X, which is the engine's +Y (glTF's left = the engine's left; frame.h):
  // the interleaved normal (stride 24) must read back as (0, 1, 0).
  EXPECT_FLOAT_EQ(p.normals[0].x, 0.f);
  EXPECT_FLOAT_EQ(p.normals[0].y, 1.f);
  EXPECT_FLOAT_EQ(p.normals[0].z, 0.f);
  EXPECT_FLOAT_EQ(p.positions[0].y, 0.5f);
  EXPECT_EQ(p.indices[0], 0u);
  EXPECT_EQ(p.indices[35], 23u);
  for (uint32_t i : p.indices) EXPECT_LT(i, 24u);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "red");
  EXPECT_FLOAT_EQ(s.materials[0].base_color.r, 1.f);
  EXPECT_FLOAT_EQ(s.materials[0].base_color.g, 0.f);
  EXPECT_FLOAT_EQ(s.materials[0].roughness, 0.5f);
  EXPECT_FLOAT_EQ(s.materials[0].metallic, 0.f);
}

TEST(Gltf, LoadsEmbeddedCube) {
  auto r = load_gltf(data("cube.gltf"));
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r->path, data("cube.gltf"));
  expect_cube(*r);
}

TEST(Gltf, LoadsGlbCubeWithUint32Indices) {
  auto r = load_gltf(data("cube.glb"));
  ASSERT_TRUE(r.ok()) << r.error();
  expect_cube(*r);
}

TEST(Gltf, LoadsExternalBinWithUbyteIndices) {
  auto r = load_gltf(data("cube_external.gltf"));
  ASSERT_TRUE(r.ok()) << r.error();
  expect_cube(*r);
}

TEST(Gltf, HierarchyParentsExtrasAndWorldMatrix) {
  auto r = load_gltf(data("hierarchy.gltf"));
  ASSERT_TRUE(r.ok()) << r.error();
  const auto& s = *r;
  ASSERT_EQ(s.nodes.size(), 2u);
  EXPECT_EQ(s.find_node("root"), 0);
  EXPECT_EQ(s.find_node("child"), 1);
  EXPECT_EQ(s.find_node("nope"), -1);
  EXPECT_EQ(s.nodes[0].parent, -1);
  EXPECT_EQ(s.nodes[1].parent, 0);
  ASSERT_EQ(s.nodes[0].children.size(), 1u);
  EXPECT_EQ(s.nodes[0].children[0], 1);
  EXPECT_EQ(s.nodes[0].extras["tag"], "root");
  EXPECT_EQ(s.nodes[0].extras["count"], 3);
  EXPECT_DOUBLE_EQ(s.nodes[0].extras["list"][1].get<double>(), 2.5);
  EXPECT_EQ(s.nodes[0].extras["list"][2], "x");
  EXPECT_EQ(s.nodes[0].extras["obj"]["flag"], true);
  EXPECT_DOUBLE_EQ(s.nodes[1].extras["physics"]["mass"].get<double>(), 1.5);
  EXPECT_EQ(s.extras["level"], "test");
  EXPECT_EQ(s.extras["version"], 2);
  // Rotation is stored xyzw in the file, glm (w, x, y, z) in memory: 90 deg about the file's Z (glTF's
  // forward), which is the engine's X. Translations (1, 0, 0) and (0, 2, 0) in the file are the engine's
  // (0, 1, 0) and (0, 0, 2): engine (x, y, z) = glTF (z, x, y).
  EXPECT_NEAR(s.nodes[1].rotation.w, 0.7071068f, 1e-6f);
  EXPECT_NEAR(s.nodes[1].rotation.x, 0.7071068f, 1e-6f);
  EXPECT_FLOAT_EQ(s.nodes[0].translation.y, 1.f);
  EXPECT_FLOAT_EQ(s.nodes[1].translation.z, 2.f);
  EXPECT_FLOAT_EQ(s.nodes[1].scale.x, 2.f);
  const glm::mat4 w = s.world_matrix(1);
  const glm::vec4 o = w * glm::vec4(0, 0, 0, 1);  // file (1, 2, 0)
  EXPECT_NEAR(o.x, 0.f, 1e-5f);
  EXPECT_NEAR(o.y, 1.f, 1e-5f);
  EXPECT_NEAR(o.z, 2.f, 1e-5f);
  // The file's (1, 0, 0): scale 2, rotate to the file's +Y, + (0, 2, 0), + (1, 0, 0) = file (1, 4, 0).
  const glm::vec4 x = w * glm::vec4(0, 1, 0, 1);
  EXPECT_NEAR(x.x, 0.f, 1e-5f);
  EXPECT_NEAR(x.y, 1.f, 1e-5f);
  EXPECT_NEAR(x.z, 4.f, 1e-5f);
  const glm::vec4 bad = s.world_matrix(99) * glm::vec4(1, 2, 3, 1);
  EXPECT_FLOAT_EQ(bad.y, 2.f);  // identity for an invalid index
}

TEST(Gltf, AnimationChannels) {
  auto r = load_gltf(data("anim.gltf"));
  ASSERT_TRUE(r.ok()) << r.error();
  ASSERT_EQ(r->animations.size(), 1u);
  const auto& a = r->animations[0];
  EXPECT_EQ(a.name, "wave");
  EXPECT_EQ(a.extras["loop"], true);
  ASSERT_EQ(a.channels.size(), 2u);
  const auto& rot = a.channels[0];
  EXPECT_EQ(rot.node, 0);
  EXPECT_EQ(rot.path, "rotation");
  EXPECT_EQ(rot.interpolation, "LINEAR");
  ASSERT_EQ(rot.times.size(), 3u);
  ASSERT_EQ(rot.values.size(), 12u);
  EXPECT_FLOAT_EQ(rot.times[1], 0.5f);
  EXPECT_FLOAT_EQ(rot.values[3], 1.f);          // key 0: identity, xyzw
  EXPECT_FLOAT_EQ(rot.values[4], 0.3826834f);   // key 1: the file's z is the engine's x
  EXPECT_FLOAT_EQ(rot.values[6], 0.f);
  EXPECT_FLOAT_EQ(rot.values[11], 0.7071068f);  // key 2: w
  const auto& tr = a.channels[1];
  EXPECT_EQ(tr.path, "translation");
  EXPECT_EQ(tr.interpolation, "STEP");
  ASSERT_EQ(tr.values.size(), 6u);
  EXPECT_FLOAT_EQ(tr.values[3], 1.f);  // key 1: the file's (0, 0, 1) is the engine's (1, 0, 0)
  EXPECT_FLOAT_EQ(tr.values[5], 0.f);
}

TEST(Gltf, MissingFileNamesThePath) {
  const std::string path = data("does_not_exist.gltf");
  auto r = load_gltf(path);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("cannot open content file '" + path + "'"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("file not found"), std::string::npos) << r.error();
}

void expect_broken(const std::string& name, const std::string& what) {
  const std::string path = data(name);
  auto r = load_gltf(path);
  ASSERT_FALSE(r.ok()) << name << " loaded but is broken";
  EXPECT_NE(r.error().find("broken glTF '" + path + "'"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find(what), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("scripts/content/"), std::string::npos) << r.error();
}

TEST(Gltf, BrokenJsonIsAnError) { expect_broken("broken_json.gltf", ""); }
TEST(Gltf, AccessorOutOfRangeIsAnError) { expect_broken("accessor_out_of_range.gltf", "accessor"); }
TEST(Gltf, BadIndicesAreAnError) { expect_broken("bad_indices.gltf", "out of range"); }
TEST(Gltf, MissingPositionIsAnError) { expect_broken("no_position.gltf", "POSITION"); }

TEST(Gltf, GarbageInputNeverCrashes) {
  const std::string dir = std::string(BOXING_BINARY_DIR) + "/";
  const std::string cases[] = {
      "",
      "{",
      "[]",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":5}",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[0]}]}",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[7]}]}",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"children\":[1]},{\"children\":[0]}]}",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"mesh\":3}]}",
      "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,\"uri\":\"data:application/"
      "octet-stream;base64,AAAAAA==\"}],\"bufferViews\":[{\"buffer\":0,\"byteOffset\":2,\"byteLength\":100}],"
      "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]}",
      "glTF\x02\0\0\0\xff\xff\xff\x7f",
  };
  int i = 0;
  for (const std::string& text : cases) {
    const std::string path = dir + "assets_garbage_" + std::to_string(i++) + ".gltf";
    {
      std::ofstream f(path, std::ios::binary);
      f << text;
    }
    auto r = load_gltf(path);  // ok or a clear error; must not crash
    if (!r.ok()) {
      EXPECT_NE(r.error().find(path), std::string::npos) << r.error();
    }
    std::remove(path.c_str());
  }
}

std::string file_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

eng::Result<eng::assets::GltfScene> from_memory(const std::string& bytes, const std::string& name = "mem.gltf") {
  return eng::assets::load_gltf_memory(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), name);
}

// A .glb of `json` whose BIN chunk holds `floats`.
std::string glb(const std::string& json, const std::vector<float>& floats) {
  std::string js = json;
  while (js.size() % 4) js += ' ';
  std::string bin(floats.size() * 4, '\0');
  std::memcpy(bin.data(), floats.data(), bin.size());
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const uint32_t total = 12 + 8 + static_cast<uint32_t>(js.size()) + 8 + static_cast<uint32_t>(bin.size());
  return "glTF" + u32(2) + u32(total) + u32(static_cast<uint32_t>(js.size())) + "JSON" + js +
         u32(static_cast<uint32_t>(bin.size())) + std::string("BIN\0", 4) + bin;
}

TEST(Gltf, LoadsFromMemoryAsFromAFile) {
  for (const char* f : {"cube.gltf", "cube.glb"}) {
    auto r = from_memory(file_bytes(data(f)), f);
    ASSERT_TRUE(r.ok()) << r.error();
    EXPECT_EQ(r->path, f);
    expect_cube(*r);
  }
}

TEST(Gltf, FromMemoryAnExternalBufferIsAnErrorAndNoFileIsRead) {
  auto r = from_memory(file_bytes(data("cube_external.gltf")), "external.gltf");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("external.gltf"), std::string::npos) << r.error();
  EXPECT_NE(r.error().find("cube_external.bin"), std::string::npos) << r.error();
}

// Found by fuzz_clips (tests/fuzz/): the binary buffer can hold NaN and infinity, which JSON cannot; they loaded
// as they were, and one NaN animation key made a NaN pose. glTF allows finite numbers only.
TEST(Gltf, NanOrInfinityInAnAccessorIsAnError) {
  const std::string json =
      R"({"asset":{"version":"2.0"},"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
      R"("buffers":[{"byteLength":36}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}]})";
  ASSERT_TRUE(from_memory(glb(json, {0, 0, 0, 1, 0, 0, 0, 1, 0})).ok());
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    auto r = from_memory(glb(json, {0, 0, 0, 1, 0, 0, 0, bad, 0}));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find("POSITION (accessor 0) element 2 is NaN or infinite"), std::string::npos) << r.error();
  }
}

// Found with a directed input while fuzzing (the fuzzer's inputs stay under 20 kB, too short for it): tinygltf
// converts the JSON into its values recursively, and 30,000 nested arrays (a 60 kB file) crashed the optimised
// loader with a stack overflow. The depth is now counted before parsing.
TEST(Gltf, DeeplyNestedJsonIsAnErrorNotAStackOverflow) {
  const std::string deep = R"({"asset":{"version":"2.0"},"nodes":[{"extras":)" + std::string(100000, '[') +
                           std::string(100000, ']') + "}]}";
  auto r = from_memory(deep, "deep.gltf");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("deep.gltf': JSON nested deeper than 512 levels"), std::string::npos) << r.error();
  const std::string path = std::string(BOXING_BINARY_DIR) + "/assets_deep.gltf";
  std::ofstream(path, std::ios::binary) << deep;
  auto f = load_gltf(path);  // the game's route
  ASSERT_FALSE(f.ok());
  EXPECT_NE(f.error().find("nested deeper"), std::string::npos) << f.error();
  std::remove(path.c_str());
  // Brackets inside strings are text, and ordinary nesting loads.
  const std::string in_string = R"({"asset":{"version":"2.0"},"nodes":[{"name":")" + std::string(1000, '[') +
                                R"(\"","extras":)" + std::string(100, '[') + std::string(100, ']') + "}]}";
  auto s = from_memory(in_string);
  ASSERT_TRUE(s.ok()) << s.error();
  EXPECT_EQ(s->nodes.at(0).name, std::string(1000, '[') + "\"");
}

TEST(Gltf, BoxerContentLoads) {
  auto r = load_gltf(std::string(BOXING_SOURCE_DIR) + "/content/boxer/boxer.gltf");
  ASSERT_TRUE(r.ok()) << r.error();
  const char* bones[] = {"pelvis",  "abdomen", "chest",   "head",        "upper_arm_l", "forearm_l",
                         "glove_l", "upper_arm_r", "forearm_r", "glove_r", "thigh_l",     "shank_l",
                         "foot_l",  "thigh_r", "shank_r", "foot_r"};
  int n = 0;
  for (const char* b : bones) {
    const int i = r->find_node(b);
    ASSERT_GE(i, 0) << b;
    EXPECT_TRUE(r->nodes[static_cast<size_t>(i)].extras.contains("physics")) << b;
    EXPECT_GE(r->nodes[static_cast<size_t>(i)].mesh, 0) << b;
    ++n;
  }
  EXPECT_EQ(n, 16);
  int with_physics = 0;
  for (const auto& node : r->nodes) with_physics += node.extras.contains("physics") ? 1 : 0;
  EXPECT_EQ(with_physics, 16);
  EXPECT_TRUE(r->extras.contains("character"));
  for (const char* m : {"skin", "team", "glove", "shoe", "shorts"}) {
    bool found = false;
    for (const auto& mat : r->materials) found = found || mat.name == m;
    EXPECT_TRUE(found) << m;
  }
  // Rest pose in the engine's frame (Z up): root joint at z = 0.97, glove wrist at
  // 0.97 + 0.10 + 0.18 + 0.19 - 0.30 - 0.26.
  const glm::vec4 root = r->world_matrix(r->find_node("pelvis")) * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(root.z, 0.97f, 1e-6f);
  const glm::vec4 wrist = r->world_matrix(r->find_node("glove_l")) * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(wrist.y, 0.19f, 1e-6f);
  EXPECT_NEAR(wrist.z, 0.88f, 1e-5f);
}

}  // namespace
