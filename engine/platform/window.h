#pragma once
// GLFW window wrapper: owns the window, collects input per frame, creates the Vulkan surface.
#include <memory>
#include <string>
#include <vector>
#include <vulkan/vulkan.h>
#include <glm/glm.hpp>
#include "engine/core/result.h"
#include "engine/ui/ui_input.h"

struct GLFWwindow;

namespace eng::platform {

// True when a display server is reachable. Checks DISPLAY / WAYLAND_DISPLAY first so it returns at once (never
// blocks) on headless machines, then tries to initialise GLFW.
bool display_available();

// A gamepad as GLFW 3.3 sees it (GLFWgamepadstate: the Xbox layout GLFW maps every pad in its built-in SDL
// GameController database to; buttons and axes in GLFW_GAMEPAD_* order; sticks -1..1 with up negative, triggers -1
// released .. 1 pulled). Not connected: a joystick GLFW has no mapping for counts as no pad.
struct GamepadReading {
  bool connected = false;
  bool buttons[15] = {};
  float axes[6] = {0.0f, 0.0f, 0.0f, 0.0f, -1.0f, -1.0f};
  const char* name = "";  // glfwGetGamepadName's
};
inline constexpr int kMaxGamepads = 16;  // GLFW_JOYSTICK_1 .. GLFW_JOYSTICK_LAST
// Reads pad jid now (GLFW must be initialised: a Window exists). GLFW notices pads plugged in or out as it polls
// events, so reading every pad each frame is the hot-plug.
GamepadReading read_gamepad(int jid);

struct WindowConfig {
  std::string title = "boxing";
  int width = 1280;
  int height = 720;
  bool resizable = true;
};

class Window {
 public:
  static eng::Result<std::unique_ptr<Window>> create(const WindowConfig& cfg);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Clears the per-frame input (pressed keys, scroll) and pumps GLFW events.
  void poll_events();
  bool should_close() const;
  void request_close();
  void set_title(const std::string& title);
  void set_size(int width, int height);
  void iconify();
  void restore();

  glm::ivec2 framebuffer_size() const;
  bool minimized() const;  // iconified or zero-sized framebuffer: nothing to render
  // True once after the framebuffer changed size (the renderer also detects this on its own).
  bool consume_resized();

  // GLFW_KEY_* codes: pressed during the last poll_events() (edge), and currently held.
  bool key_pressed(int glfw_key) const;
  bool key_down(int glfw_key) const;
  // Every key press of the last poll_events(), in order, repeats included (a menu takes two quick Downs as two).
  const std::vector<int>& keys_pressed() const { return pressed_; }
  // The same presses with the modifier keys held as each went down (kHeld* bits): GLFW's mods say Shift, not which
  // Shift, and asking glfwGetKey after the poll is too late when a quick Shift+A was pressed and let go in one poll.
  enum : unsigned { kHeldLeftShift = 1u, kHeldRightShift = 2u, kHeldLeftCtrl = 4u, kHeldRightCtrl = 8u };
  const std::vector<unsigned>& keys_pressed_held() const { return pressed_held_; }
  glm::dvec2 mouse_position() const;
  bool mouse_button_down(int glfw_button) const;
  glm::dvec2 scroll_delta() const;  // accumulated during the last poll_events()

  // This frame's input for the UI (eng::ui::ui_begin): mouse in framebuffer pixels (the image the UI is drawn
  // into), buttons held or pressed since the last poll, wheel and text of the last poll, UI keys and modifiers
  // held, display size = framebuffer size. dt is the caller's frame time.
  eng::ui::UiInput ui_input(float dt) const;

  eng::Result<VkSurfaceKHR> create_surface(VkInstance instance) const;
  // Instance extensions GLFW needs to present to this window system.
  static std::vector<const char*> required_instance_extensions();
  GLFWwindow* handle() const { return window_; }

 private:
  Window() = default;
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void on_scroll(GLFWwindow* w, double dx, double dy);
  static void on_framebuffer_size(GLFWwindow* w, int width, int height);
  static void on_mouse_button(GLFWwindow* w, int button, int action, int mods);
  static void on_char(GLFWwindow* w, unsigned int codepoint);

  GLFWwindow* window_ = nullptr;
  std::vector<int> pressed_;
  std::vector<unsigned> pressed_held_;  // per press: the modifiers held (kHeld* bits)
  unsigned held_ = 0;                   // the modifiers held now, from the key events in order
  glm::dvec2 scroll_{0.0};
  bool clicked_[3] = {false, false, false};  // pressed during the last poll (latched for the UI)
  std::vector<uint32_t> chars_;              // typed during the last poll
  bool resized_ = false;
};

}  // namespace eng::platform
