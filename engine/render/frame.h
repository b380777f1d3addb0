#pragma once
// Plain data the game fills every frame and hands to Renderer::render. No Vulkan types here, so game code and
// tests can build frames without knowing anything about the GPU. World is Z-up, metres.
#include <cstdint>
#include <string>
#include <vector>
#include <glm/glm.hpp>

namespace eng::render {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
};

struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // triangle list, counter-clockwise seen from outside
};

// Axis-aligned box centred on the origin, flat per-face normals.
MeshData make_box_mesh(glm::vec3 half_extents);
// UV sphere centred on the origin; `segments` around the equator (>= 3), segments/2 rings; smooth normals.
MeshData make_sphere_mesh(float radius, int segments);
// Capsule along local Z: a cylinder of `half_length` either side of the origin capped by hemispheres.
MeshData make_capsule_mesh(float radius, float half_length, int segments);

using MeshId = uint32_t;

struct Material {
  glm::vec4 base_color{0.8f, 0.8f, 0.8f, 1.0f};  // linear RGB albedo; a = opacity (used by ghosts)
  float roughness = 0.6f;
  float metallic = 0.0f;
};

struct Instance {
  MeshId mesh = 0;
  glm::mat4 model{1.0f};
  Material material;
};

struct Camera {
  glm::vec3 eye{4.0f, -6.0f, 3.0f};
  glm::vec3 target{0.0f, 0.0f, 1.0f};
  glm::vec3 up{0.0f, 0.0f, 1.0f};
  float fov_y_deg = 45.0f;
  float znear = 0.05f, zfar = 100.0f;
};

struct Sun {
  glm::vec3 direction{-0.45f, 0.35f, -0.82f};  // pointing from the sun toward the scene
  glm::vec3 color{1.0f, 0.95f, 0.88f};
  float intensity = 3.2f;
};

struct DebugLine {
  glm::vec3 a, b;
  glm::vec4 color;  // sRGB, drawn unlit
};

struct DebugPoint {
  glm::vec3 p;
  float size_px;
  glm::vec4 color;  // sRGB, drawn unlit
};

struct FrameDesc {
  Camera camera;
  Sun sun;
  std::vector<Instance> opaque;
  std::vector<Instance> ghosts;  // translucent, alpha from base_color.a
  std::vector<DebugLine> lines;
  std::vector<DebugPoint> points;
  bool ground = true;  // large ground plane at z=0 with a subtle grid/canvas look
  bool overlay = false;  // draw the renderer's last UI frame (Renderer::ui()) over the scene
  bool debug_on_top = false;  // lines and points drawn over everything (x-ray): springs and forces inside bodies
};

}  // namespace eng::render
