#pragma once
// Renderer: draws a FrameDesc with the same passes and shaders headless (offscreen, for tests and tools) or into a
// window. Scene -> offscreen MSAA target (resolved) -> optional ImGui overlay -> read back and/or blit to swapchain.
#include <memory>
#include <string>
#include <vector>
#include "engine/core/image.h"
#include "engine/core/result.h"
#include "engine/render/frame.h"
#include "engine/ui/ui.h"

namespace eng::platform {
class Window;
}

namespace eng::render {

struct RendererConfig {
  int width = 1280, height = 720;  // headless target size; windowed mode follows the framebuffer
  bool validation = true;          // requires VK_LAYER_KHRONOS_validation (package vulkan-validationlayers)
  bool vsync = true;
  // 0 = by device: 4 on a GPU, 1 on a CPU rasteriser (lavapipe shades and blends every sample on the CPU: 4x MSAA
  // more than doubled its frame, docs/decisions/renderer-speed.md). Any other value is clamped to what the device
  // supports.
  int msaa_samples = 0;
  // The 3D scene's resolution as a share of the target's (per axis), upscaled (bilinear) before the HUD, which stays
  // sharp. 0 = by device: a CPU rasteriser renders the scene at no more than kCpuScenePixels (at 1280x720: 0.75,
  // docs/decisions/renderer-speed.md; 640x360 and smaller stay native), a GPU at 1.
  // Any other value is clamped to [0.25, 1].
  double render_scale = 0.0;
  // The sun's shadow map, texels a side. 0 = by device: 1024 on a CPU rasteriser (clearing and filling 2048^2 depth
  // texels cost lavapipe about 6 ms a frame; the 5x5 filter's penumbra doubles to about 3 cm, a few pixels at the
  // game's camera), 2048 on a GPU. Any other value is clamped to [256, 8192].
  int shadow_map_size = 0;
  // How a window shows its frames. Auto: on a CPU rasteriser through X11 shared memory when the server allows it
  // (platform::ShmSurface: lavapipe's own X11 path sends every frame through the socket on servers without DRI3,
  // Xvfb and VNC among them, 15 ms a 1280x720 frame), else the Vulkan swapchain. SharedMemory fails if unavailable.
  enum class Present { Auto, Swapchain, SharedMemory };
  Present present = Present::Auto;
};

// A CPU rasteriser's scene pixel budget (render_scale 0): dynamic resolution as consoles do, by pixel count.
inline constexpr int kCpuScenePixels = 520000;

class Renderer {
 public:
  static eng::Result<std::unique_ptr<Renderer>> create_headless(const RendererConfig& cfg);
  static eng::Result<std::unique_ptr<Renderer>> create_windowed(const RendererConfig& cfg, platform::Window& window);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Uploads once; the returned id is valid for the renderer's lifetime.
  MeshId upload_mesh(const MeshData& mesh);
  // Headless: renders and waits. Windowed: renders and presents (skips drawing while minimised; recreates the
  // swapchain after a resize). Through shared memory a frame is shown at the next call, once the following one is
  // submitted, so the CPU rasteriser draws it while the caller simulates the next (one frame of latency, as a
  // swapchain with two frames in flight has).
  eng::Result<void> render(const FrameDesc& frame);
  // The last rendered frame as RGBA8 (sRGB-encoded, alpha 255), top row first. Works in both modes.
  eng::Result<eng::Image> read_back();

  // The UI drawn over the frame when FrameDesc::overlay is set: the caller builds it each frame with
  // eng::ui::ui_begin(r.ui(), input), ImGui:: calls, eng::ui::ui_end(r.ui()); render() draws the last ended frame.
  eng::ui::Ui& ui();

  std::string device_name() const;
  // "swapchain", "shared memory" or "none" (headless): how frames reach the window.
  const char* present_path() const;
  std::string driver_info() const;
  int validation_errors() const;
  int validation_warnings() const;
  bool validation_active() const;
  const std::vector<std::string>& validation_messages() const;

  struct Impl;

 private:
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace eng::render
