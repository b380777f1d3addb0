#include "engine/render/overlay.h"

#include "imgui.h"
#include "backends/imgui_impl_vulkan.h"

namespace eng::render {

eng::Result<void> Overlay::init(const VkContext& ctx, VkRenderPass overlay_pass, eng::ui::Ui& ui) {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pci.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;  // the backend frees its font set
  pci.maxSets = 4;
  pci.poolSizeCount = 1;
  pci.pPoolSizes = &size;
  ENG_VK_TRY(vkCreateDescriptorPool(ctx.device, &pci, nullptr, &pool_), "vkCreateDescriptorPool(imgui)");

  // The backend keeps its state in the current ImGui context (io.BackendRendererUserData): make the Ui's current.
  ImGui::SetCurrentContext(ui.context());
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = ctx.instance;
  info.PhysicalDevice = ctx.physical;
  info.Device = ctx.device;
  info.QueueFamily = ctx.queue_family;
  info.Queue = ctx.queue;
  info.DescriptorPool = pool_;
  // The backend cycles its vertex buffers over ImageCount; one more than the 2 frames in flight keeps it from
  // rewriting a buffer the GPU may still read.
  info.MinImageCount = 2;
  info.ImageCount = 3;
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  if (!ImGui_ImplVulkan_Init(&info, overlay_pass)) return eng::make_error("ImGui_ImplVulkan_Init failed");
  ready_ = true;
  ImGuiContext* imgui = ui.context();
  auto r = ctx.one_shot([imgui](VkCommandBuffer cmd) {
    ImGui::SetCurrentContext(imgui);
    ImGui_ImplVulkan_CreateFontsTexture(cmd);
  });
  if (!r) return r;
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  return {};
}

void Overlay::record(VkCommandBuffer cmd, const eng::ui::Ui& ui) {
  ImDrawData* draw = eng::ui::ui_draw_data(ui);  // makes the Ui's context current
  if (!ready_ || !draw) return;
  ImGui_ImplVulkan_RenderDrawData(draw, cmd);
}

void Overlay::shutdown(const VkContext& ctx, eng::ui::Ui& ui) {
  if (ready_) {
    ImGui::SetCurrentContext(ui.context());
    ImGui_ImplVulkan_Shutdown();
    ready_ = false;
  }
  if (pool_) vkDestroyDescriptorPool(ctx.device, pool_, nullptr);
  pool_ = VK_NULL_HANDLE;
}

}  // namespace eng::render
