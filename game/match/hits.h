#pragma once
// Punches and hits (match.h steps 1-3): a punch starting opens an event and chooses its target (the opening the guard
// covers least, best_opening); the solver's hit events between its striking glove and the opponent make it landed or
// blocked; a landed punch's impulse over the impact window becomes damage, then the reaction or a knockdown.
namespace boxing {

struct World;

// Punches starting this tick (clip changes): events opened, targets chosen; started[k]: the punch boxer k started
// (nullptr: none), for the other boxer's AI.
void track_punches(World& w, const char* started[2]);
// The striking glove's fastest speed over each punch now playing (PunchEvent::peak_speed).
void track_peak_speed(World& w);
// The solver's hit events: a punch's striking glove on the opponent; landed punches' impulses and their landing.
void read_hits(World& w);
// Balance steps started within fall_after_hit_window of a landed hit on the boxer (balance_steps_after_hit).
void count_balance_steps_after_hit(World& w);

}  // namespace boxing
