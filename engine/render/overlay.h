#pragma once
// Dear ImGui text overlay drawn into the resolved offscreen image (so screenshots include it). It needs no
// input, so no platform backend is used: display size and time step are set by hand, which also keeps it
// deterministic in headless tests.
#include <string>
#include <vulkan/vulkan.h>
#include "engine/render/frame.h"
#include "engine/render/vk_context.h"

struct ImGuiContext;

namespace eng::render {

class Overlay {
 public:
  eng::Result<void> init(const VkContext& ctx, VkRenderPass overlay_pass);
  // Builds the UI for this frame and records its draw into the overlay render pass (already begun).
  void record(VkCommandBuffer cmd, const FrameDesc& frame, VkExtent2D extent, const std::string& device);
  void shutdown(const VkContext& ctx);

 private:
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  // Each renderer owns its ImGui context (the Vulkan backend keeps its state per context), so several renderers
  // can coexist, e.g. in tests; it is made current around every ImGui call.
  ImGuiContext* imgui_ = nullptr;
  bool ready_ = false;
};

}  // namespace eng::render
