#include "engine/render/vk_context.h"

#include <cstdio>
#include <cstring>

namespace eng::render {

std::string vk_result_name(VkResult r) {
  switch (r) {
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_SURFACE_LOST_KHR: return "VK_ERROR_SURFACE_LOST_KHR";
    case VK_ERROR_OUT_OF_DATE_KHR: return "VK_ERROR_OUT_OF_DATE_KHR";
    case VK_SUBOPTIMAL_KHR: return "VK_SUBOPTIMAL_KHR";
    default: return "VkResult " + std::to_string(static_cast<int>(r));
  }
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kNoDevice = "no Vulkan device found: install mesa-vulkan-drivers (lavapipe) or a GPU driver";

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                             void* user) {
  auto* log = static_cast<ValidationLog*>(user);
  const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  if (error) ++log->errors;
  else ++log->warnings;
  std::string msg = std::string(error ? "vulkan error: " : "vulkan warning: ") + (data->pMessage ? data->pMessage : "");
  std::fprintf(stderr, "%s\n", msg.c_str());
  // Keep memory bounded if something spams every frame; the counters stay exact.
  if (log->messages.size() < 256) log->messages.push_back(std::move(msg));
  return VK_FALSE;
}

int device_rank(VkPhysicalDeviceType t) {
  // Real GPUs first; lavapipe (CPU) last so it is only a fallback.
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
    default: return 0;
  }
}

}  // namespace

