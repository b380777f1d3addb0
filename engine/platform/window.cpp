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
  glfwSetMouseButtonCallback(w->window_, &Window::on_mouse_button);
  glfwSetCharCallback(w->window_, &Window::on_char);
  return w;
}

Window::~Window() {
  if (window_) glfwDestroyWindow(window_);
}

void Window::poll_events() {
  pressed_.clear();
  pressed_held_.clear();
  scroll_ = glm::dvec2(0.0);
  for (bool& c : clicked_) c = false;
  chars_.clear();
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

eng::ui::UiInput Window::ui_input(float dt) const {
  eng::ui::UiInput in;
  const glm::ivec2 fb = framebuffer_size();
  int ww = 0, wh = 0;
  glfwGetWindowSize(window_, &ww, &wh);
  in.display_width = static_cast<float>(fb.x);
  in.display_height = static_cast<float>(fb.y);
  in.dt = dt;
  if (glfwGetWindowAttrib(window_, GLFW_HOVERED) == GLFW_TRUE && ww > 0 && wh > 0) {
    // cursor positions are in screen coordinates; the UI is laid out in framebuffer pixels (HiDPI scale)
    const glm::dvec2 m = mouse_position();
    in.mouse_x = static_cast<float>(m.x * fb.x / ww);
    in.mouse_y = static_cast<float>(m.y * fb.y / wh);
  }
  const int buttons[3] = {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT, GLFW_MOUSE_BUTTON_MIDDLE};
  for (int b = 0; b < 3; ++b) in.mouse_down[b] = clicked_[b] || mouse_button_down(buttons[b]);
  in.wheel_x = static_cast<float>(scroll_.x);
  in.wheel_y = static_cast<float>(scroll_.y);
  using eng::ui::Key;
  const struct {
    Key key;
    int glfw;
  } keys[] = {{Key::Tab, GLFW_KEY_TAB},         {Key::Left, GLFW_KEY_LEFT},         {Key::Right, GLFW_KEY_RIGHT},
              {Key::Up, GLFW_KEY_UP},           {Key::Down, GLFW_KEY_DOWN},         {Key::PageUp, GLFW_KEY_PAGE_UP},
              {Key::PageDown, GLFW_KEY_PAGE_DOWN}, {Key::Home, GLFW_KEY_HOME},      {Key::End, GLFW_KEY_END},
              {Key::Insert, GLFW_KEY_INSERT},   {Key::Delete, GLFW_KEY_DELETE},     {Key::Backspace, GLFW_KEY_BACKSPACE},
              {Key::Space, GLFW_KEY_SPACE},     {Key::Enter, GLFW_KEY_ENTER},       {Key::Escape, GLFW_KEY_ESCAPE},
              {Key::KeypadEnter, GLFW_KEY_KP_ENTER}, {Key::A, GLFW_KEY_A},          {Key::C, GLFW_KEY_C},
              {Key::V, GLFW_KEY_V},             {Key::X, GLFW_KEY_X},               {Key::Y, GLFW_KEY_Y},
              {Key::Z, GLFW_KEY_Z}};
  for (const auto& k : keys) in.key_down[static_cast<int>(k.key)] = key_down(k.glfw);
  in.ctrl = key_down(GLFW_KEY_LEFT_CONTROL) || key_down(GLFW_KEY_RIGHT_CONTROL);
  in.shift = key_down(GLFW_KEY_LEFT_SHIFT) || key_down(GLFW_KEY_RIGHT_SHIFT);
  in.alt = key_down(GLFW_KEY_LEFT_ALT) || key_down(GLFW_KEY_RIGHT_ALT);
  in.super = key_down(GLFW_KEY_LEFT_SUPER) || key_down(GLFW_KEY_RIGHT_SUPER);
  in.chars = chars_;
  return in;
}

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
  if (!self) return;
  unsigned bit = 0;
  if (key == GLFW_KEY_LEFT_SHIFT) bit = kHeldLeftShift;
  if (key == GLFW_KEY_RIGHT_SHIFT) bit = kHeldRightShift;
  if (key == GLFW_KEY_LEFT_CONTROL) bit = kHeldLeftCtrl;
  if (key == GLFW_KEY_RIGHT_CONTROL) bit = kHeldRightCtrl;
  if (action == GLFW_PRESS) self->held_ |= bit;
  if (action == GLFW_RELEASE) self->held_ &= ~bit;
  if (action == GLFW_PRESS) self->pressed_.push_back(key), self->pressed_held_.push_back(self->held_);
}

GamepadReading read_gamepad(int jid) {
  GamepadReading r;
  GLFWgamepadstate s;
  if (jid < 0 || jid >= kMaxGamepads || glfwJoystickIsGamepad(jid) != GLFW_TRUE || glfwGetGamepadState(jid, &s) != GLFW_TRUE)
    return r;
  r.connected = true;
  for (int k = 0; k < 15; ++k) r.buttons[k] = s.buttons[k] == GLFW_PRESS;
  for (int k = 0; k < 6; ++k) r.axes[k] = s.axes[k];
  if (const char* n = glfwGetGamepadName(jid)) r.name = n;
  return r;
}

void Window::on_scroll(GLFWwindow* gw, double dx, double dy) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(gw));
  if (self) self->scroll_ += glm::dvec2(dx, dy);
}

void Window::on_mouse_button(GLFWwindow* gw, int button, int action, int) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(gw));
  if (self && action == GLFW_PRESS && button >= 0 && button < 3) self->clicked_[button] = true;
}

void Window::on_char(GLFWwindow* gw, unsigned int codepoint) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(gw));
  if (self) self->chars_.push_back(codepoint);
}

void Window::on_framebuffer_size(GLFWwindow* gw, int, int) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(gw));
  if (self) self->resized_ = true;
}

}  // namespace eng::platform
