#include "engine/ui/ui.h"

#include <cassert>
#include <cstdio>

#include "imgui.h"

namespace eng::ui {

Ui::Ui() {
  IMGUI_CHECKVERSION();
  ImGuiContext* prev = ImGui::GetCurrentContext();
  imgui_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(imgui_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // never write imgui.ini next to the binary
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  // The default font first: every panel keeps it (ImGui's first font is the default). Then the display face.
  fonts_[0] = io.Fonts->AddFontDefault();
  const char* kDisplayFace = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";  // fonts-dejavu-core
  const float sizes[3] = {18.0f, 28.0f, 72.0f};
  // The huge size draws titles and numbers: ASCII up to the capitals ('_'), no lower case.
  static const ImWchar kCapitals[] = {0x20, 0x5F, 0};
  for (int k = 0; k < 3; ++k) {
    ImFont* f = nullptr;
    if (std::FILE* probe = std::fopen(kDisplayFace, "rb")) {  // AddFontFromFileTTF asserts on a missing file
      std::fclose(probe);
      // No horizontal oversampling at the large sizes (ImFontConfig::OversampleH, default 3 in imgui.h: "for
      // sub-pixel positioning"): at 28 and 72 px it tripled the atlas for nothing seen (19 MB more resident).
      ImFontConfig c;
      c.OversampleH = k == 0 ? 2 : 1;
      c.OversampleV = 1;
      f = io.Fonts->AddFontFromFileTTF(kDisplayFace, sizes[k], &c, k == 2 ? kCapitals : nullptr);
    }
    if (!f) {
      ImFontConfig c;
      c.SizePixels = sizes[k];
      f = io.Fonts->AddFontDefault(&c);
    }
    fonts_[k + 1] = f;
  }
  // ImGui 1.86 keyboard: KeysDown[] indexed by our Key values, KeyMap says which ImGui key each one is.
  const struct {
    ImGuiKey_ imgui;
    Key ours;
  } map[] = {{ImGuiKey_Tab, Key::Tab},           {ImGuiKey_LeftArrow, Key::Left},   {ImGuiKey_RightArrow, Key::Right},
             {ImGuiKey_UpArrow, Key::Up},        {ImGuiKey_DownArrow, Key::Down},   {ImGuiKey_PageUp, Key::PageUp},
             {ImGuiKey_PageDown, Key::PageDown}, {ImGuiKey_Home, Key::Home},        {ImGuiKey_End, Key::End},
             {ImGuiKey_Insert, Key::Insert},     {ImGuiKey_Delete, Key::Delete},    {ImGuiKey_Backspace, Key::Backspace},
             {ImGuiKey_Space, Key::Space},       {ImGuiKey_Enter, Key::Enter},      {ImGuiKey_Escape, Key::Escape},
             {ImGuiKey_KeyPadEnter, Key::KeypadEnter}, {ImGuiKey_A, Key::A},        {ImGuiKey_C, Key::C},
             {ImGuiKey_V, Key::V},               {ImGuiKey_X, Key::X},              {ImGuiKey_Y, Key::Y},
             {ImGuiKey_Z, Key::Z}};
  for (const auto& m : map) io.KeyMap[m.imgui] = static_cast<int>(m.ours);
  ImGui::SetCurrentContext(prev);
}

Ui::~Ui() {
  if (imgui_) ImGui::DestroyContext(imgui_);
}

void ui_begin(Ui& ui, const UiInput& in) {
  assert(!ui.in_frame_ && "ui_begin: the previous frame was not ended");
  ImGui::SetCurrentContext(ui.imgui_);
  ImGuiIO& io = ImGui::GetIO();
  if (!io.Fonts->IsBuilt()) {  // no renderer backend built it: build the atlas for layout (headless, tests)
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  io.DisplaySize = ImVec2(in.display_width, in.display_height);
  io.DeltaTime = in.dt > 0.0f ? in.dt : 1.0f / 60.0f;  // ImGui asserts on a zero time step
  io.MousePos = ImVec2(in.mouse_x, in.mouse_y);
  for (int b = 0; b < 3; ++b) io.MouseDown[b] = in.mouse_down[b];
  io.MouseWheel = in.wheel_y;
  io.MouseWheelH = in.wheel_x;
  for (int k = 0; k < kKeyCount; ++k) io.KeysDown[k] = in.key_down[k];
  io.KeyCtrl = in.ctrl;
  io.KeyShift = in.shift;
  io.KeyAlt = in.alt;
  io.KeySuper = in.super;
  for (uint32_t c : in.chars) io.AddInputCharacter(c);
  ImGui::NewFrame();
  ui.in_frame_ = true;
  ui.has_frame_ = false;
}

void ui_end(Ui& ui) {
  assert(ui.in_frame_ && "ui_end without ui_begin");
  ImGui::SetCurrentContext(ui.imgui_);
  ImGui::Render();
  ui.in_frame_ = false;
  ui.has_frame_ = true;
}

namespace {
const ImGuiIO& io_of(const Ui& ui) {
  ImGui::SetCurrentContext(ui.context());
  return ImGui::GetIO();
}
}  // namespace

bool ui_wants_mouse(const Ui& ui) { return io_of(ui).WantCaptureMouse; }
bool ui_wants_keyboard(const Ui& ui) { return io_of(ui).WantCaptureKeyboard; }
bool ui_wants_text(const Ui& ui) { return io_of(ui).WantTextInput; }

ImFont* ui_font(const Ui& ui, Font f) { return ui.fonts_[static_cast<int>(f)]; }

ImDrawData* ui_draw_data(const Ui& ui) {
  if (!ui.has_frame()) return nullptr;
  ImGui::SetCurrentContext(ui.context());
  return ImGui::GetDrawData();
}

}  // namespace eng::ui
