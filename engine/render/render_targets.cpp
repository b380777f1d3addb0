// Offscreen targets (MSAA colour, depth, resolved colour, framebuffers, readback buffer) and their recreation
// when the window's swapchain changes size.
#include "engine/render/renderer_impl.h"

#include <array>

namespace eng::render {

eng::Result<void> Renderer::Impl::create_targets(VkExtent2D size) {
  extent = size;
  const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
  auto res = ctx->create_image(size, kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
  if (!res) return eng::make_error(res.error());
  resolved = *res;
  if (msaa) {
    auto c = ctx->create_image(size, kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                               samples, VK_IMAGE_ASPECT_COLOR_BIT);
    if (!c) return eng::make_error(c.error());
    color_msaa = *c;
  }
  auto d = ctx->create_image(size, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, samples, VK_IMAGE_ASPECT_DEPTH_BIT);
  if (!d) return eng::make_error(d.error());
  depth = *d;
  std::array<VkImageView, 3> views = {msaa ? color_msaa.view : resolved.view, depth.view, resolved.view};
  VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fci.renderPass = pipes.scene_pass;
  fci.attachmentCount = msaa ? 3 : 2;
  fci.pAttachments = views.data();
  fci.width = size.width;
  fci.height = size.height;
  fci.layers = 1;
  ENG_VK_TRY(vkCreateFramebuffer(ctx->device, &fci, nullptr, &scene_fb), "vkCreateFramebuffer(scene)");
  fci.renderPass = pipes.overlay_pass;
  fci.attachmentCount = 1;
  fci.pAttachments = &resolved.view;
  ENG_VK_TRY(vkCreateFramebuffer(ctx->device, &fci, nullptr, &overlay_fb), "vkCreateFramebuffer(overlay)");
  auto rb = ctx->create_buffer(VkDeviceSize(size.width) * size.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
  if (!rb) return eng::make_error(rb.error());
  readback = *rb;
  have_frame = false;
  return {};
}

void Renderer::Impl::destroy_targets() {
  if (scene_fb) vkDestroyFramebuffer(ctx->device, scene_fb, nullptr);
  if (overlay_fb) vkDestroyFramebuffer(ctx->device, overlay_fb, nullptr);
  scene_fb = overlay_fb = VK_NULL_HANDLE;
  ctx->destroy(color_msaa);
  ctx->destroy(depth);
  ctx->destroy(resolved);
  ctx->destroy(readback);
}

eng::Result<void> Renderer::Impl::recreate_swapchain() {
  vkDeviceWaitIdle(ctx->device);
  const glm::ivec2 fb = window->framebuffer_size();
  if (fb.x <= 0 || fb.y <= 0) {
    swapchain_dirty = true;  // minimised mid-resize: retry once the window has a size again
    return {};
  }
  if (auto r = create_swapchain(*ctx, surface, fb.x, fb.y, cfg.vsync, swapchain); !r) return r;
  swapchain_dirty = false;
  destroy_targets();
  // The offscreen image follows the window so the final blit is 1:1.
  return create_targets(swapchain.extent);
}
}  // namespace eng::render
