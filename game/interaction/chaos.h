#pragma once
// Chaos (--chaos RATE): seeded random input events at RATE per second through the hands' path (interaction.h): drags
// of random bones with random strength, chest pushes, thrown beach balls and crates, in any scenario. And the
// simulation's health, measured every step whatever the input (the report's `health` block): non-finite steps, the
// fastest boxer body, bodies under the floor or inside a crate, the deepest contact. A soak (scripts/soak) runs
// chaos for a long time over seeds and checks the health.
#include <nlohmann/json.hpp>

#include "game/health.h"
#include "game/rng.h"

namespace boxing {

struct World;

struct Chaos {
  double rate = 0.0;  // events per second (0: off)
  Rng rng{0};
  int events = 0;
};


// Seeds the stream (options.seed) and the rate (options.chaos).
void chaos_setup(World& w);
// Start of a step, before the due events are applied: maybe one random event, queued for this step.
void chaos_begin_step(World& w);
// After the step: the health measurements.
void health_after_step(World& w);
nlohmann::json health_report(const World& w);

}  // namespace boxing
