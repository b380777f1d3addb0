// libFuzzer harness: the character loader (engine/assets/character.h) on arbitrary glTF bytes, through the glTF
// loader as the game does (load_gltf, then load_character on the first root node).
// Promise checked: an accepted character is one a physics model can be built from: parent[i] < i, finite offsets,
// positive finite masses and inertias, finite unit joint axes, positive shapes, exclude pairs in range.
#include <cstddef>
#include <cstdint>

#include "engine/assets/character.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto scene = eng::assets::load_gltf_memory(data, size, "fuzz.gltf");
  if (!scene) return 0;
  auto desc = eng::assets::load_character(*scene);
  if (!desc) {
    fuzz::check(!desc.error().empty(), "an error without a message");
    return 0;
  }
  const auto& d = *desc;
  const int n = d.skeleton.size();
  fuzz::check(n > 0, "no bones");
  const size_t bones = static_cast<size_t>(n);
  fuzz::check(d.bones.size() == bones && d.bone_node.size() == bones && d.skeleton.name.size() == bones &&
                  d.skeleton.offset.size() == bones,
              "array sizes differ");
  fuzz::check(d.skeleton.parent[0] == -1 && d.bones[0].joint == "free", "root bone");
  for (int i = 0; i < n; ++i) {
    const auto& b = d.bones[static_cast<size_t>(i)];
    if (i > 0) fuzz::check(d.skeleton.parent[i] >= 0 && d.skeleton.parent[i] < i, "parent[i] < i");
    fuzz::check(fuzz::finite(d.skeleton.offset[static_cast<size_t>(i)]), "bone offset not finite");
    fuzz::check(std::isfinite(b.mass) && b.mass > 0, "mass");
    fuzz::check(fuzz::finite(b.inertia_diag) && b.inertia_diag.minCoeff() > 0, "inertia");
    fuzz::check(fuzz::finite(b.com) && fuzz::finite(b.axis), "com / axis not finite");
    fuzz::check(std::isfinite(b.lower) && std::isfinite(b.upper) && b.lower <= b.upper, "hinge range");
    fuzz::check(std::isfinite(b.damping) && std::isfinite(b.armature), "damping / armature");
    fuzz::check(!b.shapes.empty(), "no shape");
    for (const auto& s : b.shapes) {
      fuzz::check(fuzz::finite(s.pos) && fuzz::finite(s.quat.coeffs()), "shape pose not finite");
      fuzz::check(std::abs(s.quat.norm() - 1.0) < 1e-9, "shape quaternion not unit");
    }
  }
  fuzz::check(d.collision_group_bit >= 0 && d.collision_group_bit <= 31, "collision group bit");
  for (const auto& [a, b] : d.exclude_pairs) fuzz::check(0 <= a && a < b && b < n, "exclude pair");
  (void)d.dof();
  (void)d.total_mass();
  return 0;
}
