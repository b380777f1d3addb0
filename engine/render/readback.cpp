// read_back: copies the resolved offscreen image (the exact pixels shown, overlay included) to the CPU. The same
// path serves headless tests and F12 screenshots in the window build.
#include "engine/render/renderer_impl.h"

#include <cstring>

namespace eng::render {

// The target (`resolved`, in TRANSFER_SRC with its writes visible to transfers: the last pass leaves it so) into a
// host buffer, readable by the CPU once the commands' fence or queue wait returns.
void Renderer::Impl::record_copy_to_host(VkCommandBuffer cmd, const Buffer& dst) {
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {extent.width, extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, resolved.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.buffer, 1, &copy);
  VkBufferMemoryBarrier b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = dst.buffer;
  b.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1, &b, 0, nullptr);
}

eng::Result<eng::Image> Renderer::read_back() {
  Impl& im = *impl_;
  if (!im.have_frame) return eng::make_error("read_back: nothing rendered yet");
  // The resolved image always ends a frame in TRANSFER_SRC layout; copying after the queue drains sees the
  // latest frame in both modes.
  ENG_VK_TRY(vkQueueWaitIdle(im.ctx->queue), "vkQueueWaitIdle");
  auto r = im.ctx->one_shot([&](VkCommandBuffer cmd) { im.record_copy_to_host(cmd, im.readback); });
  if (!r) return eng::make_error(r.error());
  eng::Image img;
  img.width = static_cast<int>(im.extent.width);
  img.height = static_cast<int>(im.extent.height);
  img.rgba.resize(static_cast<size_t>(img.width) * img.height * 4);
  std::memcpy(img.rgba.data(), im.readback.mapped, img.rgba.size());
  for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;  // frames are opaque
  return img;
}

}  // namespace eng::render
