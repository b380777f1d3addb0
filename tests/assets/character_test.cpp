#include "engine/assets/character.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include "test_paths.h"

namespace {

using eng::assets::load_character;
using eng::assets::load_gltf;

std::string boxer_path() { return std::string(BOXING_SOURCE_DIR) + "/content/boxer/boxer.gltf"; }

eng::assets::CharacterDesc boxer() {
  auto s = load_gltf(boxer_path());
  EXPECT_TRUE(s.ok()) << s.error();
  if (!s.ok()) return {};
  auto c = load_character(*s);
  EXPECT_TRUE(c.ok()) << c.error();
  if (!c.ok()) return {};
  return std::move(c).value();
}

TEST(Character, BoxerSkeleton) {
  auto c = boxer();
  ASSERT_EQ(c.skeleton.size(), 16);
  ASSERT_EQ(c.bones.size(), 16u);
  ASSERT_EQ(c.bone_node.size(), 16u);
  const char* names[] = {"pelvis",  "abdomen", "chest",   "head",        "upper_arm_l", "forearm_l",
                         "glove_l", "upper_arm_r", "forearm_r", "glove_r", "thigh_l",     "shank_l",
                         "foot_l",  "thigh_r", "shank_r", "foot_r"};
  const int parents[] = {-1, 0, 1, 2, 2, 4, 5, 2, 7, 8, 0, 10, 11, 0, 13, 14};
  for (int i = 0; i < 16; ++i) {
    EXPECT_EQ(c.skeleton.name[i], names[i]);
    EXPECT_EQ(c.skeleton.parent[i], parents[i]) << names[i];
    if (i > 0) {
      EXPECT_LT(c.skeleton.parent[i], i);
    }
  }
  EXPECT_TRUE(c.skeleton.offset[0].isApprox(Eigen::Vector3d(0, 0, 0.97)));
  EXPECT_TRUE(c.skeleton.offset[4].isApprox(Eigen::Vector3d(0, 0.19, 0.19)));
  EXPECT_TRUE(c.skeleton.offset[12].isApprox(Eigen::Vector3d(0, 0, -0.42)));
}

TEST(Character, BoxerMassAndDof) {
  auto c = boxer();
  double m = 0;
  int dof = 0;
  for (const auto& b : c.bones) {
    m += b.mass;
    dof += b.joint == "free" ? 6 : b.joint == "ball" ? 3 : b.joint == "hinge" ? 1 : 0;
    EXPECT_GT(b.inertia_diag.minCoeff(), 0.0);
    EXPECT_FALSE(b.shapes.empty());
  }
  EXPECT_NEAR(m, 75.0, 0.5);
  EXPECT_NEAR(c.total_mass(), m, 1e-12);
  EXPECT_EQ(dof, 37);
  EXPECT_EQ(c.dof(), 37);
  const auto& elbow = c.bones[static_cast<size_t>(c.skeleton.find("forearm_l"))];
  EXPECT_EQ(elbow.joint, "hinge");
  EXPECT_TRUE(elbow.axis.isApprox(Eigen::Vector3d(0, -1, 0)));
  EXPECT_DOUBLE_EQ(elbow.lower, 0.0);
  EXPECT_DOUBLE_EQ(elbow.upper, 2.6);
  const auto& knee = c.bones[static_cast<size_t>(c.skeleton.find("shank_r"))];
  EXPECT_TRUE(knee.axis.isApprox(Eigen::Vector3d(0, 1, 0)));
  EXPECT_DOUBLE_EQ(knee.upper, 2.5);
  EXPECT_EQ(c.bones[static_cast<size_t>(c.skeleton.find("glove_r"))].joint, "fixed");
  EXPECT_EQ(c.bones[0].joint, "free");
}

// World position of a bone-frame point in the rest pose (rest rotations are identity).
Eigen::Vector3d rest_world(const eng::assets::CharacterDesc& c, int bone, const Eigen::Vector3d& p) {
  Eigen::Vector3d w = p;
  for (int b = bone; b >= 0; b = c.skeleton.parent[static_cast<size_t>(b)]) w += c.skeleton.offset[static_cast<size_t>(b)];
  return w;
}

TEST(Character, SoleAtZeroInRest) {
  auto c = boxer();
  double lowest = 1e9;
  for (int i = 0; i < c.skeleton.size(); ++i)
    for (const auto& s : c.bones[static_cast<size_t>(i)].shapes) {
      const Eigen::Matrix3d R = s.quat.toRotationMatrix();
      double dz = 0;  // half height of the shape along world Z
      using eng::physics::ShapeType;
      if (s.shape.type == ShapeType::Box)
        dz = (R.cwiseAbs() * s.shape.half_extents).z();
      else if (s.shape.type == ShapeType::Capsule)
        dz = s.shape.radius + std::abs(R(2, 2)) * s.shape.half_length;
      else
        dz = s.shape.radius;
      lowest = std::min(lowest, rest_world(c, i, s.pos).z() - dz);
    }
  EXPECT_NEAR(lowest, 0.0, 1e-6);
  const Eigen::Vector3d ankle = rest_world(c, c.skeleton.find("foot_l"), Eigen::Vector3d::Zero());
  EXPECT_NEAR(ankle.z(), 0.08, 1e-9);
}

TEST(Character, LeftRightMirrorSymmetry) {
  auto c = boxer();
  for (const char* part : {"upper_arm", "forearm", "glove", "thigh", "shank", "foot"}) {
    const int l = c.skeleton.find(std::string(part) + "_l");
    const int r = c.skeleton.find(std::string(part) + "_r");
    ASSERT_GE(l, 0);
    ASSERT_GE(r, 0);
    const auto& bl = c.bones[static_cast<size_t>(l)];
    const auto& br = c.bones[static_cast<size_t>(r)];
    EXPECT_DOUBLE_EQ(bl.mass, br.mass) << part;
    EXPECT_TRUE(bl.inertia_diag.isApprox(br.inertia_diag)) << part;
    const Eigen::Vector3d mirror(1, -1, 1);
    EXPECT_TRUE(c.skeleton.offset[static_cast<size_t>(l)].isApprox(
        c.skeleton.offset[static_cast<size_t>(r)].cwiseProduct(mirror)))
        << part;
    EXPECT_TRUE((bl.com - br.com.cwiseProduct(mirror)).norm() < 1e-12) << part;
    EXPECT_EQ(bl.joint, br.joint);
    EXPECT_EQ(bl.shapes.size(), br.shapes.size());
  }
  EXPECT_GT(c.skeleton.offset[static_cast<size_t>(c.skeleton.find("upper_arm_l"))].y(), 0.0);  // left = +Y
}

TEST(Character, CollisionGroupAndExcludedPairs) {
  auto c = boxer();
  EXPECT_EQ(c.collision_group_bit, 1);
  EXPECT_FALSE(c.exclude_pairs.empty());
  for (auto [a, b] : c.exclude_pairs) {
    EXPECT_LT(a, b);
    EXPECT_NE(c.skeleton.parent[static_cast<size_t>(b)], a) << "parent/child pairs are implicit";
  }
  const auto has = [&](const char* x, const char* y) {
    const std::pair<int, int> p(std::min(c.skeleton.find(x), c.skeleton.find(y)),
                                std::max(c.skeleton.find(x), c.skeleton.find(y)));
    return std::find(c.exclude_pairs.begin(), c.exclude_pairs.end(), p) != c.exclude_pairs.end();
  };
  EXPECT_TRUE(has("abdomen", "upper_arm_l"));
  EXPECT_TRUE(has("abdomen", "upper_arm_r"));
  EXPECT_FALSE(has("glove_l", "head"));  // a boxer can hit himself in the face
}

TEST(Character, MissingMassNamesTheNode) {
  auto s = load_gltf(std::string(BOXING_SOURCE_DIR) + "/tests/assets/data/character_missing_mass.gltf");
  ASSERT_TRUE(s.ok()) << s.error();
  auto c = load_character(*s);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().find("thigh_l"), std::string::npos) << c.error();
  EXPECT_NE(c.error().find("mass"), std::string::npos) << c.error();
}

