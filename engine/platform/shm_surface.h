#pragma once
// ShmSurface: shows CPU-side frames in a window through X11 shared memory (MIT-SHM), for a CPU rasteriser.
//
// Why: lavapipe's X11 presentation (Mesa 22.3) uses shared memory only when the X server also has DRI3; Xvfb, Xvnc
// and other GPU-less servers lack it, so every frame goes to the server as a PutImage through the socket: measured
// 15 ms a 1280x720 frame under Xvfb on 2 cores (the client's write, the server's read and copy), on top of the render
// (docs/decisions/renderer-speed.md). Here the frame is written once into memory the server reads directly.
#include <cstdint>
#include <memory>
#include "engine/core/result.h"

namespace eng::platform {

class Window;

class ShmSurface {
 public:
  // Fails (with the reason) when the window is not on a local X server with MIT-SHM, or its visual is not 24/32-bit
  // true colour in B, G, R, X byte order (the format written here).
  static eng::Result<std::unique_ptr<ShmSurface>> create(const Window& window, int width, int height);
  ~ShmSurface();
  ShmSurface(const ShmSurface&) = delete;
  ShmSurface& operator=(const ShmSurface&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // The shared image: height rows of `stride` bytes, B, G, R, X per pixel, top row first. Written between presents.
  uint8_t* pixels();
  int stride() const;
  // Copies the image to the window and waits until the server has read it (so the pixels may be written again).
  void present();

  struct Impl;

 private:
  explicit ShmSurface(std::unique_ptr<Impl> impl, int width, int height);
  std::unique_ptr<Impl> impl_;
  int width_ = 0, height_ = 0;
};

}  // namespace eng::platform
