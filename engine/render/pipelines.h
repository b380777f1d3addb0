#pragma once
// Render passes, descriptor layout and graphics pipelines of the scene (created once per renderer).
#include <vulkan/vulkan.h>
#include "engine/render/vk_context.h"

namespace eng::render {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;  // gamma-correct: shaders write linear, hardware encodes
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkFormat kShadowFormat = VK_FORMAT_D32_SFLOAT;
// The sun's shadow map, texels a side: on a GPU; a CPU rasteriser uses kShadowSizeCpu (RendererConfig).
constexpr uint32_t kShadowSize = 2048;
constexpr uint32_t kShadowSizeCpu = 1024;

// Vertex of a debug line (per-vertex colour); points use eng::render::DebugPoint directly as instance data.
struct DebugVertex {
  float pos[3];
  float color[4];
};

struct Pipelines {
  VkRenderPass shadow_pass = VK_NULL_HANDLE;   // depth only, ends in SHADER_READ_ONLY
  VkRenderPass scene_pass = VK_NULL_HANDLE;    // MSAA colour + depth, resolved; ends in TRANSFER_SRC
  VkRenderPass overlay_pass = VK_NULL_HANDLE;  // loads the resolved image, draws ImGui, ends in TRANSFER_SRC
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline shadow = VK_NULL_HANDLE, sky = VK_NULL_HANDLE, ground = VK_NULL_HANDLE, ground_shadowed = VK_NULL_HANDLE,
             opaque = VK_NULL_HANDLE,
             ghost = VK_NULL_HANDLE, lines = VK_NULL_HANDLE, points = VK_NULL_HANDLE;
  VkPipeline lines_on_top = VK_NULL_HANDLE, points_on_top = VK_NULL_HANDLE;  // no depth test (FrameDesc::debug_on_top)
};

eng::Result<void> create_pipelines(const VkContext& ctx, VkSampleCountFlagBits samples, Pipelines& p);
void destroy_pipelines(const VkContext& ctx, Pipelines& p);

}  // namespace eng::render
