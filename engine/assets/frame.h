#pragma once
// The one place where glTF's axes become the engine's.
//
// glTF 2.0 (spec 3.4, "Coordinate System and Units") is right-handed with +Y up and the front of an
// asset facing +Z, so the asset's left is +X. The engine is right-handed with +Z up, characters facing
// +X and their left +Y. The map between the two is the cyclic permutation
//
//     engine (x, y, z) = glTF (z, x, y)        glTF (x, y, z) = engine (y, z, x)
//
// a proper rotation (120 deg about (1, 1, 1)), no mirror and no sign flip. Every frame-dependent
// quantity transforms the same way: positions, directions and normals; a quaternion's vector part
// (its w stays: conjugating by a rotation keeps the angle); scale and principal-moment triples
// (they are per-axis). Moving numbers, never computing with them, makes the conversion exact: a file
// written by scripts/content (to_gltf there) loads back to the engine's values bit for bit.
//
// load_gltf applies it to everything it returns (node transforms, mesh data, animation values), and
// load_character to the physics extras, so the rest of the engine only ever sees its own frame.
#include <array>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace eng::assets::frame {

// Index of the glTF component that becomes engine component i: engine[i] = gltf[kFromGltf[i]].
inline constexpr std::array<int, 3> kFromGltf = {2, 0, 1};

// A 3-vector of any type with operator[] and a 3-argument constructor (glm::vec3, Eigen::Vector3d).
template <class V>
V to_engine(const V& g) {
  return V(g[kFromGltf[0]], g[kFromGltf[1]], g[kFromGltf[2]]);
}

// Inverse of to_engine (engine -> glTF), for writers and tests.
template <class V>
V to_gltf(const V& e) {
  return V(e[1], e[2], e[0]);
}

// Quaternions: the vector part turns like a vector, w stays.
inline glm::quat to_engine(const glm::quat& g) {
  const glm::vec3 v = to_engine(glm::vec3(g.x, g.y, g.z));
  return glm::quat(g.w, v.x, v.y, v.z);
}

// Flattened glTF values (an animation channel's output): each run of `comps` floats is one key,
// xyz[w] of a translation/scale (comps 3) or rotation (comps 4); the first three turn, w stays.
inline void values_to_engine(float* values, size_t count, int comps) {
  for (size_t i = 0; i + static_cast<size_t>(comps) <= count; i += static_cast<size_t>(comps)) {
    const float g[3] = {values[i], values[i + 1], values[i + 2]};
    for (int c = 0; c < 3; ++c) values[i + static_cast<size_t>(c)] = g[kFromGltf[static_cast<size_t>(c)]];
  }
}

}  // namespace eng::assets::frame
