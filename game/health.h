#pragma once
// The simulation's health, measured every step whatever the input (the report's `health` block; measured and
// reported by game/interaction/chaos.h): non-finite steps, the fastest boxer body, bodies under the floor or inside a
// crate, the deepest contact.
namespace boxing {

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

}  // namespace boxing
