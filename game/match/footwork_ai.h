#pragma once
// The AI's footwork in the ring (footwork.h's moves): it keeps facing the opponent (pivots), steps in when out of
// range, out when crowded or hurt, off the line after its punches, circles at range, cuts off an opponent on the
// ropes, keeps inside the ring, and walks to a neutral corner when the referee sends it there (Match's go_to).
#include <Eigen/Core>

namespace boxing {

struct World;

struct FootworkAiTuning {
  bool on = true;           // off: the AI boxers stand where they are (the referee's errands still walk them)
  double band_in = 0.10;    // m inside reach: the nearest the AI wants to stand while trading (steps back inside it)
  double band_out = 0.02;   // m past reach: the farthest (steps in beyond it)
  double hurt_gap = 0.45;   // m past reach a hurt boxer keeps (backs away, circles)
  double hurt_below = 0.65; // consciousness under this: hurt
  double face_within = 0.30;  // rad: facing the opponent this well needs no pivot; a step turns at most max_turn ...
  double pivot_beyond = 0.45;  // rad: ... and farther off than this, a pivot comes first
  double circle_rate = 0.5;    // lateral moves per second at range (Poisson), the style's footwork
  double exit_share = 0.5;    // after a punch, the share that steps out or off the line at once ...
  double exit_within = 0.3;   // s ... decided this soon after the punch ended
  double pause_min = 0.1, pause_max = 0.6;   // s between moves at range
  double stunned_pause_scale = 2.0;  // a stunned boxer's pauses between moves x this ...
  double stunned_steps_above = 0.45;  // ... and no moves at all below this consciousness
  double ring_margin = 0.8;   // m, the stance's centre keeps this far inside the ring's edge ...
  double off_ropes = 0.15;    // m: pushed this far past it, the next move is the one back in (before any other)
  double corner_inset = 0.6;  // m, a neutral corner's spot inside the ropes' corner (each way)
  double at_corner = 0.35;    // m: there
  // m, pelvis to pelvis: while the other is down, closer than this (a get-up carries the pelvis up to about a metre
  // toward him) the standing boxer steps away from him first, corner or not (the count's 2 m, with room for a step)
  double count_keep_away = 3.2;
  double max_still = 1.5;     // s without a move, then one (a circle where nothing else is called for)
};

// Boxer k's footwork decision this tick (an AI boxer, standing, its walk free). True: a move was asked for.
bool footwork_ai_tick(World& w, int k, bool free, bool just_punched);
// No move for FootworkAiTuning::max_still: the feet go before the next punch (a busy puncher stood planted, 19 steps
// a minute at an attack rate of 1.6 a second).
bool footwork_restless(const World& w, int k);
// The ring's inside as the AI reads it, half its size about its centre (m): the ropes' square (its apron outside
// them is not the ring), or the platform's where there are no ropes.
Eigen::Vector2d ring_half_size(const World& w);
// A neutral corner for the boxer k standing while the other is down: the ring corner farthest from the downed one.
Eigen::Vector2d neutral_corner(const World& w, int standing);

}  // namespace boxing
