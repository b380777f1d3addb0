// Renderer: creation, per-frame orchestration (fences, acquire, submit, present) and the public API.
// The passes are recorded in shadow_pass.cpp, scene_pass.cpp, debug_draw.cpp and present_blit.cpp;
// offscreen targets live in render_targets.cpp, per-frame GPU data in frame_data.cpp, readback in readback.cpp.
#include "engine/render/renderer.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include "engine/render/renderer_impl.h"

namespace eng::render {
namespace {

VkSampleCountFlagBits pick_samples(const VkPhysicalDeviceProperties& p, int want) {
  const VkSampleCountFlags ok = p.limits.framebufferColorSampleCounts & p.limits.framebufferDepthSampleCounts;
  for (int s = 64; s > 1; s /= 2)
    if (s <= want && (ok & static_cast<VkSampleCountFlags>(s))) return static_cast<VkSampleCountFlagBits>(s);
  return VK_SAMPLE_COUNT_1_BIT;
}

}  // namespace

Renderer::Impl::~Impl() {
  if (!ctx) return;
  VkDevice dev = ctx->device;
  vkDeviceWaitIdle(dev);
  overlay.shutdown(*ctx, ui);
  for (auto& f : frames) {
    if (f.fence) vkDestroyFence(dev, f.fence, nullptr);
    if (f.image_ready) vkDestroySemaphore(dev, f.image_ready, nullptr);
    for (Buffer* b : {&f.uniforms, &f.instances, &f.lines, &f.points, &f.present_copy}) ctx->destroy(*b);
  }
  if (pool) vkDestroyDescriptorPool(dev, pool, nullptr);
  for (auto& m : meshes) {
    ctx->destroy(m.vertices);
    ctx->destroy(m.indices);
  }
  destroy_targets();
  if (shadow_fb) vkDestroyFramebuffer(dev, shadow_fb, nullptr);
  if (shadow_sampler) vkDestroySampler(dev, shadow_sampler, nullptr);
  ctx->destroy(shadow_map);
  destroy_pipelines(*ctx, pipes);
  destroy_swapchain(*ctx, swapchain);
  if (surface) vkDestroySurfaceKHR(ctx->instance, surface, nullptr);
}

eng::Result<void> Renderer::Impl::init() {
  int want = cfg.msaa_samples;
  if (want <= 0) want = ctx->props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1 : 4;
  samples = pick_samples(ctx->props, want);
  // The scene's resolution: as asked, or (0) by device: the CPU pixel budget on a CPU rasteriser, native on a GPU.
  if (cfg.render_scale > 0.0) scale_setting = std::clamp(cfg.render_scale, 0.25, 1.0);
  else scale_setting = ctx->props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 0.0 : 1.0;
  shadow_size = cfg.shadow_map_size > 0 ? static_cast<uint32_t>(std::clamp(cfg.shadow_map_size, 256, 8192))
              : ctx->props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? kShadowSizeCpu : kShadowSize;
  VkFormatProperties cf;
  vkGetPhysicalDeviceFormatProperties(ctx->physical, kColorFormat, &cf);
  upscale_linear = cf.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if (auto r = create_pipelines(*ctx, samples, pipes); !r) return r;
  if (auto r = overlay.init(*ctx, pipes.overlay_pass, ui); !r) return r;

  auto sm = ctx->create_image({shadow_size, shadow_size}, kShadowFormat,
                              VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                              VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
  if (!sm) return eng::make_error(sm.error());
  shadow_map = *sm;
  VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fci.renderPass = pipes.shadow_pass;
  fci.attachmentCount = 1;
  fci.pAttachments = &shadow_map.view;
  fci.width = fci.height = shadow_size;
  fci.layers = 1;
  ENG_VK_TRY(vkCreateFramebuffer(ctx->device, &fci, nullptr, &shadow_fb), "vkCreateFramebuffer(shadow)");
  // Hardware depth comparison; bilinear-filtered compares (where supported) smooth the PCF kernel further.
  VkFormatProperties fp;
  vkGetPhysicalDeviceFormatProperties(ctx->physical, kShadowFormat, &fp);
  const bool linear = fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sci.magFilter = sci.minFilter = linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sci.compareEnable = VK_TRUE;
  sci.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  sci.maxLod = 0.0f;
  ENG_VK_TRY(vkCreateSampler(ctx->device, &sci, nullptr, &shadow_sampler), "vkCreateSampler(shadow)");

  frames.resize(window ? 2 : 1);
  VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
                                   {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2}};
  VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pci.maxSets = 2;
  pci.poolSizeCount = 3;
  pci.pPoolSizes = sizes;
  ENG_VK_TRY(vkCreateDescriptorPool(ctx->device, &pci, nullptr, &pool), "vkCreateDescriptorPool");
  for (auto& f : frames) {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = ctx->pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    ENG_VK_TRY(vkAllocateCommandBuffers(ctx->device, &ai, &f.cmd), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fi.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // first wait returns at once
    ENG_VK_TRY(vkCreateFence(ctx->device, &fi, nullptr, &f.fence), "vkCreateFence");
    VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    ENG_VK_TRY(vkCreateSemaphore(ctx->device, &si, nullptr, &f.image_ready), "vkCreateSemaphore");
    VkDescriptorSetAllocateInfo dai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dai.descriptorPool = pool;
    dai.descriptorSetCount = 1;
    dai.pSetLayouts = &pipes.set_layout;
    ENG_VK_TRY(vkAllocateDescriptorSets(ctx->device, &dai, &f.set), "vkAllocateDescriptorSets");
    if (auto r = ensure(f.uniforms, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT); !r) return r;
    if (auto r = ensure(f.instances, 64 * sizeof(GpuInstance), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT); !r) return r;
    if (auto r = ensure(f.lines, 256 * sizeof(DebugVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT); !r) return r;
    if (auto r = ensure(f.points, 64 * sizeof(DebugPoint), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT); !r) return r;
    write_set(f);
  }
  if (window) return recreate_window_targets();
  return create_targets({static_cast<uint32_t>(cfg.width), static_cast<uint32_t>(cfg.height)});
}

eng::Result<void> Renderer::Impl::ensure(Buffer& b, VkDeviceSize size, VkBufferUsageFlags usage, bool* reallocated) {
  if (reallocated) *reallocated = false;
  if (b.buffer && b.size >= size) return {};
  // The caller waited on this frame's fence, so the GPU no longer uses the old buffer.
  // Grow geometrically so a slowly growing scene reallocates only a handful of times.
  const VkDeviceSize cap = std::max(size, b.size * 2);
  ctx->destroy(b);
  auto nb = ctx->create_buffer(cap, usage, true);
  if (!nb) return eng::make_error(nb.error());
  b = *nb;
  if (reallocated) *reallocated = true;
  return {};
}

void Renderer::Impl::write_set(PerFrame& f) {
  VkDescriptorBufferInfo ub{f.uniforms.buffer, 0, sizeof(FrameUniforms)};
  VkDescriptorBufferInfo sb{f.instances.buffer, 0, VK_WHOLE_SIZE};
  VkDescriptorImageInfo im{shadow_sampler, shadow_map.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet w[3]{};
  for (int i = 0; i < 3; ++i) {
    w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    w[i].dstSet = f.set;
    w[i].dstBinding = static_cast<uint32_t>(i);
    w[i].descriptorCount = 1;
  }
  w[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  w[0].pBufferInfo = &ub;
  w[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  w[1].pBufferInfo = &sb;
  w[2].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  w[2].pImageInfo = &im;
  vkUpdateDescriptorSets(ctx->device, 3, w, 0, nullptr);
}

void Renderer::Impl::record(PerFrame& f, const FrameDesc& frame, int swap_image) {
  VkCommandBuffer cmd = f.cmd;
  vkResetCommandBuffer(cmd, 0);
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(cmd, &bi);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes.layout, 0, 1, &f.set, 0, nullptr);
  record_shadow_pass(cmd, frame);
  record_scene_pass(cmd, f, frame);
  if (scaled()) record_upscale(cmd);
  if (frame.overlay) record_overlay_pass(cmd);
  if (swap_image >= 0) record_present_blit(cmd, swap_image);
  if (shm) record_copy_to_host(cmd, f.present_copy);  // shown at the next render() (show_shm_pending)
  vkEndCommandBuffer(cmd);
}

void Renderer::Impl::record_overlay_pass(VkCommandBuffer cmd) {
  VkRenderPassBeginInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rp.renderPass = pipes.overlay_pass;
  rp.framebuffer = overlay_fb;
  rp.renderArea = {{0, 0}, extent};
  vkCmdBeginRenderPass(cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
  overlay.record(cmd, ui);
  vkCmdEndRenderPass(cmd);
}

void Renderer::Impl::set_viewport(VkCommandBuffer cmd, VkExtent2D e) {
  VkViewport vp{0, 0, static_cast<float>(e.width), static_cast<float>(e.height), 0.0f, 1.0f};
  VkRect2D sc{{0, 0}, e};
  vkCmdSetViewport(cmd, 0, 1, &vp);
  vkCmdSetScissor(cmd, 0, 1, &sc);
}

eng::Result<void> Renderer::Impl::render(const FrameDesc& frame) {
  if (window) {
    if (window->minimized()) return {};  // nothing visible; keep the last frame for read_back
    const glm::ivec2 fb = window->framebuffer_size();
    if (swapchain_dirty || window->consume_resized() || static_cast<uint32_t>(fb.x) != extent.width ||
        static_cast<uint32_t>(fb.y) != extent.height) {
      if (auto r = recreate_window_targets(); !r) return r;
      if (swapchain_dirty) return {};
    }
  }
  PerFrame& f = frames[frame_index];
  ENG_VK_TRY(vkWaitForFences(ctx->device, 1, &f.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");

  int swap_image = -1;
  if (window && !shm) {
    uint32_t idx = 0;
    const VkResult r = vkAcquireNextImageKHR(ctx->device, swapchain.handle, UINT64_MAX, f.image_ready, VK_NULL_HANDLE, &idx);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
      swapchain_dirty = true;  // semaphore was not signalled; try again next frame
      return {};
    }
    if (r != VK_SUCCESS && r != VK_SUBOPTIMAL_KHR) ENG_VK_TRY(r, "vkAcquireNextImageKHR");
    if (r == VK_SUBOPTIMAL_KHR) swapchain_dirty = true;
    swap_image = static_cast<int>(idx);
  }
  if (shm && shm_pending == static_cast<int>(frame_index)) show_shm_pending();  // never overwrite an unshown frame
  if (auto r = upload_frame(f, frame); !r) return r;
  record(f, frame, swap_image);
  vkResetFences(ctx->device, 1, &f.fence);

  VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  const VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;  // only the final blit touches the image
  si.commandBufferCount = 1;
  si.pCommandBuffers = &f.cmd;
  if (swap_image >= 0) {
    si.waitSemaphoreCount = 1;
    si.pWaitSemaphores = &f.image_ready;
    si.pWaitDstStageMask = &wait_stage;
    si.signalSemaphoreCount = 1;
    si.pSignalSemaphores = &swapchain.render_done[static_cast<size_t>(swap_image)];
  }
  ENG_VK_TRY(vkQueueSubmit(ctx->queue, 1, &si, f.fence), "vkQueueSubmit");
  have_frame = true;
  const int slot = static_cast<int>(frame_index);
  frame_index = (frame_index + 1) % static_cast<uint32_t>(frames.size());

  if (shm) {
    // The previous frame is shown while the rasteriser draws this one (it finished before this one started).
    show_shm_pending();
    shm_pending = slot;
  } else if (window) {
    const uint32_t idx = static_cast<uint32_t>(swap_image);
    VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    pi.waitSemaphoreCount = 1;
    pi.pWaitSemaphores = &swapchain.render_done[idx];
    pi.swapchainCount = 1;
    pi.pSwapchains = &swapchain.handle;
    pi.pImageIndices = &idx;
    const VkResult r = vkQueuePresentKHR(ctx->queue, &pi);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) swapchain_dirty = true;
    else ENG_VK_TRY(r, "vkQueuePresentKHR");
  } else {
    ENG_VK_TRY(vkWaitForFences(ctx->device, 1, &f.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  }
  return {};
}

// ---- public API ----

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

eng::Result<std::unique_ptr<Renderer>> Renderer::create_headless(const RendererConfig& cfg) {
  if (cfg.width <= 0 || cfg.height <= 0) return eng::make_error("renderer size must be positive");
  auto impl = std::make_unique<Impl>();
  impl->cfg = cfg;
  ContextConfig cc;
  cc.validation = cfg.validation;
  auto ctx = VkContext::create(cc);
  if (!ctx) return eng::make_error(ctx.error());
  impl->ctx = std::move(*ctx);
  if (auto r = impl->init(); !r) return eng::make_error(r.error());
  return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
}

eng::Result<std::unique_ptr<Renderer>> Renderer::create_windowed(const RendererConfig& cfg, platform::Window& window) {
  auto impl = std::make_unique<Impl>();
  impl->cfg = cfg;
  impl->window = &window;
  ContextConfig cc;
  cc.validation = cfg.validation;
  cc.instance_extensions = platform::Window::required_instance_extensions();
  if (cc.instance_extensions.empty()) return eng::make_error("GLFW reports no Vulkan surface extensions: no display?");
  cc.need_swapchain = true;
  auto ctx = VkContext::create(cc);
  if (!ctx) return eng::make_error(ctx.error());
  impl->ctx = std::move(*ctx);
  using P = RendererConfig::Present;
  const bool cpu = impl->ctx->props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  if (cfg.present == P::SharedMemory || (cfg.present == P::Auto && cpu)) {
    const glm::ivec2 fb = window.framebuffer_size();
    auto s = platform::ShmSurface::create(window, std::max(fb.x, 1), std::max(fb.y, 1));
    if (s) impl->shm = std::move(*s);
    else if (cfg.present == P::SharedMemory) return eng::make_error(s.error() + ": use --present swapchain");
  }
  if (impl->shm) {
    if (auto r = impl->init(); !r) return eng::make_error(r.error());
    return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
  }
  auto surface = window.create_surface(impl->ctx->instance);
  if (!surface) return eng::make_error(surface.error());
  impl->surface = *surface;
  if (auto r = impl->ctx->check_present(impl->surface); !r) return eng::make_error(r.error());
  if (auto r = impl->init(); !r) return eng::make_error(r.error());
  return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
}

MeshId Renderer::upload_mesh(const MeshData& mesh) {
  GpuMesh m;
  // An index past the vertex array would make the GPU read outside the buffer (a crash on lavapipe, garbage
  // elsewhere); such a mesh is refused, drawn as nothing, and reported once.
  bool indices_ok = mesh.indices.size() % 3 == 0;
  for (uint32_t i : mesh.indices) indices_ok &= i < mesh.vertices.size();
  if (!indices_ok)
    std::fprintf(stderr, "renderer: mesh %zu refused: %zu indices (not a multiple of 3, or past its %zu vertices)\n",
                 impl_->meshes.size(), mesh.indices.size(), mesh.vertices.size());
  if (indices_ok && !mesh.vertices.empty() && !mesh.indices.empty()) {
    auto vb = impl_->ctx->upload_buffer(mesh.vertices.data(), mesh.vertices.size() * sizeof(Vertex),
                                        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    auto ib = impl_->ctx->upload_buffer(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t),
                                        VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (vb && ib) {
      m.vertices = *vb;
      m.indices = *ib;
      m.index_count = static_cast<uint32_t>(mesh.indices.size());
      m.lo = m.hi = mesh.vertices[0].position;
      for (const Vertex& v : mesh.vertices) {
        m.lo = glm::min(m.lo, v.position);
        m.hi = glm::max(m.hi, v.position);
      }
    } else {
      std::fprintf(stderr, "renderer: mesh upload failed: %s\n", (vb ? ib.error() : vb.error()).c_str());
      if (vb) impl_->ctx->destroy(*vb);
      if (ib) impl_->ctx->destroy(*ib);
    }
  }
  impl_->meshes.push_back(m);
  return static_cast<MeshId>(impl_->meshes.size() - 1);
}

eng::Result<void> Renderer::render(const FrameDesc& frame) { return impl_->render(frame); }

std::string Renderer::device_name() const { return impl_->ctx->device_name; }
const char* Renderer::present_path() const {
  return impl_->shm ? "shared memory" : impl_->window ? "swapchain" : "none";
}
eng::ui::Ui& Renderer::ui() { return impl_->ui; }
std::string Renderer::driver_info() const { return impl_->ctx->driver_info; }
int Renderer::validation_errors() const { return impl_->ctx->log->errors; }
int Renderer::validation_warnings() const { return impl_->ctx->log->warnings; }
bool Renderer::validation_active() const { return impl_->ctx->validation; }
const std::vector<std::string>& Renderer::validation_messages() const { return impl_->ctx->log->messages; }

}  // namespace eng::render
