#include "game/control_panel.h"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <optional>

#include "game/interaction/interaction.h"
#include "game/match/match.h"
#include "game/world.h"
#include "imgui.h"

namespace boxing {

namespace {

constexpr const char* kSpaces[] = {"world", "person", "parent"};
constexpr double kScales[] = {1.0, 0.5, 0.25, 0.1};
constexpr const char* kScaleNames[] = {"1x", "1/2", "1/4", "1/10"};

int space_index(const Boxer& b) {
  const char* name = servo_space_name(b.settings.space);
  for (int i = 0; i < 3; ++i)
    if (std::string(name) == kSpaces[i]) return i;
  return 0;
}

// A slider whose value goes out once the drag on it ends (a set event per release, not one per frame of the drag).
std::optional<double> edited_slider(const char* label, double value, float lo, float hi, const char* format,
                                    float width) {
  float v = float(value);
  ImGui::SetNextItemWidth(width);
  ImGui::SliderFloat(label, &v, lo, hi, format);
  if (!ImGui::IsItemDeactivatedAfterEdit()) return std::nullopt;
  return double(v);
}

InputEvent set_event(int boxer) {
  InputEvent e;
  e.kind = InputKind::Set;
  e.boxer = boxer;
  return e;
}

}  // namespace

double time_scale(const PanelState& p) { return kScales[p.slow]; }
const char* time_scale_name(const PanelState& p) { return kScaleNames[p.slow]; }

void draw_control_panel(World& w, SceneView& view, PanelState& p) {
  const ImGuiIO& io = ImGui::GetIO();
  const float width = 340.0f;
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - width - 10.0f, 10.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.7f);
  ImGui::SetNextWindowCollapsed(!p.open, ImGuiCond_Always);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoFocusOnAppearing;
  // Open = not collapsed (Tab, or the title bar's arrow). Not Begin's return value: the window fits its height every
  // frame (size y 0, ImGuiCond_Always), and a window auto-fitting still lays its items out collapsed, so Begin
  // returned true and the panel reopened the frame after Tab closed it.
  ImGui::Begin("Controls (Tab)", nullptr, flags);
  p.open = !ImGui::IsWindowCollapsed();
  if (!p.open) {
    ImGui::End();
    return;
  }
  // No Tab focus on the panel's widgets: Tab is the game's (the panel's toggle), and with the panel focused (any
  // click on it) ImGui's Tab moved the focus into the seed's text field, which then held the keyboard, so the game's
  // keys went into it until the player clicked elsewhere. A field takes the keyboard only when clicked.
  ImGui::PushAllowKeyboardFocus(false);
  for (const Boxer& b : w.boxers) {
    if (b.limp) continue;
    ImGui::PushID(b.index);
    char title[64];
    std::snprintf(title, sizeof title, "Boxer %d", b.index);
    ImGui::TextColored(ImVec4(0.35f + 0.8f * b.team_color.x(), 0.35f + 0.8f * b.team_color.y(),
                              0.35f + 0.8f * b.team_color.z(), 1.0f),
                       "%s", title);
    int space = space_index(b);
    ImGui::SetNextItemWidth(100);
    if (ImGui::Combo("servo", &space, kSpaces, 3)) {
      InputEvent e = set_event(b.index);
      e.servo = kSpaces[space];
      interaction_submit(w, e);
    }
    ImGui::SameLine();
    int qp = b.settings.balance_qp ? 0 : 1;
    bool changed = ImGui::RadioButton("QP", &qp, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("PD", &qp, 1);
    if (changed) {
      InputEvent e = set_event(b.index);
      e.balance = qp == 0 ? "qp" : "pd";
      interaction_submit(w, e);
    }
    if (auto wn = edited_slider("gain wn", b.settings.gains.omega_n, 5.0f, 40.0f, "%.1f rad/s", 150)) {
      InputEvent e = set_event(b.index);
      e.omega_n = *wn;
      interaction_submit(w, e);
    }
    bool root = b.settings.root_params.enabled;
    if (ImGui::Checkbox("root spring", &root)) {
      InputEvent e = set_event(b.index);
      e.root_spring = root ? "on" : "off";
      interaction_submit(w, e);
    }
    ImGui::SameLine();
    if (auto limit = edited_slider("##limit", b.settings.root_params.max_torque, 0.0f, 1000.0f, "%.0f N m", 110)) {
      InputEvent e = set_event(b.index);
      e.root_limit = *limit;
      interaction_submit(w, e);
    }
    if (auto c = edited_slider("conscious", b.ctl.root_spring.consciousness(), 0.0f, 1.0f, "%.2f", 150)) {
      InputEvent e = set_event(b.index);
      e.consciousness = *c;
      interaction_submit(w, e);
    }
    if (w.match->active && b.index < 2) {
      int player = w.match->fighter[b.index].player ? 1 : 0;
      bool switched = ImGui::RadioButton("AI", &player, 0);
      ImGui::SameLine();
      switched |= ImGui::RadioButton("player", &player, 1);
      if (switched) {
        InputEvent e = set_event(b.index);
        e.control = player ? "player" : "ai";
        interaction_submit(w, e);
      }
    }
    ImGui::Separator();
    ImGui::PopID();
  }
  ImGui::Checkbox("ghost (G)", &view.ghost);
  ImGui::Checkbox("contacts (1)", &view.debug.contacts);
  ImGui::SameLine(170);
  ImGui::Checkbox("com (2)", &view.debug.com);
  ImGui::Checkbox("support (3)", &view.debug.support);
  ImGui::SameLine(170);
  ImGui::Checkbox("capture pt (4)", &view.debug.capture_point);
  ImGui::Checkbox("hit flashes (5)", &view.debug.hits);
  ImGui::Separator();
  ImGui::Checkbox("pause (P)", &p.paused);
  ImGui::SameLine();
  if (ImGui::Button("step (.)")) p.step_once = true;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70);
  ImGui::Combo("speed", &p.slow, kScaleNames, 4);
  ImGui::SetNextItemWidth(90);
  ImGui::InputInt("seed", &p.seed);
  if (p.seed < 1) p.seed = 1;
  ImGui::SameLine();
  if (ImGui::Button("restart (F5)")) p.restart = true;
  ImGui::TextDisabled("left-drag grabs (Shift: strong, wheel: depth)");
  ImGui::TextDisabled("T ball  Y crate  Backspace clear  F5 restart");
  ImGui::TextDisabled("F1/F2 servo  F3/F4 QP-PD  F6/F7 root spring");
  if (w.match->active) {
    ImGui::TextDisabled("fight: J jab  K cross  U/I hooks  N/M uppercuts");
    ImGui::TextDisabled("       B block  A/D slip  S duck  W/X step");
  }
  ImGui::PopAllowKeyboardFocus();
  ImGui::End();
}

