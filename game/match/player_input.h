#pragma once
// Every press accounted for (issue 65, item 1). A fight key's press (match_command) is, at once, one of:
//   * free: the boxer stands in guard with nothing under way: its motion starts at this tick's control, so the
//     physics tick after the press already moves toward it (a punch enters its clip by GraphWalker::force_clip, a
//     short blend from the guard's pose, instead of waiting for the graph's next transition point: up to a guard
//     loop, 0.6 s, before);
//   * buffered: something is under way (a punch, a slip, a step): the press waits, at most PlayerInputTuning::buffer
//     of them, and starts as soon as the boxer is back in guard, in the order pressed;
//   * refused, with a reason the HUD shows by the boxer's plate for notice_seconds: "tired" (stamina spent,
//     stamina.h), "hurt" (a hit's reaction plays), "down" (falling, down or getting up), "busy" (the buffer is full),
//     "rest" (between rounds), "over" (the bout is over), "off balance" (a step the balance cannot take now).
// A buffered press that can no longer start (the boxer went down, was hit, got tired) is refused then, with the
// reason. The log (Match::presses) is the report's match.player_inputs.
#include <array>
#include <cstdint>
#include <vector>

namespace boxing {

struct World;
enum class FightCommand : uint8_t;

struct PlayerInputTuning {
  // Presses kept while something is under way: two, a one-two pressed during a jab. More is mashing: refused
  // ("busy"), visibly, where the old four-deep queue took 64 of 96 mashed presses and dropped the rest unseen.
  int buffer = 2;
  double notice_seconds = 1.0;  // s the refusal's reason stays on the HUD
};

enum class PressWait : uint8_t { Free, Buffered };

struct PlayerPress {
  double t_pressed = 0.0;  // s, the match clock when the press reached the game
  FightCommand action{};
  int boxer = 0;
  PressWait waited = PressWait::Free;
  // s: the end of the physics tick whose control first drove the motion (the press's tick + 1/240 when free);
  // < 0: not started.
  double t_started = -1.0;
  const char* refused = nullptr;  // why it was not taken (see above); nullptr: started or still waiting
};

// A boxer's waiting presses (indices into Match::presses, oldest first) and the HUD's last refusal.
struct PlayerQueue {
  static constexpr int kMax = 3;  // one free press being started this tick + up to two buffered
  std::array<int, kMax> press{};
  int queued = 0;
  const char* notice = nullptr;  // the last refusal's reason
  double notice_at = -1e9;       // s
};

// A key pressed for boxer k: logged, then started, buffered or refused (match_command calls it).
void player_press(World& w, int k, FightCommand c);
// Before control, each tick, for a player's boxer: the oldest waiting press starts if the boxer is free (one a
// tick), or is refused if it can no longer start.
void player_take_input(World& w, int k);
// The HUD's line for boxer k: the last refusal's reason while it is fresh ("" otherwise).
const char* player_notice(const World& w, int k);

}  // namespace boxing
