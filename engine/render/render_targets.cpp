// Offscreen targets (MSAA colour, depth, resolved colour, framebuffers, readback buffer) and their recreation
// when the window's swapchain (or shared-memory surface) changes size.
#include "engine/render/renderer_impl.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace eng::render {

// The scene's size for a target of `size`: scale_setting > 0 per axis, else within the CPU pixel budget.
static VkExtent2D scene_size(VkExtent2D size, double scale_setting) {
  const double pixels = double(size.width) * double(size.height);
  const double s = scale_setting > 0.0 ? scale_setting : std::min(1.0, std::sqrt(kCpuScenePixels / std::max(pixels, 1.0)));
  if (s >= 1.0) return size;
  return {std::max(1u, static_cast<uint32_t>(std::lround(size.width * s))),
          std::max(1u, static_cast<uint32_t>(std::lround(size.height * s)))};
}

eng::Result<void> Renderer::Impl::create_targets(VkExtent2D size) {
  extent = size;
  scene_extent = scene_size(size, scale_setting);
  const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
  auto res = ctx->create_image(size, kColorFormat,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                               VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
  if (!res) return eng::make_error(res.error());
  resolved = *res;
  if (scaled()) {
    auto s = ctx->create_image(scene_extent, kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    if (!s) return eng::make_error(s.error());
    scene_color = *s;
  }
  // The scene's colour lands here (resolved into it under MSAA): the target itself, or the smaller scene image.
  const Image& scene_out = scaled() ? scene_color : resolved;
  if (msaa) {
    auto c = ctx->create_image(scene_extent, kColorFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                               samples, VK_IMAGE_ASPECT_COLOR_BIT);
    if (!c) return eng::make_error(c.error());
    color_msaa = *c;
  }
  auto d = ctx->create_image(scene_extent, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, samples, VK_IMAGE_ASPECT_DEPTH_BIT);
  if (!d) return eng::make_error(d.error());
  depth = *d;
  std::array<VkImageView, 3> views = {msaa ? color_msaa.view : scene_out.view, depth.view, scene_out.view};
  VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fci.renderPass = pipes.scene_pass;
  fci.attachmentCount = msaa ? 3 : 2;
  fci.pAttachments = views.data();
  fci.width = scene_extent.width;
  fci.height = scene_extent.height;
  fci.layers = 1;
  ENG_VK_TRY(vkCreateFramebuffer(ctx->device, &fci, nullptr, &scene_fb), "vkCreateFramebuffer(scene)");
  fci.width = size.width;
  fci.height = size.height;
  fci.renderPass = pipes.overlay_pass;
  fci.attachmentCount = 1;
  fci.pAttachments = &resolved.view;
  ENG_VK_TRY(vkCreateFramebuffer(ctx->device, &fci, nullptr, &overlay_fb), "vkCreateFramebuffer(overlay)");
  auto rb = ctx->create_buffer(VkDeviceSize(size.width) * size.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
  if (!rb) return eng::make_error(rb.error());
  readback = *rb;
  if (shm)
    for (PerFrame& f : frames)
      if (auto r = ensure(f.present_copy, rb->size, VK_BUFFER_USAGE_TRANSFER_DST_BIT); !r) return r;
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
  ctx->destroy(scene_color);
  ctx->destroy(readback);
}

eng::Result<void> Renderer::Impl::recreate_window_targets() {
  return shm ? recreate_shm_surface() : recreate_swapchain();
}

eng::Result<void> Renderer::Impl::recreate_shm_surface() {
  vkDeviceWaitIdle(ctx->device);
  shm_pending = -1;  // a frame of the old size is not shown
  const glm::ivec2 fb = window->framebuffer_size();
  if (fb.x <= 0 || fb.y <= 0) {
    swapchain_dirty = true;  // minimised mid-resize: retry once the window has a size again
    return {};
  }
  if (shm->width() != fb.x || shm->height() != fb.y) {
    shm.reset();
    auto s = platform::ShmSurface::create(*window, fb.x, fb.y);
    if (!s) return eng::make_error(s.error());
    shm = std::move(*s);
  }
  swapchain_dirty = false;
  destroy_targets();
  return create_targets({static_cast<uint32_t>(fb.x), static_cast<uint32_t>(fb.y)});
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