TEST(Character, MissingRootAndBadFieldsAreErrors) {
  auto s = load_gltf(boxer_path());
  ASSERT_TRUE(s.ok()) << s.error();
  auto c = load_character(*s, "no_such_bone");
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().find("no_such_bone"), std::string::npos);

  auto scene = *s;
  const int chest = scene.find_node("chest");
  scene.nodes[static_cast<size_t>(chest)].extras["physics"]["joint"] = "slider";
  c = load_character(scene);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().find("chest"), std::string::npos) << c.error();
  EXPECT_NE(c.error().find("joint"), std::string::npos) << c.error();

  scene = *s;
  scene.nodes[static_cast<size_t>(chest)].extras["physics"]["shapes"] = nlohmann::json::array();
  c = load_character(scene);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().find("shapes"), std::string::npos) << c.error();

  scene = *s;
  scene.nodes[static_cast<size_t>(chest)].extras["physics"]["inertia"] = {0.1, -1.0, 0.1};
  c = load_character(scene);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().find("inertia"), std::string::npos) << c.error();

  // A joint offset no body has (a unit mistake; found by scripts/bad-input: 1e30 m loaded and simulated).
  for (const float far : {1e30f, 11.0f, std::numeric_limits<float>::infinity()}) {
    scene = *s;
    scene.nodes[static_cast<size_t>(chest)].translation = glm::vec3(far, 0.f, 0.f);
    c = load_character(scene);
    ASSERT_FALSE(c.ok()) << far;
    EXPECT_NE(c.error().find("chest"), std::string::npos) << c.error();
    EXPECT_NE(c.error().find("metres"), std::string::npos) << c.error();
  }

  // A character can start at a sub-root: the left arm is 3 bones, root joint must then be free.
  c = load_character(*s, "upper_arm_l");
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().find("free"), std::string::npos) << c.error();
}

}  // namespace
