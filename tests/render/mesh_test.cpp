#include <gtest/gtest.h>
#include <cmath>
#include <map>
#include <tuple>
#include "engine/render/frame.h"

using namespace eng::render;

namespace {

// Closed = every edge (vertices welded by position, since boxes split vertices per face) is shared by exactly two
// triangles, once in each direction (consistent outward winding).
void expect_closed(const MeshData& m) {
  ASSERT_EQ(m.indices.size() % 3, 0u);
  std::map<std::tuple<long, long, long>, int> ids;
  auto key = [&](uint32_t i) {
    const glm::vec3 p = m.vertices[i].position;
    auto k = std::make_tuple(std::lround(p.x * 1e4), std::lround(p.y * 1e4), std::lround(p.z * 1e4));
    auto it = ids.emplace(k, static_cast<int>(ids.size())).first;
    return it->second;
  };
  std::map<std::pair<int, int>, int> edges;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const int a = key(m.indices[t]), b = key(m.indices[t + 1]), c = key(m.indices[t + 2]);
    ASSERT_TRUE(a != b && b != c && a != c) << "degenerate triangle";
    ++edges[{a, b}];
    ++edges[{b, c}];
    ++edges[{c, a}];
  }
  for (auto& [e, n] : edges) {
    EXPECT_EQ(n, 1) << "edge used twice in the same direction";
    EXPECT_EQ(edges.count({e.second, e.first}), 1u) << "open edge";
  }
}

void expect_unit_normals_outward(const MeshData& m) {
  for (const Vertex& v : m.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
    EXPECT_GT(glm::dot(v.normal, v.position), 0.0f) << "normal points inward";
  }
}

void expect_bounds(const MeshData& m, glm::vec3 lo, glm::vec3 hi) {
  glm::vec3 mn(1e9f), mx(-1e9f);
  for (const Vertex& v : m.vertices) {
    mn = glm::min(mn, v.position);
    mx = glm::max(mx, v.position);
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(mn[i], lo[i], 1e-4f);
    EXPECT_NEAR(mx[i], hi[i], 1e-4f);
  }
}

// Outward winding: summed signed volume (divergence theorem) is positive and close to the analytic volume.
float signed_volume(const MeshData& m) {
  double v = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 a = m.vertices[m.indices[t]].position, b = m.vertices[m.indices[t + 1]].position,
                    c = m.vertices[m.indices[t + 2]].position;
    v += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return static_cast<float>(v);
}

}  // namespace

TEST(MeshGen, Box) {
  const MeshData m = make_box_mesh({0.5f, 1.0f, 1.5f});
  expect_closed(m);
  expect_unit_normals_outward(m);
  expect_bounds(m, {-0.5f, -1.0f, -1.5f}, {0.5f, 1.0f, 1.5f});
  EXPECT_NEAR(signed_volume(m), 1.0f * 2.0f * 3.0f, 1e-3f);
}

TEST(MeshGen, Sphere) {
  const MeshData m = make_sphere_mesh(0.7f, 32);
  expect_closed(m);
  expect_unit_normals_outward(m);
  expect_bounds(m, glm::vec3(-0.7f), glm::vec3(0.7f));
  const float v = 4.0f / 3.0f * 3.14159265f * 0.343f;
  EXPECT_NEAR(signed_volume(m), v, 0.05f * v);
  for (const Vertex& vx : m.vertices) EXPECT_NEAR(glm::length(vx.position), 0.7f, 1e-4f);
}

TEST(MeshGen, Capsule) {
  const MeshData m = make_capsule_mesh(0.2f, 0.6f, 24);
  expect_closed(m);
  expect_unit_normals_outward(m);
  expect_bounds(m, {-0.2f, -0.2f, -0.8f}, {0.2f, 0.2f, 0.8f});
  const float v = 3.14159265f * 0.04f * 1.2f + 4.0f / 3.0f * 3.14159265f * 0.008f;
  EXPECT_NEAR(signed_volume(m), v, 0.06f * v);
}