eng::Result<std::unique_ptr<VkContext>> VkContext::create(const ContextConfig& cfg) {
  std::unique_ptr<VkContext> c(new VkContext());
  c->validation = cfg.validation;

  uint32_t api = 0;
  if (vkEnumerateInstanceVersion(&api) != VK_SUCCESS || api < VK_API_VERSION_1_2)
    return eng::make_error("Vulkan 1.2 loader not found: install libvulkan1 (and mesa-vulkan-drivers for lavapipe)");

  std::vector<const char*> layers;
  std::vector<const char*> exts = cfg.instance_extensions;
  if (cfg.validation) {
    uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> avail(n);
    vkEnumerateInstanceLayerProperties(&n, avail.data());
    bool found = false;
    for (auto& l : avail) found |= std::strcmp(l.layerName, kValidationLayer) == 0;
    if (!found)
      return eng::make_error(std::string(kValidationLayer) +
                             " not found: install the Debian package vulkan-validationlayers (or disable validation)");
    layers.push_back(kValidationLayer);
    exts.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "boxing";
  app.pEngineName = "eng";
  app.apiVersion = VK_API_VERSION_1_2;
  VkDebugUtilsMessengerCreateInfoEXT dbg{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  dbg.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  dbg.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                    VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  dbg.pfnUserCallback = &on_validation;
  dbg.pUserData = c->log.get();

  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  ici.enabledLayerCount = static_cast<uint32_t>(layers.size());
  ici.ppEnabledLayerNames = layers.data();
  ici.enabledExtensionCount = static_cast<uint32_t>(exts.size());
  ici.ppEnabledExtensionNames = exts.data();
  if (cfg.validation) ici.pNext = &dbg;  // also reports problems inside vkCreateInstance itself
  VkResult r = vkCreateInstance(&ici, nullptr, &c->instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER) return eng::make_error(kNoDevice);
  ENG_VK_TRY(r, "vkCreateInstance");

  if (cfg.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(c->instance, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) return eng::make_error("VK_EXT_debug_utils missing although validation is on");
    ENG_VK_TRY(create(c->instance, &dbg, nullptr, &c->messenger_), "vkCreateDebugUtilsMessengerEXT");
  }

  uint32_t n = 0;
  vkEnumeratePhysicalDevices(c->instance, &n, nullptr);
  std::vector<VkPhysicalDevice> devs(n);
  vkEnumeratePhysicalDevices(c->instance, &n, devs.data());
  int best_rank = -1;
  uint32_t best_family = 0;
  for (VkPhysicalDevice d : devs) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    if (p.apiVersion < VK_API_VERSION_1_2) continue;
    if (cfg.need_swapchain) {
      uint32_t en = 0;
      vkEnumerateDeviceExtensionProperties(d, nullptr, &en, nullptr);
      std::vector<VkExtensionProperties> de(en);
      vkEnumerateDeviceExtensionProperties(d, nullptr, &en, de.data());
      bool sw = false;
      for (auto& e : de) sw |= std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0;
      if (!sw) continue;
    }
    uint32_t qn = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &qn, nullptr);
    std::vector<VkQueueFamilyProperties> qf(qn);
    vkGetPhysicalDeviceQueueFamilyProperties(d, &qn, qf.data());
    for (uint32_t i = 0; i < qn; ++i) {
      if ((qf[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && device_rank(p.deviceType) > best_rank) {
        best_rank = device_rank(p.deviceType);
        c->physical = d;
        best_family = i;
        break;
      }
    }
  }
  if (!c->physical) return eng::make_error(kNoDevice);
  c->queue_family = best_family;

  VkPhysicalDeviceDriverProperties drv{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  p2.pNext = &drv;
  vkGetPhysicalDeviceProperties2(c->physical, &p2);
  c->props = p2.properties;
  c->device_name = c->props.deviceName;
  c->driver_info = std::string(drv.driverName) + " " + drv.driverInfo;
  std::fprintf(stderr, "renderer: using %s (%s)\n", c->device_name.c_str(), c->driver_info.c_str());

  const float prio = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = c->queue_family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &prio;
  const char* dev_exts[] = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = cfg.need_swapchain ? 1 : 0;
  dci.ppEnabledExtensionNames = dev_exts;
  VkPhysicalDeviceFeatures feats{};  // nothing optional is needed
  dci.pEnabledFeatures = &feats;
  ENG_VK_TRY(vkCreateDevice(c->physical, &dci, nullptr, &c->device), "vkCreateDevice");
  vkGetDeviceQueue(c->device, c->queue_family, 0, &c->queue);

  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = c->queue_family;
  ENG_VK_TRY(vkCreateCommandPool(c->device, &pci, nullptr, &c->pool), "vkCreateCommandPool");
  return c;
}

VkContext::~VkContext() {
  if (device) {
    vkDeviceWaitIdle(device);
    if (pool) vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance, messenger_, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
}

eng::Result<void> VkContext::check_present(VkSurfaceKHR surface) const {
  VkBool32 ok = VK_FALSE;
  vkGetPhysicalDeviceSurfaceSupportKHR(physical, queue_family, surface, &ok);
  if (!ok) return eng::make_error("the graphics queue of " + device_name + " cannot present to this window");
  return {};
}

eng::Result<uint32_t> VkContext::memory_type(uint32_t bits, VkMemoryPropertyFlags want) const {
  VkPhysicalDeviceMemoryProperties mp;
  vkGetPhysicalDeviceMemoryProperties(physical, &mp);
  for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
  return eng::make_error("no suitable Vulkan memory type");
}

eng::Result<Buffer> VkContext::create_buffer(VkDeviceSize size, VkBufferUsageFlags usage, bool host_visible) const {
  Buffer b;
  b.size = size;
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = size;
  bci.usage = usage;
  bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ENG_VK_TRY(vkCreateBuffer(device, &bci, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device, b.buffer, &req);
  auto mt = memory_type(req.memoryTypeBits, host_visible ? (VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)
                                                         : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!mt) return eng::make_error(mt.error());
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = *mt;
  ENG_VK_TRY(vkAllocateMemory(device, &mai, nullptr, &b.memory), "vkAllocateMemory");
  vkBindBufferMemory(device, b.buffer, b.memory, 0);
  if (host_visible) ENG_VK_TRY(vkMapMemory(device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  return b;
}

void VkContext::destroy(Buffer& b) const {
  if (b.buffer) vkDestroyBuffer(device, b.buffer, nullptr);
  if (b.memory) vkFreeMemory(device, b.memory, nullptr);
  b = Buffer{};
}

eng::Result<Image> VkContext::create_image(VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                                           VkSampleCountFlagBits samples, VkImageAspectFlags aspect) const {
  Image img;
  img.format = format;
  img.extent = extent;
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.imageType = VK_IMAGE_TYPE_2D;
  ici.format = format;
  ici.extent = {extent.width, extent.height, 1};
  ici.mipLevels = 1;
  ici.arrayLayers = 1;
  ici.samples = samples;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = usage;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  ENG_VK_TRY(vkCreateImage(device, &ici, nullptr, &img.image), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, img.image, &req);
  auto mt = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (!mt) return eng::make_error(mt.error());
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = *mt;
  ENG_VK_TRY(vkAllocateMemory(device, &mai, nullptr, &img.memory), "vkAllocateMemory");
  vkBindImageMemory(device, img.image, img.memory, 0);
  VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vci.image = img.image;
  vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
  vci.format = format;
  vci.subresourceRange = {aspect, 0, 1, 0, 1};
  ENG_VK_TRY(vkCreateImageView(device, &vci, nullptr, &img.view), "vkCreateImageView");
  return img;
}

void VkContext::destroy(Image& img) const {
  if (img.view) vkDestroyImageView(device, img.view, nullptr);
  if (img.image) vkDestroyImage(device, img.image, nullptr);
  if (img.memory) vkFreeMemory(device, img.memory, nullptr);
  img = Image{};
}

eng::Result<void> VkContext::begin_one_shot(VkCommandBuffer& cmd) const {
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  ENG_VK_TRY(vkAllocateCommandBuffers(device, &ai, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  ENG_VK_TRY(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");
  return {};
}

eng::Result<void> VkContext::end_one_shot(VkCommandBuffer cmd) const {
  vkEndCommandBuffer(cmd);
  VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cmd;
  // Waiting on the whole queue also orders this work after any frame still in flight.
  VkResult r = vkQueueSubmit(queue, 1, &si, VK_NULL_HANDLE);
  if (r == VK_SUCCESS) r = vkQueueWaitIdle(queue);
  vkFreeCommandBuffers(device, pool, 1, &cmd);
  ENG_VK_TRY(r, "one-shot submit");
  return {};
}

eng::Result<Buffer> VkContext::upload_buffer(const void* data, VkDeviceSize size, VkBufferUsageFlags usage) const {
  auto staging = create_buffer(size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
  if (!staging) return eng::make_error(staging.error());
  std::memcpy(staging->mapped, data, size);
  auto dst = create_buffer(size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
  if (!dst) {
    destroy(*staging);
    return dst;
  }
  auto r = one_shot([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, 0, size};
    vkCmdCopyBuffer(cmd, staging->buffer, dst->buffer, 1, &copy);
  });
  destroy(*staging);
  if (!r) return eng::make_error(r.error());
  return dst;
}

eng::Result<VkShaderModule> VkContext::shader(const uint32_t* code, size_t bytes) const {
  VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  ci.codeSize = bytes;
  ci.pCode = code;
  VkShaderModule m = VK_NULL_HANDLE;
  ENG_VK_TRY(vkCreateShaderModule(device, &ci, nullptr, &m), "vkCreateShaderModule");
  return m;
}

}  // namespace eng::render
