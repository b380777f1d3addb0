#include "game/match/stamina.h"

#include <algorithm>
#include <cstdio>

namespace boxing {

double stamina_clip_cost(const Stamina& s, const StaminaTuning& t, bool punch, int punches, bool defence, double now) {
  if (punch) {
    const double flurry = now - s.last_punch < t.flurry_window ? t.flurry_factor : 1.0;
    return t.punch_cost * std::max(1, punches) * flurry;
  }
  return defence ? t.defence_cost : 0.0;
}

void stamina_spend(Stamina& s, const StaminaTuning& t, double cost, bool punch, double now) {
  if (punch) s.last_punch = now;
  if (cost <= 0.0) return;
  const double before = s.level;
  s.level = std::max(0.0, s.level - cost);
  s.spent += before - s.level;
  s.lowest = std::min(s.lowest, s.level);
  if (s.level < t.punch_cost) s.gassed = true;
}

void stamina_recover(Stamina& s, const StaminaTuning& t, bool punching, double dt) {
  if (!punching && s.level < 1.0) {
    const double before = s.level;
    s.level = std::min(1.0, s.level + (s.gassed ? t.spent_recover_rate : t.recover_rate) * dt);
    s.recovered += s.level - before;
  }
  if (s.gassed && s.level >= t.rested_at) s.gassed = false;
}

namespace {
// Linear from `at0` (level 0) to 1 (level effect_below); exactly 1 at and above it, so that a boxer in the band
// fights bit for bit as without stamina (x * 1.0 == x).
double below_band(const Stamina& s, const StaminaTuning& t, double at0) {
  if (s.level >= t.effect_below || t.effect_below <= 0.0) return 1.0;
  return at0 + (1.0 - at0) * std::clamp(s.level / t.effect_below, 0.0, 1.0);
}
}  // namespace

double stamina_speed(const Stamina& s, const StaminaTuning& t) { return below_band(s, t, t.min_speed); }
double stamina_power(const Stamina& s, const StaminaTuning& t) { return below_band(s, t, t.min_power); }

bool stamina_can_punch(const Stamina& s) { return !s.gassed; }

std::string stamina_rule_text(const StaminaTuning& t) {
  char line[256];
  std::snprintf(line, sizeof line,
                "punch -%.2f (x%.0f within %.1f s of the last), slip/duck/block -%.2f, step -%.2f; +%.2f/s while no "
                "punch plays; below %.2f punches slow (x%.2f at 0) and weaken (x%.2f at 0); under %.2f: spent, punch keys "
                "refused and +%.2f/s until %.2f",
                t.punch_cost, t.flurry_factor, t.flurry_window, t.defence_cost, t.move_cost, t.recover_rate,
                t.effect_below, t.min_speed, t.min_power, t.punch_cost, t.spent_recover_rate, t.rested_at);
  return line;
}

}  // namespace boxing
