#pragma once
// The UI overlay's Vulkan side: the Dear ImGui Vulkan backend attached to the renderer's eng::ui::Ui context,
// recording the UI frame the game built (ui_begin .. ui_end, engine/ui/ui.h) into the overlay pass, on top of the
// resolved offscreen image (so screenshots include it). It builds no windows and reads no input itself.
#include <vulkan/vulkan.h>
#include "engine/render/vk_context.h"
#include "engine/ui/ui.h"

namespace eng::render {

class Overlay {
 public:
  // Attaches the backend to ui's context and uploads its font atlas.
  eng::Result<void> init(const VkContext& ctx, VkRenderPass overlay_pass, eng::ui::Ui& ui);
  // Records the last ended UI frame (nothing when there is none) into the overlay render pass (already begun).
  void record(VkCommandBuffer cmd, const eng::ui::Ui& ui);
  void shutdown(const VkContext& ctx, eng::ui::Ui& ui);

 private:
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  bool ready_ = false;
};

}  // namespace eng::render
