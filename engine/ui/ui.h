#pragma once
// Immediate-mode UI frames (Dear ImGui 1.86, the version Debian ships): the game builds its windows with ImGui::
// calls between ui_begin(ui, input) and ui_end(ui); the renderer draws the finished frame (ui_draw_data) into the
// overlay pass. ui_wants_mouse / ui_wants_keyboard tell the game whether this frame's input belongs to a panel or
// to the scene (io.WantCaptureMouse / WantCaptureKeyboard: hovering or dragging a window, a text field focused).
//
// Input: ImGui 1.86 predates the input-event queue (AddMousePosEvent & co. came in 1.87); it reads a state
// snapshot per frame (io.MousePos, MouseDown[], MouseWheel, KeysDown[] through io.KeyMap, KeyCtrl..., and
// AddInputCharacter for text), which is what UiInput holds. A button therefore needs the press and the release in
// different frames; UiInput::mouse_down latches presses shorter than a frame for that reason.
//
// Fonts: ImGui's default (ProggyClean, 13 px) stays the first font, what every panel uses; a game's title screen and
// broadcast HUD also get a bold display face in three sizes (ui_font: Medium 18, Large 28, Huge 72 px), rasterised from
// DejaVu Sans Bold (Debian's fonts-dejavu-core) when it is installed, else ImGui's default face at those sizes.
//
// Each Ui owns its ImGui context (made current around every call), so several can coexist, e.g. one per renderer
// in tests. Headless and deterministic: nothing reads a clock or a window; the font atlas is built on the first
// frame if no renderer backend built it (so a Ui works without a GPU).
#include "engine/ui/ui_input.h"

struct ImGuiContext;
struct ImDrawData;
struct ImFont;

namespace eng::ui {

enum class Font { Default, Medium, Large, Huge };

class Ui {
 public:
  Ui();  // creates the ImGui context: no imgui.ini / log files, dark style, io.KeyMap onto eng::ui::Key
  ~Ui();
  Ui(const Ui&) = delete;
  Ui& operator=(const Ui&) = delete;

  ImGuiContext* context() const { return imgui_; }
  bool in_frame() const { return in_frame_; }
  bool has_frame() const { return has_frame_; }  // a frame was ended and not begun since

 private:
  friend void ui_begin(Ui&, const UiInput&);
  friend void ui_end(Ui&);
  ImGuiContext* imgui_ = nullptr;
  ImFont* fonts_[4] = {nullptr, nullptr, nullptr, nullptr};
  friend ImFont* ui_font(const Ui&, Font);
  bool in_frame_ = false, has_frame_ = false;
};

// Feeds the input and starts a UI frame (ImGui::NewFrame); the UI's context is current until ui_end.
void ui_begin(Ui& ui, const UiInput& input);
// Finishes the frame (ImGui::Render): its draw data stays valid until the next ui_begin.
void ui_end(Ui& ui);
// Whether the UI claims the mouse / keyboard this frame (valid after ui_begin).
bool ui_wants_mouse(const Ui& ui);
bool ui_wants_keyboard(const Ui& ui);
// Whether a text field is being edited (io.WantTextInput): only then do typed keys belong to the UI, whatever window
// was clicked last (a game routes its own keys unless this is true).
bool ui_wants_text(const Ui& ui);
// A font for ImGui::PushFont (or ImDrawList::AddText), owned by the Ui's atlas.
ImFont* ui_font(const Ui& ui, Font f);
// The last ended frame's draw lists, or nullptr when there is none (before the first ui_end, or inside a frame).
ImDrawData* ui_draw_data(const Ui& ui);

}  // namespace eng::ui
