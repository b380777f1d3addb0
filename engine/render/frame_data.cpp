// Per-frame GPU data: camera and sun matrices (shadow frustum fitted to the casters), instance records sorted for
// instancing, and debug geometry, written into this frame-in-flight's persistently mapped buffers.
#include "engine/render/renderer_impl.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <glm/gtc/matrix_transform.hpp>

namespace eng::render {

FrameUniforms Renderer::Impl::make_uniforms(const FrameDesc& frame) {
  FrameUniforms u{};
  const Camera& cam = frame.camera;
  const float aspect = static_cast<float>(extent.width) / static_cast<float>(std::max(1u, extent.height));
  glm::mat4 proj = glm::perspectiveRH_ZO(glm::radians(cam.fov_y_deg), aspect, cam.znear, cam.zfar);
  proj[1][1] *= -1.0f;  // Vulkan clip space has +Y down
  const glm::mat4 view = glm::lookAtRH(cam.eye, cam.target, cam.up);
  u.view_proj = proj * view;
  u.inv_view_proj = glm::inverse(u.view_proj);

  const glm::vec3 sun_dir = glm::normalize(frame.sun.direction);
  // Fit an orthographic sun frustum around a bounding sphere of all opaque casters (a sphere keeps the fit
  // stable as objects rotate).
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const Instance& in : frame.opaque) {
    if (in.mesh >= meshes.size()) continue;
    const GpuMesh& m = meshes[in.mesh];
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner((c & 1) ? m.hi.x : m.lo.x, (c & 2) ? m.hi.y : m.lo.y, (c & 4) ? m.hi.z : m.lo.z);
      const glm::vec3 w = glm::vec3(in.model * glm::vec4(corner, 1.0f));
      lo = glm::min(lo, w);
      hi = glm::max(hi, w);
    }
  }
  const bool casters = lo.x <= hi.x;
  float texel_world = 0.0f;
  bool footprint = false;
  if (casters) {
    const glm::vec3 center = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 0.5f) + 0.25f;
    const glm::vec3 up = std::abs(sun_dir.z) > 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    glm::mat4 lview = glm::lookAtRH(center - sun_dir * (radius + 1.0f), center, up);
    // Snap the light's origin to whole shadow texels (in light space) so shadow edges do not crawl as casters
    // move and the fitted sphere's centre slides.
    const float texel = 2.0f * radius / static_cast<float>(shadow_size);
    const glm::vec3 origin_ls = glm::vec3(lview * glm::vec4(0, 0, 0, 1));
    const glm::vec3 snapped(std::floor(origin_ls.x / texel) * texel, std::floor(origin_ls.y / texel) * texel, origin_ls.z);
    lview = glm::translate(glm::mat4(1.0f), snapped - origin_ls) * lview;
    // The far plane reaches well past the casters so the ground they shadow (possibly far along a low sun) is
    // inside the map.
    const float far_plane = 2.0f * radius + 1.0f + 4.0f * radius + 20.0f;
    const glm::mat4 lproj = glm::orthoRH_ZO(-radius, radius, -radius, radius, 0.0f, far_plane);
    u.light_view_proj = lproj * lview;
    texel_world = 2.0f * radius / static_cast<float>(shadow_size);
    // The map's footprint on the ground: its square (a little wider) carried along the sun onto z = 0. Only this
    // part of the ground can be shadowed; ground.frag's shadowed variant draws it, the cheap one the rest. A sun
    // lower than ~11 degrees stretches it too far: then the whole ground takes the shadowed variant.
    if (sun_dir.z < -0.2f) {
      const glm::mat4 inv = glm::inverse(lview);
      const float e = 1.02f * radius;
      const glm::vec2 sq[4] = {{-e, -e}, {e, -e}, {e, e}, {-e, e}};
      glm::vec2 c[4];
      for (int k = 0; k < 4; ++k) {
        const glm::vec3 p = glm::vec3(inv * glm::vec4(sq[k], 0.0f, 1.0f));
        const glm::vec3 q = p + sun_dir * (-p.z / sun_dir.z);
        c[k] = glm::vec2(q);
      }
      u.ground_footprint[0] = glm::vec4(c[0], c[1]);
      u.ground_footprint[1] = glm::vec4(c[2], c[3]);
      footprint = true;
    }
  }
  ground_shadows = casters;
  ground_footprint = footprint;
  u.eye = glm::vec4(cam.eye, cam.zfar);
  u.sun_dir = glm::vec4(sun_dir, frame.sun.intensity);
  u.sun_color = glm::vec4(frame.sun.color, 1.0f);
  u.sky_zenith = glm::vec4(0.10f, 0.28f, 0.82f, 1.0f);
  u.sky_horizon = glm::vec4(0.62f, 0.72f, 0.88f, 1.0f);
  u.ground_tint = glm::vec4(0.30f, 0.26f, 0.20f, 1.0f);
  u.fog = glm::vec4(2.2f / std::max(cam.zfar, 1.0f), 0, 0, 0);
  u.viewport = glm::vec4(extent.width, extent.height, 1.0f / extent.width, 1.0f / extent.height);
  u.shadow = glm::vec4(1.0f / shadow_size, 1.5f * texel_world, casters ? 1.0f : 0.0f, footprint ? 1.0f : 0.0f);
  return u;
}

