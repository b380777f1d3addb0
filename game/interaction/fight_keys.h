#pragma once
// THE FIGHT KEYS: the keyboard's layout for the match, as data (README: Controls; docs/guide/controls.md). The
// keyboard has two halves that never share a key, so two players can fight on one keyboard: player 1 (red) the left
// half, player 2 (blue) the right half. Alone, the player has the whole keyboard: the left hand on W A S D, the right
// on J K U I N M (or both halves' keys, whichever is at hand).
//
//   action              left half (player 1)    right half (player 2)
//   step in/out/l/r     W S A D                 Up Down Left Right
//   pivot left/right    Q E                     Right Ctrl + Left / Right
//   jab / cross         R F                     J K
//   lead / rear hook    V B                     U I
//   lead / rear upper.  Z X                     N M
//   block               Left Shift + W          Right Shift + Up
//   slip left / right   Left Shift + A / D      Right Shift + Left / Right
//   duck                Left Shift + S          Right Shift + Down
//
// Shift turns the movement keys from the feet to the head and hands (W guard up, A / D slip, S duck), so each half
// needs only its movement block, its punches and one modifier. The keys the window already uses while playing (T Y
// throws, G ghost, C camera, H debug, P pause, 1-5 debug drawing, Tab, Esc, F-keys, [ ] .) are left alone.
// A modifier counts only on its own half: Left Shift + Left arrow is a step, not a slip.
#include <string>
#include <vector>

namespace boxing {

enum class KeyHalf : uint8_t { Left, Right };
// The modifier keys held when a key went down, one bit per physical key (GLFW reports Shift, not which Shift).
enum HeldModifier : unsigned { kHeldLeftShift = 1u, kHeldRightShift = 2u, kHeldLeftCtrl = 4u, kHeldRightCtrl = 8u };

struct FightKey {
  int key;           // GLFW_KEY_*
  KeyHalf half;
  unsigned needs;    // the modifier (HeldModifier bits) it needs held; 0: none of its half's modifiers held
  const char* action;  // kKeyActions' name (input_events.h)
};

// The key's fight action with these modifiers held, or nullptr (not a fight key, or a combination that is none).
const FightKey* fight_key(int glfw_key, unsigned held);
// Every fight key (the layout above), for the tests and the README's table.
const std::vector<FightKey>& fight_keys();

// Which boxer a half of the keyboard drives: outside versus the player's (player, or red when none); in versus the
// left half red and the right half blue, except with exactly one pad connected, when the pad is blue's and the whole
// keyboard red's (gamepad.h pad_boxer).
int key_boxer(KeyHalf half, int pads_connected, bool versus, int player);

// The controls as rows for the pause menu: {action, left keys, right keys, pad}; the first row is the heading.
struct ControlsRow {
  const char* action;
  const char* left;
  const char* right;
  const char* pad;
};
const std::vector<ControlsRow>& controls_table();

// Who has which controls now, one line per boxer for the HUD's name plate and the pause menu: "LEFT KEYS",
// "RIGHT KEYS + PAD 1", "KEYS", ... (boxer 0, 1; "" for an AI boxer).
std::string controls_tag(int boxer, int pads_connected, bool versus, int player);

}  // namespace boxing
