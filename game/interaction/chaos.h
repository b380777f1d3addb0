#pragma once
// Chaos (--chaos RATE): seeded random input events at RATE per second through the hands' path (interaction.h): drags
// of random bones with random strength, chest pushes, thrown beach balls and crates, in any scenario. And the
// simulation's health, measured every step whatever the input (the report's `health` block): non-finite steps, the
// fastest boxer body, bodies under the floor or inside a crate, the deepest contact. A soak (scripts/soak) runs
// chaos for a long time over seeds and checks the health.
#include <nlohmann/json.hpp>

#include "game/rng.h"

namespace boxing {

struct World;

struct Chaos {
  double rate = 0.0;  // events per second (0: off)
  Rng rng{0};
  int events = 0;
};

struct Health {
  long non_finite_steps = 0;            // steps after which a coordinate or velocity was not finite
  double max_body_speed = 0.0;          // m/s, over the boxers' bodies
  double max_object_speed = 0.0;        // m/s, over thrown objects from 0.1 s after their throw
  long bodies_below_floor = 0;          // body-steps with a body's centre under the floor or inside a crate (> 2 cm)
  double max_penetration = 0.0;         // m, the deepest contact
  double worst_speed_at = -1.0;         // s, when max_body_speed was seen
  int worst_speed_boxer = -1, worst_speed_bone = -1;  // ... and whose body (for tracing a soak's outlier)
  double crates_top = -1.0;             // m, the highest crate top (a body centre above it is in no crate)
};

// Seeds the stream (options.seed) and the rate (options.chaos).
void chaos_setup(World& w);
// Start of a step, before the due events are applied: maybe one random event, queued for this step.
void chaos_begin_step(World& w);
// After the step: the health measurements.
void health_after_step(World& w);
nlohmann::json health_report(const World& w);

}  // namespace boxing
