#pragma once
// Pins what makes lavapipe's output vary, for every Vulkan test, before any Vulkan instance exists:
// only the lavapipe ICD, a fixed rasteriser thread count, and poisoned fresh allocations so reads of
// unwritten memory show up as wrong pixels instead of passing by luck. (scripts/test exports the same.)
#include <cstdlib>

namespace boxing_test {

inline constexpr const char* kLavapipeIcd = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";

inline void pin_lavapipe_env() {
  setenv("VK_ICD_FILENAMES", kLavapipeIcd, 1);
  setenv("VK_DRIVER_FILES", kLavapipeIcd, 1);
  setenv("LP_NUM_THREADS", "2", 1);
  setenv("LVP_POISON_MEMORY", "1", 1);
}

}  // namespace boxing_test
