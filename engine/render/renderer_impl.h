#pragma once
// Internal to engine/render: the Renderer's state, shared by the files that record each pass.
#include <memory>
#include <vector>
#include <glm/glm.hpp>
#include "engine/platform/shm_surface.h"
#include "engine/platform/window.h"
#include "engine/render/overlay.h"
#include "engine/render/pipelines.h"
#include "engine/render/renderer.h"
#include "engine/render/swapchain.h"
#include "engine/render/vk_context.h"

namespace eng::render {

// std140 mirror of FrameUniforms in shaders/common.glsl.
struct FrameUniforms {
  glm::mat4 view_proj, inv_view_proj, light_view_proj;
  glm::vec4 eye, sun_dir, sun_color, sky_zenith, sky_horizon, ground_tint, fog, viewport, shadow;
  glm::vec4 ground_footprint[2];  // the shadow map's footprint on z = 0, corners (x, y) in order: xy xy | xy xy
};
static_assert(sizeof(FrameUniforms) == 3 * 64 + 11 * 16, "FrameUniforms must match shaders/common.glsl (std140)");

// std430 mirror of InstanceData.
struct GpuInstance {
  glm::mat4 model;
  glm::vec4 color;
  glm::vec4 params;
};
static_assert(sizeof(GpuInstance) == 96, "GpuInstance must match InstanceData in shaders/common.glsl (std430)");

struct GpuMesh {
  Buffer vertices, indices;
  uint32_t index_count = 0;
  glm::vec3 lo{0.0f}, hi{0.0f};  // local bounds, for fitting the shadow frustum
};

struct PerFrame {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkSemaphore image_ready = VK_NULL_HANDLE;
  Buffer uniforms, instances, lines, points;
  Buffer present_copy;  // shared-memory present: the finished frame (RGBA) copied out for the CPU
  VkDescriptorSet set = VK_NULL_HANDLE;
};

struct Renderer::Impl {
  RendererConfig cfg;
  std::unique_ptr<VkContext> ctx;
  platform::Window* window = nullptr;
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  Swapchain swapchain;
  bool swapchain_dirty = false;
  std::unique_ptr<platform::ShmSurface> shm;  // set when the window is shown through shared memory (no swapchain)
  int shm_pending = -1;                       // the frame slot submitted and not yet shown, -1 if none

  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  Pipelines pipes;
  eng::ui::Ui ui;  // the game builds its UI frames here; the overlay pass draws the last one
  Overlay overlay;
  uint32_t shadow_size = kShadowSize;  // texels a side (init: by device or as configured)
  Image shadow_map;
  VkFramebuffer shadow_fb = VK_NULL_HANDLE;
  VkSampler shadow_sampler = VK_NULL_HANDLE;

  VkExtent2D extent{};        // the target: what is read back or presented
  VkExtent2D scene_extent{};  // the 3D scene's (extent x render scale); equal to extent when native
  double scale_setting = 1.0; // cfg.render_scale resolved for this device (init); <= 0 = by pixel budget
  bool upscale_linear = true;  // the colour format filters linearly (else the upscale is nearest)
  Image color_msaa, depth, resolved;
  Image scene_color;  // the scene at scene_extent, upscaled into `resolved` (only while scene_extent != extent)
  VkFramebuffer scene_fb = VK_NULL_HANDLE, overlay_fb = VK_NULL_HANDLE;
  Buffer readback;
  bool have_frame = false;
  // This frame's shadow setup (make_uniforms): casters cast shadows; the ground's shadowed part is the map's
  // footprint, drawn apart from the rest of the ground.
  bool ground_shadows = false, ground_footprint = false;

  VkDescriptorPool pool = VK_NULL_HANDLE;
  std::vector<PerFrame> frames;  // 2 in flight when windowed; 1 headless (it waits every frame anyway)
  uint32_t frame_index = 0;
  std::vector<GpuMesh> meshes;

  // Reused every frame so steady-state rendering does no heap churn.
  std::vector<GpuInstance> gpu_instances;
  std::vector<uint32_t> order;
  std::vector<DebugVertex> line_vertices;

  ~Impl();
  eng::Result<void> init();
  eng::Result<void> create_targets(VkExtent2D size);
  void destroy_targets();
  // Windowed: the swapchain or the shared-memory surface and the offscreen targets at the window's size.
  eng::Result<void> recreate_window_targets();
  eng::Result<void> recreate_swapchain();
  eng::Result<void> recreate_shm_surface();
  void show_shm_pending();  // waits for the pending frame and copies it to the window (present_blit.cpp)
  // Makes `b` hold at least `size` bytes (host-visible, mapped), reallocating geometrically; sets *reallocated when
  // the buffer was replaced, so anything referring to it (descriptor sets) can be updated.
  eng::Result<void> ensure(Buffer& b, VkDeviceSize size, VkBufferUsageFlags usage, bool* reallocated = nullptr);
  void write_set(PerFrame& f);
  FrameUniforms make_uniforms(const FrameDesc& frame);
  eng::Result<void> upload_frame(PerFrame& f, const FrameDesc& frame);
  void record(PerFrame& f, const FrameDesc& frame, int swap_image);
  // Pass recorders, each in the file named after it.
  void record_shadow_pass(VkCommandBuffer cmd, const FrameDesc& frame);              // shadow_pass.cpp
  void record_scene_pass(VkCommandBuffer cmd, PerFrame& f, const FrameDesc& frame);  // scene_pass.cpp
  void record_debug_draw(VkCommandBuffer cmd, PerFrame& f, const FrameDesc& frame);  // debug_draw.cpp
  void record_overlay_pass(VkCommandBuffer cmd);             // renderer.cpp
  void record_present_blit(VkCommandBuffer cmd, int swap_image);                     // present_blit.cpp
  void record_upscale(VkCommandBuffer cmd);                                          // present_blit.cpp
  void record_copy_to_host(VkCommandBuffer cmd, const Buffer& dst);                  // readback.cpp
  bool scaled() const { return scene_extent.width != extent.width || scene_extent.height != extent.height; }
  // One instanced draw per run of equal meshes in the mesh-sorted opaque list (shared by shadow + scene).
  void draw_opaque(VkCommandBuffer cmd, const FrameDesc& frame);
  void draw_mesh(VkCommandBuffer cmd, MeshId mesh, uint32_t first_instance, uint32_t count);
  static void set_viewport(VkCommandBuffer cmd, VkExtent2D e);
  eng::Result<void> render(const FrameDesc& frame);
};

}  // namespace eng::render
