// engine/assets/frame.h: glTF's +Y-up, +Z-forward axes to the engine's +Z-up, +X-forward axes.
#include "engine/assets/frame.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cstring>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <random>

#include "engine/assets/character.h"
#include "engine/assets/gltf.h"
#include "test_paths.h"

namespace {

using eng::assets::frame::to_engine;
using eng::assets::frame::to_gltf;

TEST(Frame, GltfUpForwardAndLeftBecomeTheEnginesUpForwardAndLeft) {
  // glTF 2.0: +Y up, the asset faces +Z, so (right-handed) its left is +X. Engine: +Z up, faces +X, left +Y.
  EXPECT_EQ(to_engine(glm::vec3(0, 1, 0)), glm::vec3(0, 0, 1));  // up
  EXPECT_EQ(to_engine(glm::vec3(0, 0, 1)), glm::vec3(1, 0, 0));  // forward
  EXPECT_EQ(to_engine(glm::vec3(1, 0, 0)), glm::vec3(0, 1, 0));  // left
}

TEST(Frame, IsAProperRotationNotAMirror) {
  // The columns are the images of the glTF axes; a mirror would flip the handedness of every mesh.
  glm::mat3 m(to_engine(glm::vec3(1, 0, 0)), to_engine(glm::vec3(0, 1, 0)), to_engine(glm::vec3(0, 0, 1)));
  EXPECT_FLOAT_EQ(glm::determinant(m), 1.f);
  // And it is the rotation by 120 deg about (1, 1, 1) / sqrt(3): the quaternion turns vectors the same way.
  const glm::quat r = glm::angleAxis(glm::radians(120.f), glm::normalize(glm::vec3(1, 1, 1)));
  for (const glm::vec3& v : {glm::vec3(0.3f, -1.2f, 2.5f), glm::vec3(1, 0, 0), glm::vec3(0, 0, -4)}) {
    const glm::vec3 rv = r * v;
    const glm::vec3 p = to_engine(v);
    EXPECT_NEAR(rv.x, p.x, 1e-5f);
    EXPECT_NEAR(rv.y, p.y, 1e-5f);
    EXPECT_NEAR(rv.z, p.z, 1e-5f);
  }
}

TEST(Frame, RoundTripsBitForBit) {
  // Only moves numbers: to_gltf(to_engine(v)) is v to the bit, for floats and doubles, signed zeros too.
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(-3.f, 3.f);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 v(u(rng), i % 7 == 0 ? -0.f : u(rng), u(rng));
    const glm::vec3 w = to_gltf(to_engine(v));
    EXPECT_EQ(std::memcmp(&v, &w, sizeof v), 0);
    const Eigen::Vector3d d(u(rng) / 3.0, u(rng) * 1e-7, u(rng));
    const Eigen::Vector3d e = to_gltf(to_engine(d));
    EXPECT_EQ(std::memcmp(d.data(), e.data(), sizeof(double) * 3), 0);
  }
}

TEST(Frame, QuaternionTurnsVectorsConsistently) {
  // Rotating in glTF's frame then converting equals converting both then rotating in the engine's frame.
  const glm::quat qg = glm::normalize(glm::quat(0.8f, 0.1f, -0.5f, 0.3f));
  const glm::quat qe = to_engine(qg);
  EXPECT_EQ(qe.w, qg.w);  // the angle is frame-independent
  const glm::vec3 vg(0.2f, 1.0f, -0.7f);
  const glm::vec3 a = to_engine(qg * vg), b = qe * to_engine(vg);
  EXPECT_NEAR(a.x, b.x, 1e-6f);
  EXPECT_NEAR(a.y, b.y, 1e-6f);
  EXPECT_NEAR(a.z, b.z, 1e-6f);
}

TEST(Frame, AnimationValuesTurnPerKeyAndKeepW) {
  float v[8] = {1, 2, 3, 4, 5, 6, 7, 8};  // two rotation keys x y z w
  eng::assets::frame::values_to_engine(v, 8, 4);
  const float want[8] = {3, 1, 2, 4, 7, 5, 6, 8};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(v[i], want[i]) << i;
  float t[6] = {1, 2, 3, 4, 5, 6};  // two translation keys
  eng::assets::frame::values_to_engine(t, 6, 3);
  const float want_t[6] = {3, 1, 2, 6, 4, 5};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(t[i], want_t[i]) << i;
}

nlohmann::json read_json(const std::string& rel) {
  std::ifstream f(std::string(BOXING_SOURCE_DIR) + rel);
  return nlohmann::json::parse(f);
}

