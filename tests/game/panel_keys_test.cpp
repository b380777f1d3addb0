// The live panel's keys (game/control_panel.h) without a window: handle_panel_keys with an injected KeyState, and the
// keyboard's owner frame by frame as run_windowed (game/app.cpp) decides it: after ui_begin, the keys are the game's
// (its own keys, the fight keys, handle_panel_keys) unless ui_wants_keyboard says a panel's text field has them. Tab
// is both the panel's toggle (a game key) and ImGui's focus key; the panel's fields take no Tab focus, so a game key
// is never swallowed by a text field the player did not click.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "engine/ui/ui.h"
#include "game/control_panel.h"
#include "game/interaction/interaction.h"
#include "game/world.h"
#include "imgui.h"
#include "imgui_internal.h"

namespace boxing {
namespace {

std::unique_ptr<World> two_boxers() {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Stand;
  o.scenario = "stand";
  o.seed = 1;
  auto w = make_world(o);
  EXPECT_TRUE(w) << w.error();
  return w ? std::move(*w) : nullptr;
}

// The keys pressed this frame, as the window's key_pressed reports them.
struct Keys {
  std::set<int> down;
  KeyState state() const {
    return {[](const void* c, int k) { return static_cast<const Keys*>(c)->down.count(k) > 0; }, this};
  }
};

void press(World& w, SceneView& view, PanelState& p, std::set<int> keys) {
  Keys k{std::move(keys)};
  handle_panel_keys(w, view, p, k.state());
}

TEST(PanelKeys, NoKeyNoChange) {
  auto w = two_boxers();
  ASSERT_TRUE(w);
  SceneView view;
  PanelState p;
  press(*w, view, p, {});
  press(*w, view, p, {GLFW_KEY_J, GLFW_KEY_K, GLFW_KEY_G, GLFW_KEY_H});  // the fight keys and the window's own: not the panel's
  EXPECT_TRUE(w->interaction->queue.empty());
  EXPECT_TRUE(p.open);
  EXPECT_FALSE(p.paused || p.step_once || p.restart);
  EXPECT_EQ(p.slow, 0);
  const DebugDrawFlags d0;
  EXPECT_TRUE(view.debug.contacts == d0.contacts && view.debug.com == d0.com && view.debug.support == d0.support &&
              view.debug.capture_point == d0.capture_point && view.debug.hits == d0.hits);
}

// F1 / F2 cycle boxer 0's / 1's servo space world -> person -> parent -> world, F3 / F4 toggle the balance, F6 / F7
// the root spring: each through one set event (recorded and replayed like the panel's clicks), applied at the next
// step, and only to its own boxer.
TEST(PanelKeys, FunctionKeysChangeTheirBoxersSettingsThroughSetEvents) {
  auto w = two_boxers();
  ASSERT_TRUE(w);
  World& world = *w;
  SceneView view;
  PanelState p;
  const auto servo = [&](int k) { return std::string(servo_space_name(world.boxers[k].settings.space)); };
  ASSERT_EQ(servo(0), "world");
  ASSERT_EQ(servo(1), "world");
  for (const char* next : {"person", "parent", "world"}) {
    press(world, view, p, {GLFW_KEY_F1});
    ASSERT_EQ(world.interaction->queue.size(), 1u);
    EXPECT_EQ(world.interaction->queue[0].kind, InputKind::Set);
    EXPECT_EQ(world.interaction->queue[0].boxer, 0);
    EXPECT_EQ(world.interaction->queue[0].servo, std::optional<std::string>(next));
    step_world(world);
    EXPECT_EQ(servo(0), next);
    EXPECT_EQ(servo(1), "world");
  }
  press(world, view, p, {GLFW_KEY_F2});
  step_world(world);
  EXPECT_EQ(servo(1), "person");
  EXPECT_EQ(servo(0), "world");

  const bool qp0 = world.boxers[0].settings.balance_qp, qp1 = world.boxers[1].settings.balance_qp;
  press(world, view, p, {GLFW_KEY_F3});
  step_world(world);
  EXPECT_EQ(world.boxers[0].settings.balance_qp, !qp0);
  EXPECT_EQ(world.boxers[1].settings.balance_qp, qp1);
  press(world, view, p, {GLFW_KEY_F4});
  step_world(world);
  EXPECT_EQ(world.boxers[1].settings.balance_qp, !qp1);
  press(world, view, p, {GLFW_KEY_F3});
  step_world(world);
  EXPECT_EQ(world.boxers[0].settings.balance_qp, qp0);  // back

  const bool root0 = world.boxers[0].settings.root_params.enabled, root1 = world.boxers[1].settings.root_params.enabled;
  press(world, view, p, {GLFW_KEY_F6});
  step_world(world);
  EXPECT_EQ(world.boxers[0].settings.root_params.enabled, !root0);
  EXPECT_EQ(world.boxers[1].settings.root_params.enabled, root1);
  press(world, view, p, {GLFW_KEY_F7});
  step_world(world);
  EXPECT_EQ(world.boxers[1].settings.root_params.enabled, !root1);
}

// 1-5 toggle one debug drawing each; Tab the panel; P pause; period one step; [ and ] the slow motion (1x, 1/2, 1/4,
// 1/10, held at the ends); F5 the restart. None of them touches the simulation (no event).
TEST(PanelKeys, ViewAndTimeKeysToggleTheirOwnSettingOnly) {
  auto w = two_boxers();
  ASSERT_TRUE(w);
  SceneView view;
  PanelState p;
  const std::pair<int, bool DebugDrawFlags::*> debug[] = {
      {GLFW_KEY_1, &DebugDrawFlags::contacts}, {GLFW_KEY_2, &DebugDrawFlags::com},
      {GLFW_KEY_3, &DebugDrawFlags::support},  {GLFW_KEY_4, &DebugDrawFlags::capture_point},
      {GLFW_KEY_5, &DebugDrawFlags::hits}};
  for (const auto& [key, flag] : debug) {
    const DebugDrawFlags before = view.debug;
    press(*w, view, p, {key});
    for (const auto& [other, f] : debug) EXPECT_EQ(view.debug.*f, f == flag ? !(before.*f) : before.*f) << key;
    press(*w, view, p, {key});
    EXPECT_EQ(view.debug.*flag, before.*flag);
  }
  press(*w, view, p, {GLFW_KEY_TAB});
  EXPECT_FALSE(p.open);
  press(*w, view, p, {GLFW_KEY_TAB});
  EXPECT_TRUE(p.open);
  press(*w, view, p, {GLFW_KEY_P});
  EXPECT_TRUE(p.paused);
  press(*w, view, p, {GLFW_KEY_PERIOD});
  EXPECT_TRUE(p.step_once);
  press(*w, view, p, {GLFW_KEY_P});
  EXPECT_FALSE(p.paused);
  const char* scales[] = {"1x", "1/2", "1/4", "1/10", "1/10"};
  for (const char* s : scales) {
    EXPECT_STREQ(time_scale_name(p), s);
    press(*w, view, p, {GLFW_KEY_LEFT_BRACKET});
  }
  EXPECT_EQ(p.slow, 3);
  EXPECT_DOUBLE_EQ(time_scale(p), 0.1);
  for (int i = 0; i < 5; ++i) press(*w, view, p, {GLFW_KEY_RIGHT_BRACKET});
  EXPECT_EQ(p.slow, 0);
  EXPECT_DOUBLE_EQ(time_scale(p), 1.0);
  EXPECT_FALSE(p.restart);
  press(*w, view, p, {GLFW_KEY_F5});
  EXPECT_TRUE(p.restart);
  EXPECT_TRUE(w->interaction->queue.empty());
}

// The window's frames without the window: a headless eng::ui::Ui (1280 x 720), the panel built each frame, the keys
// handed out as run_windowed hands them (after ui_begin: to the game unless ui_wants_keyboard).
struct Frames {
  World& w;
  eng::ui::Ui ui;
  SceneView view;
  PanelState p;
  bool last_keys_to_game = true;
  explicit Frames(World& world) : w(world) {}

