#pragma once
// Shared setup for renderer tests: lavapipe pinned, validation on, skip only when there is no Vulkan device.
#include <gtest/gtest.h>
#include <cstdlib>
#include <memory>
#include <string>
#include "engine/render/renderer.h"
#include "support/vulkan_test_env.h"

namespace render_test {

// Also turns on the validation layer's synchronization checks (missing barriers, hazards between passes)
// unless the caller already chose layer features.
inline void enable_sync_validation() {
  setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 0);
}

inline std::unique_ptr<eng::render::Renderer> make_renderer(int w, int h, std::string* skip_reason) {
  boxing_test::pin_lavapipe_env();
  enable_sync_validation();
  eng::render::RendererConfig cfg;
  cfg.width = w;
  cfg.height = h;
  cfg.validation = true;
  auto r = eng::render::Renderer::create_headless(cfg);
  if (!r) {
    // Only a machine with no Vulkan device at all may skip; a missing validation layer must fail.
    if (r.error().rfind("no Vulkan device", 0) == 0) {
      *skip_reason = r.error();
      return nullptr;
    }
    ADD_FAILURE() << r.error();
    return nullptr;
  }
  return std::move(r.value());
}

// Skips when no device, fails (returns from the test) when creation failed for any other reason.
#define MAKE_RENDERER_OR_RETURN(var, w, h)                   \
  std::string var##_skip;                                    \
  auto var = render_test::make_renderer(w, h, &var##_skip);  \
  if (!var) {                                                \
    if (!var##_skip.empty()) GTEST_SKIP() << var##_skip;     \
    return;                                                  \
  }

inline eng::render::FrameDesc basic_frame() {
  eng::render::FrameDesc f;
  f.camera.eye = {4.0f, -6.0f, 3.0f};
  f.camera.target = {0.0f, 0.0f, 1.0f};
  return f;
}

}  // namespace render_test
