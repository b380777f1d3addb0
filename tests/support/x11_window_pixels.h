#pragma once
// What the X server shows in a window, read back with XGetImage: the check that a frame really reached the screen
// (not only the renderer's own copy of it). Test support only; links X11.
#include <cstdint>
#include <vector>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include "engine/core/image.h"
#include "engine/platform/window.h"

namespace boxing_test {

// The window's pixels as RGBA8 (alpha 255), top row first; empty when the server refuses (unmapped window).
inline eng::Image x11_window_pixels(const eng::platform::Window& window) {
  eng::Image img;
  Display* d = glfwGetX11Display();
  const ::Window w = glfwGetX11Window(window.handle());
  XSync(d, False);
  XWindowAttributes wa;
  if (!XGetWindowAttributes(d, w, &wa)) return img;
  XImage* x = XGetImage(d, w, 0, 0, static_cast<unsigned>(wa.width), static_cast<unsigned>(wa.height), AllPlanes, ZPixmap);
  if (!x) return img;
  img.width = wa.width;
  img.height = wa.height;
  img.rgba.resize(static_cast<size_t>(wa.width) * static_cast<size_t>(wa.height) * 4);
  for (int y = 0; y < wa.height; ++y)
    for (int i = 0; i < wa.width; ++i) {
      const unsigned long p = XGetPixel(x, i, y);
      uint8_t* o = &img.rgba[(static_cast<size_t>(y) * static_cast<size_t>(wa.width) + static_cast<size_t>(i)) * 4];
      o[0] = static_cast<uint8_t>((p & x->red_mask) >> 16);
      o[1] = static_cast<uint8_t>((p & x->green_mask) >> 8);
      o[2] = static_cast<uint8_t>(p & x->blue_mask);
      o[3] = 255;
    }
  XDestroyImage(x);
  return img;
}

}  // namespace boxing_test
