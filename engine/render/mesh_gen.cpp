// Procedural meshes for the primitives the physics uses (boxes, spheres, capsules).
#include <algorithm>
#include <cmath>
#include <utility>
#include "engine/render/frame.h"

namespace eng::render {

MeshData make_box_mesh(glm::vec3 h) {
  MeshData m;
  // One quad per face with its own vertices, so each face keeps a flat normal (hard edges).
  struct Face { glm::vec3 n, u, v; };
  const Face faces[6] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  for (const Face& f : faces) {
    // u x v == n for every face above, so (0,1,2)(0,2,3) winds counter-clockwise seen from outside.
    const auto base = static_cast<uint32_t>(m.vertices.size());
    const float su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
    for (int i = 0; i < 4; ++i) m.vertices.push_back({(f.n + f.u * su[i] + f.v * sv[i]) * h, f.n});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
  }
  return m;
}

// Shared by sphere and capsule: a pole-to-pole lat/long surface with single pole vertices (no degenerate
// triangles, closed by index). Ring r sits at polar angle theta(r); rings in the upper half are shifted by +offset
// along Z, rings in the lower half by -offset, which turns a sphere into a capsule.
static MeshData make_round(float radius, float offset, int segments, int half_rings) {
  MeshData m;
  segments = segments < 3 ? 3 : segments;
  half_rings = half_rings < 1 ? 1 : half_rings;
  const float pi = 3.14159265358979f;
  std::vector<std::pair<float, float>> rings;  // (theta, z offset)
  for (int r = 1; r <= half_rings; ++r) rings.push_back({0.5f * pi * r / half_rings, offset});
  // With an offset the equator appears twice (top and bottom of the cylinder); a sphere needs it once.
  for (int r = (offset > 0.0f ? 0 : 1); r < half_rings; ++r)
    rings.push_back({0.5f * pi + 0.5f * pi * r / half_rings, -offset});
  m.vertices.push_back({{0, 0, radius + offset}, {0, 0, 1}});
  for (auto [theta, dz] : rings) {
    for (int s = 0; s < segments; ++s) {
      const float phi = 2.0f * pi * s / segments;
      const glm::vec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
      m.vertices.push_back({n * radius + glm::vec3(0, 0, dz), n});
    }
  }
  const auto south = static_cast<uint32_t>(m.vertices.size());
  m.vertices.push_back({{0, 0, -radius - offset}, {0, 0, -1}});
  const auto seg = static_cast<uint32_t>(segments);
  auto ring_v = [&](size_t r, uint32_t s) { return 1 + static_cast<uint32_t>(r) * seg + (s % seg); };
  for (uint32_t s = 0; s < seg; ++s) m.indices.insert(m.indices.end(), {0u, ring_v(0, s), ring_v(0, s + 1)});
  for (size_t r = 0; r + 1 < rings.size(); ++r) {
    for (uint32_t s = 0; s < seg; ++s) {
      const uint32_t a = ring_v(r, s), b = ring_v(r, s + 1), c = ring_v(r + 1, s), d = ring_v(r + 1, s + 1);
      m.indices.insert(m.indices.end(), {a, c, d, a, d, b});
    }
  }
  const size_t last = rings.size() - 1;
  for (uint32_t s = 0; s < seg; ++s) m.indices.insert(m.indices.end(), {south, ring_v(last, s + 1), ring_v(last, s)});
  return m;
}

MeshData make_sphere_mesh(float radius, int segments) {
  return make_round(radius, 0.0f, segments, std::max(1, segments / 4));
}

MeshData make_capsule_mesh(float radius, float half_length, int segments) {
  return make_round(radius, half_length > 0.0f ? half_length : 0.0f, segments, std::max(1, segments / 4));
}

}  // namespace eng::render
