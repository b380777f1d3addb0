#include "engine/render/swapchain.h"

#include <algorithm>

namespace eng::render {

eng::Result<void> create_swapchain(const VkContext& ctx, VkSurfaceKHR surface, int width, int height, bool vsync,
                                   Swapchain& sc) {
  VkSurfaceCapabilitiesKHR caps;
  ENG_VK_TRY(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx.physical, surface, &caps), "surface capabilities");
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
    return eng::make_error("swapchain images cannot be blit targets on this device");
  uint32_t n = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physical, surface, &n, nullptr);
  std::vector<VkSurfaceFormatKHR> fmts(n);
  vkGetPhysicalDeviceSurfaceFormatsKHR(ctx.physical, surface, &n, fmts.data());
  if (fmts.empty()) return eng::make_error("surface reports no formats");
  // An sRGB swapchain keeps the blit from the sRGB offscreen image colour-exact (blits convert via linear).
  VkSurfaceFormatKHR fmt = fmts[0];
  for (auto f : fmts)
    if ((f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) &&
        f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
      fmt = f;
  vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physical, surface, &n, nullptr);
  std::vector<VkPresentModeKHR> modes(n);
  vkGetPhysicalDeviceSurfacePresentModesKHR(ctx.physical, surface, &n, modes.data());
  VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;  // always available; the vsync choice
  if (!vsync) {
    for (auto m : modes)
      if (m == VK_PRESENT_MODE_MAILBOX_KHR) mode = m;
    if (mode == VK_PRESENT_MODE_FIFO_KHR)
      for (auto m : modes)
        if (m == VK_PRESENT_MODE_IMMEDIATE_KHR) mode = m;
  }
  VkExtent2D extent = caps.currentExtent;
  if (extent.width == 0xFFFFFFFFu) {
    extent.width = std::clamp<uint32_t>(static_cast<uint32_t>(width), caps.minImageExtent.width, caps.maxImageExtent.width);
    extent.height = std::clamp<uint32_t>(static_cast<uint32_t>(height), caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent.width == 0 || extent.height == 0) return eng::make_error("swapchain extent is zero (window minimised)");
  uint32_t count = std::max(caps.minImageCount + 1, 3u);
  if (caps.maxImageCount) count = std::min(count, caps.maxImageCount);

  VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  ci.surface = surface;
  ci.minImageCount = count;
  ci.imageFormat = fmt.format;
  ci.imageColorSpace = fmt.colorSpace;
  ci.imageExtent = extent;
  ci.imageArrayLayers = 1;
  ci.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ci.preTransform = caps.currentTransform;
  ci.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  if (!(caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)) ci.compositeAlpha = VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR;
  ci.presentMode = mode;
  ci.clipped = VK_TRUE;
  ci.oldSwapchain = sc.handle;
  VkSwapchainKHR fresh = VK_NULL_HANDLE;
  ENG_VK_TRY(vkCreateSwapchainKHR(ctx.device, &ci, nullptr, &fresh), "vkCreateSwapchainKHR");
  destroy_swapchain(ctx, sc);
  sc.handle = fresh;
  sc.format = fmt.format;
  sc.extent = extent;
  vkGetSwapchainImagesKHR(ctx.device, sc.handle, &n, nullptr);
  sc.images.resize(n);
  vkGetSwapchainImagesKHR(ctx.device, sc.handle, &n, sc.images.data());
  sc.render_done.resize(n);
  for (auto& s : sc.render_done) {
    VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    ENG_VK_TRY(vkCreateSemaphore(ctx.device, &si, nullptr, &s), "vkCreateSemaphore");
  }
  return {};
}

void destroy_swapchain(const VkContext& ctx, Swapchain& sc) {
  for (auto s : sc.render_done) vkDestroySemaphore(ctx.device, s, nullptr);
  sc.render_done.clear();
  sc.images.clear();
  if (sc.handle) vkDestroySwapchainKHR(ctx.device, sc.handle, nullptr);
  sc.handle = VK_NULL_HANDLE;
}

}  // namespace eng::render
