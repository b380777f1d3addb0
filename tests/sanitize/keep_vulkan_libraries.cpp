// Linked into test_render in sanitizer builds only (BOXING_SANITIZE, tests/CMakeLists.txt). Keeps lavapipe and the
// Khronos validation layer mapped until the process exits, so LeakSanitizer's report at exit can name them: the
// Vulkan loader unloads both at vkDestroyInstance, and a stack in an unloaded library reads "<unknown module>",
// which no suppression can match (tests/sanitize/lsan.supp; docs/decisions/sanitizers-and-fuzzing.md).
// RTLD_LOCAL: their symbols do not interpose on the loader's (LD_PRELOAD would, and breaks the layer checks).
#include <dlfcn.h>

#include <initializer_list>

namespace {

struct KeepVulkanLibrariesLoaded {
  KeepVulkanLibrariesLoaded() {
    for (const char* lib : {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"})
      dlopen(lib, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);  // a missing one: nothing to keep
  }
} keep_vulkan_libraries_loaded;

}  // namespace