eng::Result<void> Renderer::Impl::upload_frame(PerFrame& f, const FrameDesc& frame) {
  const FrameUniforms u = make_uniforms(frame);
  std::memcpy(f.uniforms.mapped, &u, sizeof(u));

  // Opaque instances sorted (stably, for determinism) by mesh so each mesh is one instanced draw; ghosts follow,
  // back to front so alpha blending composes correctly.
  gpu_instances.clear();
  order.resize(frame.opaque.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return frame.opaque[a].mesh < frame.opaque[b].mesh; });
  auto push = [&](const Instance& in) {
    gpu_instances.push_back({in.model, in.material.base_color, glm::vec4(in.material.roughness, in.material.metallic, 0, 0)});
  };
  for (uint32_t i : order) push(frame.opaque[i]);
  const size_t ghost_base = order.size();
  order.resize(ghost_base + frame.ghosts.size());
  std::iota(order.begin() + ghost_base, order.end(), 0u);
  auto dist = [&](uint32_t i) { return glm::length(glm::vec3(frame.ghosts[i].model[3]) - frame.camera.eye); };
  std::stable_sort(order.begin() + ghost_base, order.end(), [&](uint32_t a, uint32_t b) { return dist(a) > dist(b); });
  for (size_t k = ghost_base; k < order.size(); ++k) push(frame.ghosts[order[k]]);
  if (gpu_instances.empty()) gpu_instances.push_back({});  // keep the bound SSBO non-empty
  // The descriptor set must be rewritten whenever the SSBO was reallocated. Do not detect that by comparing
  // VkBuffer handles: a driver may hand out the just-freed handle again (lavapipe's handles are heap pointers,
  // so the new buffer often has the old handle's value); a set not rewritten then points at the destroyed buffer,
  // which crashes lavapipe without the validation layer (whose wrapped handles are always unique).
  bool reallocated = false;
  if (auto r = ensure(f.instances, gpu_instances.size() * sizeof(GpuInstance), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, &reallocated); !r)
    return r;
  if (reallocated) write_set(f);
  std::memcpy(f.instances.mapped, gpu_instances.data(), gpu_instances.size() * sizeof(GpuInstance));

  line_vertices.clear();
  for (const DebugLine& l : frame.lines) {
    line_vertices.push_back({{l.a.x, l.a.y, l.a.z}, {l.color.r, l.color.g, l.color.b, l.color.a}});
    line_vertices.push_back({{l.b.x, l.b.y, l.b.z}, {l.color.r, l.color.g, l.color.b, l.color.a}});
  }
  if (!line_vertices.empty()) {
    if (auto r = ensure(f.lines, line_vertices.size() * sizeof(DebugVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT); !r) return r;
    std::memcpy(f.lines.mapped, line_vertices.data(), line_vertices.size() * sizeof(DebugVertex));
  }
  if (!frame.points.empty()) {
    if (auto r = ensure(f.points, frame.points.size() * sizeof(DebugPoint), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT); !r) return r;
    std::memcpy(f.points.mapped, frame.points.data(), frame.points.size() * sizeof(DebugPoint));
  }
  return {};
}
}  // namespace eng::render