  // One frame: the mouse at (x, y) (< 0: none), the left button, the keys pressed (GLFW codes; Tab also reaches the
  // UI as held this frame) and the text typed.
  void frame(float x, float y, bool left, std::set<int> keys = {}, std::vector<uint32_t> chars = {}) {
    eng::ui::UiInput in;
    in.display_width = 1280, in.display_height = 720;
    if (x >= 0) in.mouse_x = x, in.mouse_y = y;
    in.mouse_down[0] = left;
    in.key_down[static_cast<int>(eng::ui::Key::Tab)] = keys.count(GLFW_KEY_TAB) > 0;
    in.chars = std::move(chars);
    eng::ui::ui_begin(ui, in);
    last_keys_to_game = !eng::ui::ui_wants_keyboard(ui);
    Keys k{std::move(keys)};
    if (last_keys_to_game) handle_panel_keys(w, view, p, k.state());
    draw_control_panel(w, view, p);
    eng::ui::ui_end(ui);
  }
  // Hover, press, release, and a frame after (while the button is down on a panel, ImGui holds that frame's keys).
  void click(float x, float y) {
    frame(x, y, false);
    frame(x, y, true);
    frame(x, y, false);
    frame(x, y, false);
  }
  // The ImGui item under (x, y) after hovering it a frame (0: none).
  ImGuiID hovered(float x, float y) {
    frame(x, y, false);
    frame(x, y, false);
    ImGui::SetCurrentContext(ui.context());
    return GImGui->HoveredIdPreviousFrame;
  }
  // The panel's window (ImGui's record of it: position and size).
  ImGuiWindow* panel() {
    ImGui::SetCurrentContext(ui.context());
    return ImGui::FindWindowByName("Controls (Tab)");
  }
};

// Tab with the panel focused (clicked on its background): ImGui would move the focus to the next field that takes
// text (the seed's) and the field would hold the keyboard, so the next P, J or Tab went into it. The panel's
// widgets take no Tab focus: every Tab and the game keys after it stay the game's, Tab toggling the panel each time.
// The control: a click INTO the seed field does take the keyboard (the game keys go to the field, as they should).
TEST(PanelKeys, TabTogglesThePanelAndNeverHandsTheKeyboardToAFieldThatWasNotClicked) {
  auto world = two_boxers();
  ASSERT_TRUE(world);
  Frames f(*world);
  f.frame(-1, -1, false);
  f.frame(-1, -1, false);
  ImGuiWindow* win = f.panel();
  ASSERT_NE(win, nullptr);
  ASSERT_GT(win->Size.y, 100.0f);
  // On the panel's background: its bottom padding, below the last line of text.
  const float bx = win->Pos.x + 0.5f * win->Size.x, by = win->Pos.y + win->Size.y - 3.0f;
  ASSERT_EQ(f.hovered(bx, by), 0u) << "the background click would hit a widget";
  f.click(bx, by);
  ImGui::SetCurrentContext(f.ui.context());
  ASSERT_EQ(GImGui->NavWindow, win) << "the click did not focus the panel";
  EXPECT_TRUE(f.last_keys_to_game);
  for (int i = 0; i < 4; ++i) {
    const bool open = f.p.open;
    f.frame(bx, by, false, {GLFW_KEY_TAB});
    EXPECT_TRUE(f.last_keys_to_game) << "Tab " << i;
    EXPECT_EQ(f.p.open, !open) << "Tab " << i << " did not toggle the panel";
    for (int k = 0; k < 3; ++k) {
      f.frame(bx, by, false);
      EXPECT_TRUE(f.last_keys_to_game) << "after Tab " << i << ", frame " << k << ": a field took the keyboard";
    }
    const bool paused = f.p.paused;
    f.frame(bx, by, false, {GLFW_KEY_P}, {'p'});
    EXPECT_EQ(f.p.paused, !paused) << "P after Tab " << i << " was swallowed";
    // The panel is open again after every second Tab: refocus it as the player would (clicked again).
    if (f.p.open) f.click(bx, by);
  }
  EXPECT_EQ(f.p.seed, 1);  // nothing typed into the seed

  // The control: the seed field clicked takes the keyboard, and what is typed goes there, not to the game.
  ASSERT_TRUE(f.p.open);
  f.frame(-1, -1, false);
  win = f.panel();
  const ImGuiID seed = win->GetID("seed");
  float sx = -1, sy = -1;
  for (float y = win->Pos.y + 20.0f; y < win->Pos.y + win->Size.y && sx < 0; y += 4.0f)
    if (f.hovered(win->Pos.x + 30.0f, y) == seed) sx = win->Pos.x + 30.0f, sy = y;
  ASSERT_GE(sx, 0.0f) << "the seed field was not found on the panel";
  f.click(sx, sy);
  f.frame(sx, sy, false);
  EXPECT_FALSE(f.last_keys_to_game) << "a clicked text field did not take the keyboard";
  const bool paused = f.p.paused;
  f.frame(sx, sy, false, {GLFW_KEY_P}, {'p'});
  EXPECT_EQ(f.p.paused, paused) << "P went to the game while the seed field had the keyboard";
}

}  // namespace
}  // namespace boxing