TEST(Frame, BoxerFileIsYUpFacingZ) {
  // On disk (what Blender, three.js and every glTF viewer read) the boxer stands along +Y and his toes
  // point along +Z; loaded, the same data stands along the engine's +Z and faces +X.
  const nlohmann::json j = read_json("/content/boxer/boxer.gltf");
  double up = 0;  // pelvis -> abdomen -> chest -> head translations, along the file's Y
  for (const char* n : {"pelvis", "abdomen", "chest", "head"})
    for (const auto& node : j["nodes"])
      if (node["name"] == n) {
        up += node["translation"][1].get<double>();
        EXPECT_EQ(node["translation"][0].get<double>(), 0.0) << n;
        EXPECT_EQ(node["translation"][2].get<double>(), 0.0) << n;
      }
  EXPECT_NEAR(up, 1.50, 1e-9);  // the neck, 0.97 + 0.10 + 0.18 + 0.25
  for (const auto& node : j["nodes"])
    if (node["name"] == "foot_l") {  // the foot box's centre is ahead of the ankle: forward = +Z
      const auto& pos = node["extras"]["physics"]["shapes"][0]["pos"];
      EXPECT_GT(pos[2].get<double>(), 0.04);
      EXPECT_EQ(pos[0].get<double>(), 0.0);
    }
  for (const auto& node : j["nodes"]) {
    if (node["name"] == "upper_arm_l") {
      EXPECT_GT(node["translation"][0].get<double>(), 0.1);  // left = +X
    }
  }

  auto s = eng::assets::load_gltf(std::string(BOXING_SOURCE_DIR) + "/content/boxer/boxer.gltf");
  ASSERT_TRUE(s.ok()) << s.error();
  auto c = eng::assets::load_character(*s);
  ASSERT_TRUE(c.ok()) << c.error();
  // The engine's values, exactly the decimals make_boxer.py computes in the engine's frame.
  EXPECT_EQ(c->skeleton.offset[0], Eigen::Vector3d(0, 0, 0.97));
  EXPECT_EQ(c->skeleton.offset[4], Eigen::Vector3d(0, 0.19, 0.19));
  const auto& foot = c->bones[static_cast<size_t>(c->skeleton.find("foot_l"))];
  EXPECT_EQ(foot.shapes[0].pos, Eigen::Vector3d(0.05, 0, -0.04));
  EXPECT_EQ(foot.shapes[0].shape.half_extents, Eigen::Vector3d(0.13, 0.05, 0.04));
  const auto& knee = c->bones[static_cast<size_t>(c->skeleton.find("shank_l"))];
  EXPECT_EQ(knee.axis, Eigen::Vector3d(0, 1, 0));
  // Trunk capsules lie across the body: their local Z (the capsule axis) along the engine's Y.
  const auto& pelvis = c->bones[0];
  const Eigen::Vector3d axis = pelvis.shapes[0].quat * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(axis.y(), 1.0, 1e-12);
  // Head mesh above the neck in the engine's frame: the loader turned the vertices too.
  const auto& head = s->nodes[static_cast<size_t>(s->find_node("head"))];
  float top = -1e9f;
  for (const auto& p : s->meshes[static_cast<size_t>(head.mesh)].primitives)
    for (const glm::vec3& v : p.positions) top = std::max(top, v.z);
  EXPECT_NEAR(top, 0.24f, 1e-6f);  // sphere centre 0.12 above the neck + 0.12 radius
}

TEST(Frame, ClipsFileIsYUpAndLoadsZUp) {
  const nlohmann::json j = read_json("/content/clips/boxing_clips.gltf");
  EXPECT_DOUBLE_EQ(j["nodes"][0]["translation"][1].get<double>(), 0.97);  // pelvis height along the file's Y
  auto s = eng::assets::load_gltf(std::string(BOXING_SOURCE_DIR) + "/content/clips/boxing_clips.gltf");
  ASSERT_TRUE(s.ok()) << s.error();
  for (const auto& a : s->animations)
    for (const auto& ch : a.channels)
      if (ch.node == 0 && ch.path == "translation") {
        EXPECT_GT(ch.values[2], 0.05f) << a.name;  // the first key's pelvis height, on the engine's Z
        if (a.name == "guard") {  // (0, 0, 0.93) in the engine's frame, (0, 0.93, 0) in the file
          EXPECT_EQ(ch.values[0], 0.f);
          EXPECT_EQ(ch.values[1], 0.f);
          EXPECT_EQ(ch.values[2], 0.93f);
        }
      }
}

}  // namespace
