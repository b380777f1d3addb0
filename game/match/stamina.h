#pragma once
// Stamina (issue 65, item 3): a boxer's wind, 1 fresh .. 0 spent, the same rule for both boxers (player or AI).
//   * Costs: a punch started costs punch_cost (a combination's one clip once), and flurry_factor times that when
//     it starts within flurry_window of the last punch's start (a flurry tires: what separates a masher from a boxer
//     at the AI's pace, one punch every two or three seconds); a defence (slip, duck, block) costs defence_cost, a
//     footwork move move_cost: slipping and moving cost less than punching.
//   * Recovery: recover_rate per second while no punch plays (in the rest between rounds too); spent_recover_rate
//     while spent (below).
//   * Effect: none at or above effect_below (the band a boxer fighting at the AI's pace stays in: the fight is the
//     same as without stamina); below it a punch's clip plays slower and its landed damage is smaller, both linear
//     in the level down to min_speed and min_power at 0.
//   * Spent: below punch_cost a boxer is "gassed": the player's punch keys are refused ("tired") until stamina is
//     back to rested_at, and it recovers at the slower spent_recover_rate meanwhile. A masher (a jab every 0.15 s)
//     throws a burst, then stands tired for many seconds while the other punches. A boxer at the AI's pace is
//     never spent, so neither rule touches it.
// Why these numbers: docs/decisions/stamina.md (the AI's lowest level over seeds, the masher's record).
#include <string>

namespace boxing {

struct StaminaTuning {
  double punch_cost = 0.05;     // per punch clip started (a combination's clip too)
  double flurry_window = 1.0;   // s: a punch started this soon after the last one's start ...
  double flurry_factor = 2.0;   // ... costs this many times punch_cost
  double defence_cost = 0.01;   // per slip, duck or block started
  double move_cost = 0.01;      // per footwork move started
  double recover_rate = 0.06;   // per second while no punch plays
  double spent_recover_rate = 0.02;  // ... while spent (gassed): an exhausted boxer gets its wind back slower
  double effect_below = 0.3;    // no effect at or above this level
  double min_speed = 0.3;       // a punch's clip rate at level 0 (x1 at effect_below and up)
  double min_power = 0.2;       // a landed punch's damage factor at level 0
  double rested_at = 0.5;       // a gassed boxer's punch keys work again at this level
};

struct Stamina {
  double level = 1.0;
  double lowest = 1.0;          // the lowest level so far (the report's)
  double last_punch = -1e9;     // s, the last punch's start (the flurry's)
  bool gassed = false;          // spent: punch keys refused until rested_at
  int last_clip = -1;           // the clip seen last tick (a new clip's start is what costs)
  bool was_moving = false;      // a footwork move under way last tick
  double spent = 0.0, recovered = 0.0;  // totals (the report's)
};

// What starting a clip costs at time `now` (0: none): a punch (`punches` 2 for a combination; a flurry's more), a
// defence.
double stamina_clip_cost(const Stamina& s, const StaminaTuning& t, bool punch, int punches, bool defence, double now);
// Pays `cost` at time now (punch: remembered for the flurry). Crossing below punch_cost makes the boxer gassed.
void stamina_spend(Stamina& s, const StaminaTuning& t, double cost, bool punch, double now);
// One tick of recovery: recover_rate x dt while no punch plays; the gassed boxer rested at rested_at.
void stamina_recover(Stamina& s, const StaminaTuning& t, bool punching, double dt);
// The punch's clip rate and its damage factor at this level (exactly 1 at or above effect_below).
double stamina_speed(const Stamina& s, const StaminaTuning& t);
double stamina_power(const Stamina& s, const StaminaTuning& t);
// Whether the boxer can start a punch now (not gassed).
bool stamina_can_punch(const Stamina& s);
// The rule in one line (the report's stamina_rule): "punch -0.05 (x3 within 1.0 s of the last), ...".
std::string stamina_rule_text(const StaminaTuning& t);

}  // namespace boxing
