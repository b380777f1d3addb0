#include "engine/platform/window.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

namespace eng::platform {
namespace {

// GLFW is process-global; initialise it once and keep it for the life of the process (windows may come and go).
bool glfw_ready() {
  static const bool ok = [] {
    glfwSetErrorCallback([](int code, const char* msg) { std::fprintf(stderr, "glfw: %s (%d)\n", msg, code); });
    return glfwInit() == GLFW_TRUE;
  }();
  return ok;
}

bool env_set(const char* name) {
  const char* v = std::getenv(name);
  return v && *v;
}

}  // namespace

bool display_available() {
  if (!env_set("DISPLAY") && !env_set("WAYLAND_DISPLAY")) return false;
  return glfw_ready();
}

eng::Result<std::unique_ptr<Window>> Window::create(const WindowConfig& cfg) {
  if (!display_available())
    return eng::make_error("no display: run with --headless or start Xvfb (xvfb-run -s \"-screen 0 1280x720x24\")");
  if (glfwVulkanSupported() != GLFW_TRUE)
    return eng::make_error("GLFW found no Vulkan loader: install libvulkan1 and mesa-vulkan-drivers");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan renders; no GL context
  glfwWindowHint(GLFW_RESIZABLE, cfg.resizable ? GLFW_TRUE : GLFW_FALSE);
  std::unique_ptr<Window> w(new Window());
  w->window_ = glfwCreateWindow(cfg.width, cfg.height, cfg.title.c_str(), nullptr, nullptr);
  if (!w->window_) return eng::make_error("could not create a " + std::to_string(cfg.width) + "x" +
                                          std::to_string(cfg.height) + " window: check the display server");
  glfwSetWindowUserPointer(w->window_, w.get());
  glfwSetKeyCallback(w->window_, &Window::on_key);
  glfwSetScrollCallback(w->window_, &Window::on_scroll);
  glfwSetFramebufferSizeCallback(w->window_, &Window::on_framebuffer_size);
  return w;
}

Window::~Window() {
  if (window_) glfwDestroyWindow(window_);
}

void Window::poll_events() {
  pressed_.clear();
  scroll_ = glm::dvec2(0.0);
  glfwPollEvents();
}

bool Window::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }
void Window::set_size(int width, int height) { glfwSetWindowSize(window_, width, height); }
void Window::iconify() { glfwIconifyWindow(window_); }
void Window::restore() { glfwRestoreWindow(window_); }

glm::ivec2 Window::framebuffer_size() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {w, h};
}

bool Window::minimized() const {
  const glm::ivec2 s = framebuffer_size();
  return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE || s.x == 0 || s.y == 0;
}

bool Window::consume_resized() {
  const bool r = resized_;
  resized_ = false;
  return r;
}

bool Window::key_pressed(int key) const { return std::find(pressed_.begin(), pressed_.end(), key) != pressed_.end(); }
bool Window::key_down(int key) const { return glfwGetKey(window_, key) == GLFW_PRESS; }

glm::dvec2 Window::mouse_position() const {
  double x = 0, y = 0;
  glfwGetCursorPos(window_, &x, &y);
  return {x, y};
}

bool Window::mouse_button_down(int button) const { return glfwGetMouseButton(window_, button) == GLFW_PRESS; }
glm::dvec2 Window::scroll_delta() const { return scroll_; }

eng::Result<VkSurfaceKHR> Window::create_surface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  const VkResult r = glfwCreateWindowSurface(instance, window_, nullptr, &surface);
  if (r != VK_SUCCESS)
    return eng::make_error("glfwCreateWindowSurface failed (VkResult " + std::to_string(r) +
                           "): the instance lacks the surface extensions from Window::required_instance_extensions()");
  return surface;
}

std::vector<const char*> Window::required_instance_extensions() {
  if (!glfw_ready()) return {};
  uint32_t n = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&n);
  return names ? std::vector<const char*>(names, names + n) : std::vector<const char*>{};
}

void Window::on_key(GLFWwindow* gw, int key, int, int action, int) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(gw));
  if (self && action == GLFW_PRESS) self->pressed_.push_back(key);
}

void Window::on_scroll(GLFWwindow* gw, double dx, double dy) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(gw));
  if (self) self->scroll_ += glm::dvec2(dx, dy);
}

void Window::on_framebuffer_size(GLFWwindow* gw, int, int) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(gw));
  if (self) self->resized_ = true;
}

}  // namespace eng::platform
