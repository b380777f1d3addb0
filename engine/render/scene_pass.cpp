// Scene pass into the colour target at the scene's resolution (multisampled and resolved at the end where MSAA is on;
// upscaled into the target afterwards where the scene is smaller, record_upscale): opaque instances,
// ground, sky, alpha-blended ghosts (depth test on, depth write off, back to front), then debug lines/points.
#include "engine/render/renderer_impl.h"

namespace eng::render {

void Renderer::Impl::record_scene_pass(VkCommandBuffer cmd, PerFrame& f, const FrameDesc& frame) {
  VkClearValue clears[3]{};
  clears[0].color = {{0.0f, 0.0f, 0.0f, 1.0f}};
  clears[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rp.renderPass = pipes.scene_pass;
  rp.framebuffer = scene_fb;
  rp.renderArea = {{0, 0}, scene_extent};
  rp.clearValueCount = 3;
  rp.pClearValues = clears;
  vkCmdBeginRenderPass(cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
  set_viewport(cmd, scene_extent);
  // Front to back as far as it goes, so the depth test rejects hidden fragments before they are shaded: opaque
  // bodies, the ground (its shadowed footprint, then the rest), the sky where nothing drew; then the blended
  // ghosts and the debug drawing.
  if (!frame.opaque.empty()) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes.opaque);
    draw_opaque(cmd, frame);
  }
  if (frame.ground) {
    // Instance 1 = the footprint quad, instance 0 = the square around the camera (ground.vert).
    if (ground_footprint) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes.ground_shadowed);
      vkCmdDraw(cmd, 6, 1, 0, 1);
    }
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ground_footprint || !ground_shadows ? pipes.ground : pipes.ground_shadowed);
    vkCmdDraw(cmd, 6, 1, 0, 0);
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes.sky);
  vkCmdDraw(cmd, 3, 1, 0, 0);
  if (!frame.ghosts.empty()) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipes.ghost);
    const size_t base = frame.opaque.size();
    // One draw per ghost: they are sorted far to near, which instancing by mesh would undo.
    for (size_t k = 0; k < frame.ghosts.size(); ++k) {
      const MeshId id = frame.ghosts[order[base + k]].mesh;
      if (id < meshes.size()) draw_mesh(cmd, id, static_cast<uint32_t>(base + k), 1);
    }
  }
  record_debug_draw(cmd, f, frame);
  vkCmdEndRenderPass(cmd);
}

}  // namespace eng::render
