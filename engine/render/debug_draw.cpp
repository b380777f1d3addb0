// Debug lines (LINE_LIST) and points (screen-size quads, one instance per point), unlit, depth-tested against the
// scene but not writing depth, recorded at the end of the scene pass.
#include "engine/render/renderer_impl.h"

namespace eng::render {

void Renderer::Impl::record_debug_draw(VkCommandBuffer cmd, PerFrame& f, const FrameDesc& frame) {
  VkDeviceSize off = 0;
  if (!line_vertices.empty()) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, frame.debug_on_top ? pipes.lines_on_top : pipes.lines);
    vkCmdBindVertexBuffers(cmd, 0, 1, &f.lines.buffer, &off);
    vkCmdDraw(cmd, static_cast<uint32_t>(line_vertices.size()), 1, 0, 0);
  }
  if (!frame.points.empty()) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, frame.debug_on_top ? pipes.points_on_top : pipes.points);
    vkCmdBindVertexBuffers(cmd, 0, 1, &f.points.buffer, &off);
    vkCmdDraw(cmd, 6, static_cast<uint32_t>(frame.points.size()), 0, 0);
  }
}

}  // namespace eng::render
