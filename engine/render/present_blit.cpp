// Windowed mode: blits the finished offscreen image (scene + overlay) into the acquired swapchain image and
// leaves it ready to present. Both images are sRGB, so the blit copies colours exactly. Or, through shared memory,
// copies it out to the CPU and into the window's shared image.
#include "engine/render/renderer_impl.h"


namespace eng::render {

void Renderer::Impl::record_present_blit(VkCommandBuffer cmd, int swap_image) {
  VkImage dst = swapchain.images[static_cast<size_t>(swap_image)];
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = 0;
  b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // previous contents are not needed
  b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = dst;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  // Source stage TRANSFER chains with the acquire semaphore's wait stage, so the layout change waits for it.
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {static_cast<int32_t>(extent.width), static_cast<int32_t>(extent.height), 1};
  blit.dstSubresource = blit.srcSubresource;
  blit.dstOffsets[1] = {static_cast<int32_t>(swapchain.extent.width), static_cast<int32_t>(swapchain.extent.height), 1};
  vkCmdBlitImage(cmd, resolved.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                 &blit, VK_FILTER_NEAREST);
  b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  b.dstAccessMask = 0;
  b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
}

// The scene rendered smaller (render_scale) is stretched over the whole target with a bilinear blit, before the HUD
// is drawn on top at full resolution. Leaves the target in TRANSFER_SRC layout, as the scene pass does when native.
void Renderer::Impl::record_upscale(VkCommandBuffer cmd) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = 0;  // the last frame's reads of the target (readback, present blit) are in the stage below
  b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // fully overwritten
  b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = resolved.image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 1, &b);
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {static_cast<int32_t>(scene_extent.width), static_cast<int32_t>(scene_extent.height), 1};
  blit.dstSubresource = blit.srcSubresource;
  blit.dstOffsets[1] = {static_cast<int32_t>(extent.width), static_cast<int32_t>(extent.height), 1};
  // The scene pass left scene_color in TRANSFER_SRC layout and made its writes visible to transfers (its
  // outgoing dependency).
  vkCmdBlitImage(cmd, scene_color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, resolved.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, upscale_linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST);
  b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &b);
}

void Renderer::Impl::show_shm_pending() {
  if (shm_pending < 0) return;
  PerFrame& p = frames[static_cast<size_t>(shm_pending)];
  shm_pending = -1;
  if (vkWaitForFences(ctx->device, 1, &p.fence, VK_TRUE, UINT64_MAX) != VK_SUCCESS) return;
  // R, G, B, A (the frame, sRGB-encoded) to B, G, R, X (the window's visual): a swap of bytes 0 and 2, written
  // row by row into the shared image (its rows may be padded).
  const int w = shm->width(), h = shm->height();
  const auto* src = static_cast<const uint32_t*>(p.present_copy.mapped);
  for (int y = 0; y < h; ++y) {
    const uint32_t* s = src + static_cast<size_t>(y) * static_cast<size_t>(w);
    uint32_t* d = reinterpret_cast<uint32_t*>(shm->pixels() + static_cast<size_t>(y) * static_cast<size_t>(shm->stride()));
    for (int x = 0; x < w; ++x) {
      const uint32_t c = s[x];
      d[x] = (c & 0xff00ff00u) | ((c >> 16) & 0xffu) | ((c & 0xffu) << 16);
    }
  }
  shm->present();
}

}  // namespace eng::render