void handle_panel_keys(World& w, SceneView& view, PanelState& p, const KeyState& keys) {
  auto pressed = [&](int k) { return keys.pressed(keys.ctx, k); };
  for (int k = 0; k < 2 && k < int(w.boxers.size()); ++k) {
    const Boxer& b = w.boxers[k];
    if (b.limp) continue;
    if (pressed(k == 0 ? GLFW_KEY_F1 : GLFW_KEY_F2)) {
      InputEvent e = set_event(k);
      e.servo = kSpaces[(space_index(b) + 1) % 3];
      interaction_submit(w, e);
    }
    if (pressed(k == 0 ? GLFW_KEY_F3 : GLFW_KEY_F4)) {
      InputEvent e = set_event(k);
      e.balance = b.settings.balance_qp ? "pd" : "qp";
      interaction_submit(w, e);
    }
    if (pressed(k == 0 ? GLFW_KEY_F6 : GLFW_KEY_F7)) {
      InputEvent e = set_event(k);
      e.root_spring = b.settings.root_params.enabled ? "off" : "on";
      interaction_submit(w, e);
    }
  }
  if (pressed(GLFW_KEY_1)) view.debug.contacts = !view.debug.contacts;
  if (pressed(GLFW_KEY_2)) view.debug.com = !view.debug.com;
  if (pressed(GLFW_KEY_3)) view.debug.support = !view.debug.support;
  if (pressed(GLFW_KEY_4)) view.debug.capture_point = !view.debug.capture_point;
  if (pressed(GLFW_KEY_5)) view.debug.hits = !view.debug.hits;
  if (pressed(GLFW_KEY_TAB)) p.open = !p.open;
  if (pressed(GLFW_KEY_P)) p.paused = !p.paused;
  if (pressed(GLFW_KEY_PERIOD)) p.step_once = true;
  if (pressed(GLFW_KEY_LEFT_BRACKET)) p.slow = std::min(p.slow + 1, 3);
  if (pressed(GLFW_KEY_RIGHT_BRACKET)) p.slow = std::max(p.slow - 1, 0);
  if (pressed(GLFW_KEY_F5)) p.restart = true;
}

}  // namespace boxing
