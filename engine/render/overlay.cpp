#include "engine/render/overlay.h"

#include <algorithm>
#include <cstdio>
#include "imgui.h"
#include "backends/imgui_impl_vulkan.h"

namespace eng::render {

eng::Result<void> Overlay::init(const VkContext& ctx, VkRenderPass overlay_pass) {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pci.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;  // the backend frees its font set
  pci.maxSets = 4;
  pci.poolSizeCount = 1;
  pci.pPoolSizes = &size;
  ENG_VK_TRY(vkCreateDescriptorPool(ctx.device, &pci, nullptr, &pool_), "vkCreateDescriptorPool(imgui)");

  IMGUI_CHECKVERSION();
  imgui_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(imgui_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // never write imgui.ini next to the binary
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();

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
  auto r = ctx.one_shot([this](VkCommandBuffer cmd) {
    ImGui::SetCurrentContext(imgui_);
    ImGui_ImplVulkan_CreateFontsTexture(cmd);
  });
  if (!r) return r;
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  return {};
}

void Overlay::record(VkCommandBuffer cmd, const FrameDesc& frame, VkExtent2D extent, const std::string& device) {
  ImGui::SetCurrentContext(imgui_);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(extent.width), static_cast<float>(extent.height));
  io.DeltaTime = 1.0f / 60.0f;
  ImGui_ImplVulkan_NewFrame();
  ImGui::NewFrame();
  char stats[96];
  std::snprintf(stats, sizeof(stats), "%.2f ms  (%.0f fps)", frame.frame_ms,
                frame.frame_ms > 0 ? 1000.0f / frame.frame_ms : 0.0f);
  // Size the panel from its text up front: an auto-resizing ImGui window is hidden on its first frame and lags
  // one frame behind its content, which would make a single headless frame miss the overlay and break
  // frame-to-frame determinism.
  const ImGuiStyle& style = ImGui::GetStyle();
  float w = std::max(ImGui::CalcTextSize(stats).x, ImGui::CalcTextSize(device.c_str()).x);
  for (const std::string& line : frame.overlay_lines) w = std::max(w, ImGui::CalcTextSize(line.c_str()).x);
  const int rows = 2 + static_cast<int>(frame.overlay_lines.size());
  const float sep = frame.overlay_lines.empty() ? 0.0f : style.ItemSpacing.y + 1.0f;
  const float h = rows * ImGui::GetTextLineHeightWithSpacing() - style.ItemSpacing.y + sep + 2.0f * style.WindowPadding.y;
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w + 2.0f * style.WindowPadding.x, h), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.55f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##stats", nullptr, flags)) {
    ImGui::TextUnformatted(stats);
    ImGui::TextUnformatted(device.c_str());
    if (!frame.overlay_lines.empty()) ImGui::Separator();
    for (const std::string& line : frame.overlay_lines) ImGui::TextUnformatted(line.c_str());
  }
  ImGui::End();
  ImGui::Render();
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

void Overlay::shutdown(const VkContext& ctx) {
  if (imgui_) {
    ImGui::SetCurrentContext(imgui_);
    if (ready_) ImGui_ImplVulkan_Shutdown();
    ImGui::DestroyContext(imgui_);
    imgui_ = nullptr;
    ready_ = false;
  }
  if (pool_) vkDestroyDescriptorPool(ctx.device, pool_, nullptr);
  pool_ = VK_NULL_HANDLE;
}

}  // namespace eng::render
