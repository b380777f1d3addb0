#include "game/interaction/fight_keys.h"

#include <GLFW/glfw3.h>

#include "game/interaction/gamepad.h"

namespace boxing {

namespace {

constexpr unsigned kLeftMods = kHeldLeftShift | kHeldLeftCtrl, kRightMods = kHeldRightShift | kHeldRightCtrl;

}  // namespace

const std::vector<FightKey>& fight_keys() {
  using H = KeyHalf;
  static const std::vector<FightKey> keys = {
      // Left half: player 1.
      {GLFW_KEY_W, H::Left, 0, "step_forward"},
      {GLFW_KEY_S, H::Left, 0, "step_back"},
      {GLFW_KEY_A, H::Left, 0, "step_left"},
      {GLFW_KEY_D, H::Left, 0, "step_right"},
      {GLFW_KEY_Q, H::Left, 0, "pivot_left"},
      {GLFW_KEY_E, H::Left, 0, "pivot_right"},
      {GLFW_KEY_R, H::Left, 0, "jab"},
      {GLFW_KEY_F, H::Left, 0, "cross"},
      {GLFW_KEY_V, H::Left, 0, "lead_hook"},
      {GLFW_KEY_B, H::Left, 0, "rear_hook"},
      {GLFW_KEY_Z, H::Left, 0, "lead_uppercut"},
      {GLFW_KEY_X, H::Left, 0, "rear_uppercut"},
      {GLFW_KEY_W, H::Left, kHeldLeftShift, "block"},
      {GLFW_KEY_A, H::Left, kHeldLeftShift, "slip_left"},
      {GLFW_KEY_D, H::Left, kHeldLeftShift, "slip_right"},
      {GLFW_KEY_S, H::Left, kHeldLeftShift, "duck"},
      // Right half: player 2.
      {GLFW_KEY_UP, H::Right, 0, "step_forward"},
      {GLFW_KEY_DOWN, H::Right, 0, "step_back"},
      {GLFW_KEY_LEFT, H::Right, 0, "step_left"},
      {GLFW_KEY_RIGHT, H::Right, 0, "step_right"},
      {GLFW_KEY_LEFT, H::Right, kHeldRightCtrl, "pivot_left"},
      {GLFW_KEY_RIGHT, H::Right, kHeldRightCtrl, "pivot_right"},
      {GLFW_KEY_J, H::Right, 0, "jab"},
      {GLFW_KEY_K, H::Right, 0, "cross"},
      {GLFW_KEY_U, H::Right, 0, "lead_hook"},
      {GLFW_KEY_I, H::Right, 0, "rear_hook"},
      {GLFW_KEY_N, H::Right, 0, "lead_uppercut"},
      {GLFW_KEY_M, H::Right, 0, "rear_uppercut"},
      {GLFW_KEY_UP, H::Right, kHeldRightShift, "block"},
      {GLFW_KEY_LEFT, H::Right, kHeldRightShift, "slip_left"},
      {GLFW_KEY_RIGHT, H::Right, kHeldRightShift, "slip_right"},
      {GLFW_KEY_DOWN, H::Right, kHeldRightShift, "duck"},
  };
  return keys;
}

const FightKey* fight_key(int glfw_key, unsigned held) {
  for (const FightKey& k : fight_keys()) {
    if (k.key != glfw_key) continue;
    // Only the key's own half's modifiers count; the combination must be exactly the one it needs.
    const unsigned own = held & (k.half == KeyHalf::Left ? kLeftMods : kRightMods);
    if (own == k.needs) return &k;
  }
  return nullptr;
}

int key_boxer(KeyHalf half, int pads_connected, bool versus, int player) {
  if (!versus) return player >= 0 ? player : 0;
  if (pads_connected == 1) return 0;
  return half == KeyHalf::Left ? 0 : 1;
}

const std::vector<ControlsRow>& controls_table() {
  static const std::vector<ControlsRow> rows = {
      {"", "LEFT KEYS (P1)", "RIGHT KEYS (P2)", "GAMEPAD"},
      {"step in out left right", "W S A D", "arrows", "left stick, d-pad"},
      {"pivot left right", "Q E", "R-Ctrl + Left Right", "L3 R3 (stick clicks)"},
      {"jab  cross", "R F", "J K", "X Y"},
      {"lead  rear hook", "V B", "U I", "A B"},
      {"lead  rear uppercut", "Z X", "N M", "LB RB"},
      {"block", "L-Shift + W", "R-Shift + Up", "LT"},
      {"slip left right", "L-Shift + A D", "R-Shift + Left Right", "right stick"},
      {"duck", "L-Shift + S", "R-Shift + Down", "RT"},
  };
  return rows;
}

std::string controls_tag(int boxer, int pads_connected, bool versus, int player) {
  std::string tag;
  if (!versus) {
    if (boxer != (player >= 0 ? player : 0)) return "";
    tag = "KEYS";
  } else if (pads_connected == 1) {
    tag = boxer == 0 ? "KEYS" : "";
  } else {
    tag = boxer == 0 ? "LEFT KEYS" : "RIGHT KEYS";
  }
  for (int rank = 0; rank < pads_connected; ++rank)
    if (pad_boxer(rank, pads_connected, versus, player) == boxer)
      tag += (tag.empty() ? "PAD " : " + PAD ") + std::to_string(rank + 1);
  return tag;
}

}  // namespace boxing
