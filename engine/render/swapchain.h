#pragma once
// Window swapchain: (re)creation on resize, per-image "render finished" semaphores.
#include <vector>
#include <vulkan/vulkan.h>
#include "engine/render/vk_context.h"

namespace eng::render {

struct Swapchain {
  VkSwapchainKHR handle = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{};
  std::vector<VkImage> images;
  // One per image: a present may still be waiting on the semaphore when the next frame starts, so it cannot be
  // tied to the frame-in-flight index.
  std::vector<VkSemaphore> render_done;
};

// Creates or recreates (passing the old one to the driver, then destroying it). width/height = framebuffer size.
eng::Result<void> create_swapchain(const VkContext& ctx, VkSurfaceKHR surface, int width, int height, bool vsync,
                                   Swapchain& sc);
void destroy_swapchain(const VkContext& ctx, Swapchain& sc);

}  // namespace eng::render
