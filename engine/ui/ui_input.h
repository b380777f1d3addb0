#pragma once
// One frame of user input for the immediate-mode UI, as plain data: gathered by the platform layer (or made up by a
// test), consumed by ui_begin(). No window-system or ImGui types, so platform and ui stay independent.
#include <cfloat>
#include <cstdint>
#include <vector>

namespace eng::ui {

// The keys the UI reacts to (navigation and text editing; letters for the Ctrl shortcuts).
enum class Key : uint8_t {
  Tab, Left, Right, Up, Down, PageUp, PageDown, Home, End, Insert, Delete, Backspace, Space, Enter, Escape,
  KeypadEnter, A, C, V, X, Y, Z, Count
};
inline constexpr int kKeyCount = static_cast<int>(Key::Count);

struct UiInput {
  float display_width = 0, display_height = 0;  // pixels of the image the UI is drawn into
  float dt = 1.0f / 60.0f;                       // seconds since the previous UI frame (> 0)
  // Mouse in display pixels from the top-left corner; -FLT_MAX when there is no mouse (outside the window).
  float mouse_x = -FLT_MAX, mouse_y = -FLT_MAX;
  // Left, right, middle: held, or pressed at any time since the previous frame (so a click shorter than a frame
  // still reaches the UI).
  bool mouse_down[3] = {false, false, false};
  float wheel_x = 0, wheel_y = 0;  // scroll since the previous frame (lines; +y = away from the user)
  bool key_down[kKeyCount] = {};
  bool ctrl = false, shift = false, alt = false, super = false;
  std::vector<uint32_t> chars;  // text typed since the previous frame (Unicode code points)
};

}  // namespace eng::ui
