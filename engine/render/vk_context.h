#pragma once
// Vulkan instance + device + queue, the validation messenger, and small resource helpers shared by every pass.
#include <memory>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>
#include "engine/core/result.h"

namespace eng::render {

// Turns a failing VkResult into an eng::Error naming the call; used as: ENG_VK_TRY(vkCreateX(...), "vkCreateX");
// only inside functions returning eng::Result<...>.
std::string vk_result_name(VkResult r);
#define ENG_VK_TRY(expr, what)                                                                          \
  do {                                                                                                  \
    const VkResult eng_vk_r_ = (expr);                                                                  \
    if (eng_vk_r_ != VK_SUCCESS) return eng::make_error(std::string(what) + " failed: " + ::eng::render::vk_result_name(eng_vk_r_)); \
  } while (0)

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* mapped = nullptr;  // persistently mapped when host-visible
};

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{};
};

// Validation counters live in their own heap object so the messenger callback keeps a stable pointer.
struct ValidationLog {
  int errors = 0;
  int warnings = 0;
  std::vector<std::string> messages;
};

struct ContextConfig {
  bool validation = true;
  std::vector<const char*> instance_extensions;  // e.g. GLFW's surface extensions
  bool need_swapchain = false;
};

class VkContext {
 public:
  static eng::Result<std::unique_ptr<VkContext>> create(const ContextConfig& cfg);
  ~VkContext();

  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
  VkCommandPool pool = VK_NULL_HANDLE;  // transient one-shot work (uploads, readback)
  VkPhysicalDeviceProperties props{};
  std::string device_name, driver_info;
  bool validation = false;
  std::unique_ptr<ValidationLog> log = std::make_unique<ValidationLog>();

  // Must be called once a surface exists when the queue family must also present; checks support.
  eng::Result<void> check_present(VkSurfaceKHR surface) const;

  eng::Result<Buffer> create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, bool host_visible) const;
  void destroy(Buffer& b) const;
  eng::Result<Image> create_image(VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                                  VkSampleCountFlagBits samples, VkImageAspectFlags aspect) const;
  void destroy(Image& img) const;
  // Device-local buffer filled through a staging copy (waits for completion; load-time only).
  eng::Result<Buffer> upload_buffer(const void* data, VkDeviceSize size, VkBufferUsageFlags usage) const;
  // Records `fn` into a fresh command buffer, submits and waits.
  template <class F>
  eng::Result<void> one_shot(F&& fn) const {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    auto r = begin_one_shot(cmd);
    if (!r) return r;
    fn(cmd);
    return end_one_shot(cmd);
  }
  eng::Result<VkShaderModule> shader(const uint32_t* code, size_t bytes) const;

 private:
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  eng::Result<void> begin_one_shot(VkCommandBuffer& cmd) const;
  eng::Result<void> end_one_shot(VkCommandBuffer cmd) const;
  eng::Result<uint32_t> memory_type(uint32_t bits, VkMemoryPropertyFlags want) const;
};

}  // namespace eng::render
