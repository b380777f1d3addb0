// Sun shadow map: depth-only render of the opaque casters into a square D32 map (2048^2 on a GPU, 1024^2 on a CPU rasteriser; slope-scaled bias is baked into
// the pipeline). Always recorded, even without casters, so the sampled image is in a defined layout.
#include "engine/render/renderer_impl.h"

namespace eng::render {

void Renderer::Impl::draw_mesh(VkCommandBuffer cmd, MeshId mesh, uint32_t first_instance, uint32_t count) {
  const GpuMesh& m = meshes[mesh];
  if (m.index_count == 0) return;  // failed upload
  VkDeviceSize off = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &m.vertices.buffer, &off);
  vkCmdBindIndexBuffer(cmd, m.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, m.index_count, count, 0, 0, first_instance);
}

void Renderer::Impl::draw_opaque(VkCommandBuffer cmd, const FrameDesc& frame) {
  // `order` holds opaque indices sorted by mesh (frame_data.cpp); instance i of the SSBO is order[i].
  size_t i = 0;
  const size_t n = frame.opaque.size();
  while (i < n) {
    const MeshId id = frame.opaque[order[i]].mesh;
    size_t j = i;
    while (j < n && frame.opaque[order[j]].mesh == id) ++j;
    if (id < meshes.size()) draw_mesh(cmd, id, static_cast<uint32_t>(i), static_cast<uint32_t>(j - i));
    i = j;
  }
}

void Renderer::Impl::record_shadow_pass(VkCommandBuffer cmd, const FrameDesc& frame) {
  VkClearValue clear{};
  clear.depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rp.renderPass = pipes.shadow_pass;
  rp.framebuffer = shadow_fb;
  rp.renderArea = {{0, 0}, {shadow_size, shadow_size}};
  rp.clearValueCount = 1;
  rp.pClearValues = &clear;
  vkCmdBeginRenderPass(cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
  if (!frame.opaque.empty()) {
    set_viewport(cmd, {shadow_size, shadow_size});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes.shadow);
    draw_opaque(cmd, frame);
  }
  vkCmdEndRenderPass(cmd);
}

}  // namespace eng::render
