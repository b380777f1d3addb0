#pragma once
// Shared setup for renderer tests: lavapipe pinned, validation on, skip only when there is no Vulkan device.
#include <gtest/gtest.h>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>
#include "engine/render/renderer.h"
#include "engine/ui/ui.h"
#include "imgui.h"
#include "support/vulkan_test_env.h"
#include "support/ci_env.h"

namespace render_test {

// Also turns on the validation layer's synchronization checks (missing barriers, hazards between passes)
// unless the caller already chose layer features.
inline void enable_sync_validation() {
  setenv("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT", 0);
}

// A headless renderer with `cfg` (validation forced on).
inline std::unique_ptr<eng::render::Renderer> make_renderer(eng::render::RendererConfig cfg, std::string* skip_reason) {
  boxing_test::pin_lavapipe_env();
  enable_sync_validation();
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

inline std::unique_ptr<eng::render::Renderer> make_renderer(int w, int h, std::string* skip_reason) {
  eng::render::RendererConfig cfg;
  cfg.width = w;
  cfg.height = h;
  return make_renderer(cfg, skip_reason);
}

// Skips when no device, fails (returns from the test) when creation failed for any other reason.
#define MAKE_RENDERER_WITH_OR_RETURN(var, cfg)                \
  std::string var##_skip;                                     \
  auto var = render_test::make_renderer(cfg, &var##_skip);    \
  if (!var) {                                                 \
    if (!var##_skip.empty()) BOXING_SKIP_OR_FAIL(var##_skip);      \
    return;                                                   \
  }
#define MAKE_RENDERER_OR_RETURN(var, w, h) MAKE_RENDERER_WITH_OR_RETURN(var, (eng::render::RendererConfig{w, h}))

inline eng::render::FrameDesc basic_frame() {
  eng::render::FrameDesc f;
  f.camera.eye = {4.0f, -6.0f, 3.0f};
  f.camera.target = {0.0f, 0.0f, 1.0f};
  return f;
}

// One UI frame into the renderer's Ui: a fixed, translucent text panel at (10, 10) (what the game's stats panel
// looks like), for the tests that draw the overlay. Fixed size: no first-frame auto-fit, so one frame shows it.
inline void ui_text_panel(eng::render::Renderer& r, const eng::ui::UiInput& in, const std::vector<std::string>& lines) {
  eng::ui::ui_begin(r.ui(), in);
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(220, 20.0f + 17.0f * static_cast<float>(lines.size())), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.55f);
  ImGui::Begin("##panel", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoInputs);
  for (const std::string& l : lines) ImGui::TextUnformatted(l.c_str());
  ImGui::End();
  eng::ui::ui_end(r.ui());
}
inline eng::ui::UiInput ui_display(int w, int h) {
  eng::ui::UiInput in;
  in.display_width = static_cast<float>(w);
  in.display_height = static_cast<float>(h);
  return in;
}

}  // namespace render_test
