// The UI frame API without a GPU: synthetic UiInput clicks press an ImGui button (on the frame of the release, as
// ImGui's default button behaviour says), ui_wants_mouse is true over a window and false elsewhere, typed characters
// reach a focused text field (which then claims the keyboard), and draw data exists only for an ended frame.
#include <gtest/gtest.h>

#include <cstring>

#include "engine/ui/ui.h"
#include "imgui.h"

using namespace eng::ui;

namespace {

UiInput screen(float mx = -FLT_MAX, float my = -FLT_MAX, bool left = false) {
  UiInput in;
  in.display_width = 640;
  in.display_height = 480;
  in.mouse_x = mx;
  in.mouse_y = my;
  in.mouse_down[0] = left;
  return in;
}

// A fixed window at (100, 100), 200 x 120, holding one button; returns whether the button reported a press and
// where it is.
struct Panel {
  bool pressed = false;
  ImVec2 lo, hi;
  ImVec2 centre() const { return ImVec2(0.5f * (lo.x + hi.x), 0.5f * (lo.y + hi.y)); }
};
Panel button_frame(Ui& ui, const UiInput& in) {
  Panel p;
  ui_begin(ui, in);
  ImGui::SetNextWindowPos(ImVec2(100, 100), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(200, 120), ImGuiCond_Always);
  ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoSavedSettings);
  p.pressed = ImGui::Button("press me", ImVec2(120, 30));
  p.lo = ImGui::GetItemRectMin();
  p.hi = ImGui::GetItemRectMax();
  ImGui::End();
  ui_end(ui);
  return p;
}

}  // namespace

TEST(Ui, ASyntheticClickOnAButtonReportsItPressedOnTheFrameOfTheRelease) {
  Ui ui;
  const Panel first = button_frame(ui, screen());  // lays the window out; no mouse
  EXPECT_FALSE(first.pressed);
  ASSERT_GT(first.hi.x, first.lo.x);
  EXPECT_GE(first.lo.x, 100.0f);  // inside the window
  const ImVec2 c = first.centre();
  EXPECT_FALSE(button_frame(ui, screen(c.x, c.y)).pressed);        // hover
  EXPECT_FALSE(button_frame(ui, screen(c.x, c.y, true)).pressed);  // press: not yet
  EXPECT_TRUE(button_frame(ui, screen(c.x, c.y)).pressed);         // release over the button: clicked
  EXPECT_FALSE(button_frame(ui, screen(c.x, c.y)).pressed);        // once
  // a click outside the button (inside the window, below it) presses nothing
  const float below = first.hi.y + 20.0f;
  EXPECT_FALSE(button_frame(ui, screen(c.x, below, true)).pressed);
  EXPECT_FALSE(button_frame(ui, screen(c.x, below)).pressed);
  // press on the button, release away from it: not a click (ImGui's PressedOnClickRelease)
  EXPECT_FALSE(button_frame(ui, screen(c.x, c.y, true)).pressed);
  EXPECT_FALSE(button_frame(ui, screen(600, 400)).pressed);
}

TEST(Ui, WantsTheMouseOverAWindowAndNotElsewhere) {
  Ui ui;
  button_frame(ui, screen());
  ui_begin(ui, screen(150, 200));  // inside the window (100..300 x 100..220), below the button
  EXPECT_TRUE(ui_wants_mouse(ui));
  ui_end(ui);
  ui_begin(ui, screen(500, 400));  // over the scene
  EXPECT_FALSE(ui_wants_mouse(ui));
  ui_end(ui);
  ui_begin(ui, screen());  // no mouse at all
  EXPECT_FALSE(ui_wants_mouse(ui));
  EXPECT_FALSE(ui_wants_keyboard(ui));
  ui_end(ui);
}

TEST(Ui, TypedCharactersReachAClickedTextFieldWhichThenClaimsTheKeyboard) {
  Ui ui;
  char text[32] = "";
  ImVec2 lo, hi;
  auto frame = [&](const UiInput& in) {
    ui_begin(ui, in);
    ImGui::SetNextWindowPos(ImVec2(20, 20), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(300, 80), ImGuiCond_Always);
    ImGui::Begin("form", nullptr, ImGuiWindowFlags_NoSavedSettings);
    ImGui::InputText("name", text, sizeof text);
    lo = ImGui::GetItemRectMin();
    hi = ImGui::GetItemRectMax();
    ImGui::End();
    const bool keys = ui_wants_keyboard(ui);
    ui_end(ui);
    return keys;
  };
  EXPECT_FALSE(frame(screen()));
  const float x = lo.x + 10.0f, y = 0.5f * (lo.y + hi.y);
  frame(screen(x, y, true));
  frame(screen(x, y));
  UiInput typing = screen(x, y);
  typing.chars = {'h', 'i'};
  frame(typing);
  EXPECT_TRUE(frame(screen(x, y)));
  EXPECT_STREQ(text, "hi");
}

TEST(Ui, DrawDataExistsOnlyForAnEndedFrame) {
  Ui ui;
  EXPECT_EQ(ui_draw_data(ui), nullptr);
  const Panel p = button_frame(ui, screen());
  (void)p;
  ImDrawData* d = ui_draw_data(ui);
  ASSERT_NE(d, nullptr);
  EXPECT_GT(d->TotalVtxCount, 0);  // the window and its button were drawn
  EXPECT_EQ(d->DisplaySize.x, 640.0f);
  ui_begin(ui, screen());
  EXPECT_EQ(ui_draw_data(ui), nullptr);
  ui_end(ui);
  EXPECT_NE(ui_draw_data(ui), nullptr);
}

TEST(Ui, TwoUisKeepSeparateState) {
  Ui a, b;
  button_frame(a, screen());
  button_frame(b, screen());
  const ImVec2 c = button_frame(a, screen()).centre();
  button_frame(a, screen(c.x, c.y, true));
  button_frame(b, screen());  // b sees no mouse: it must not disturb a's press
  EXPECT_TRUE(button_frame(a, screen(c.x, c.y)).pressed);
  EXPECT_FALSE(button_frame(b, screen(c.x, c.y)).pressed);
}
