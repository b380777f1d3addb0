// libFuzzer harness: the glTF loader (engine/assets/gltf.h, load_gltf_memory) on arbitrary bytes, .gltf JSON or .glb.
// Promise checked: an accepted scene is self-consistent (indices within the vertices, parents and children in range,
// channel value counts matching their key times), so the code that reads it needs no checks of its own.
#include <cstddef>
#include <cstdint>

#include "engine/assets/gltf.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto scene = eng::assets::load_gltf_memory(data, size, "fuzz.gltf");
  if (!scene) {
    fuzz::check(!scene.error().empty(), "an error without a message");
    return 0;
  }
  const int nodes = static_cast<int>(scene->nodes.size());
  for (int i = 0; i < nodes; ++i) {
    const auto& n = scene->nodes[static_cast<size_t>(i)];
    fuzz::check(n.parent >= -1 && n.parent < nodes, "node parent out of range");
    for (int c : n.children) fuzz::check(c >= 0 && c < nodes, "node child out of range");
    fuzz::check(n.mesh >= -1 && n.mesh < static_cast<int>(scene->meshes.size()), "node mesh out of range");
    (void)scene->world_matrix(i);  // walks the parents: must end (no cycles)
  }
  for (const auto& m : scene->meshes)
    for (const auto& p : m.primitives) {
      for (uint32_t ix : p.indices) fuzz::check(ix < p.positions.size(), "index out of range");
      fuzz::check(p.normals.empty() || p.normals.size() == p.positions.size(), "normal count");
      fuzz::check(p.material >= -1 && p.material < static_cast<int>(scene->materials.size()), "material");
    }
  for (const auto& a : scene->animations)
    for (const auto& c : a.channels) {
      fuzz::check(c.node >= 0 && c.node < nodes, "channel node out of range");
      const size_t comps = c.path == "rotation" ? 4 : 3;
      const size_t per_key = comps * (c.interpolation == "CUBICSPLINE" ? 3 : 1);
      fuzz::check(c.values.size() == c.times.size() * per_key, "channel value count");
    }
  (void)scene->find_node("root");
  return 0;
}
