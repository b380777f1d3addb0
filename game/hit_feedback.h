#pragma once
// Hits a player can read (issue 64, item 4), in the window only: nothing here feeds back into the simulation.
// - Sparks: a ring of short streaks that leaves the contact point across the hit's normal, sized and counted by the
//   hit's impulse. It starts outside the contact (spark_inner_m) and moves away, so it frames the head instead of
//   covering it (the old flash was one yellow disc up to 48 px wide drawn over the head).
// - Hit-stop: a heavy hit holds the simulation for a moment of real time, up to 60 ms (fighting games hold 50-200 ms,
//   Street Fighter's light hits about 11 frames at 60 Hz; 60 ms is the bound), longer for a bigger impulse.
// - Camera shake: a heavy hit shakes the camera a few centimetres, decaying over shake_s of simulated time.
// Driven by the interaction's hit flashes (Interaction::Flash: time, point, normal, approach speed, impulse).
#include <Eigen/Core>
#include <vector>

#include "engine/render/frame.h"
#include "game/interaction/interaction.h"

namespace boxing {

struct HitFeedbackTuning {
  // A hit's weight: its first step's normal impulse over heavy_impulse or its closing speed over heavy_speed, whichever
  // is more. The speed is there because a punch's impulse builds over several steps, so its first step alone
  // understates a hard punch (docs/decisions/readable-hits.md). A weight of 1 or more is a heavy hit.
  double heavy_impulse = 4.0;    // N s
  double heavy_speed = 6.5;      // m/s (the fight's landed fists: median 6.9 m/s)
  double max_stop_s = 0.06;      // s of real time
  double min_stop_s = 0.02;      // at weight 1, growing stop_per_weight per unit of weight past it
  double stop_per_weight = 0.04;
  double shake_per_weight = 0.02;  // m
  double max_shake_m = 0.04;
  double shake_s = 0.3;           // s of simulated time
  double spark_s = 0.3;           // s of simulated time a spark ring lives
  double spark_inner_m = 0.07;    // the ring's radius at the hit: clear of the contact
  double spark_reach_per_impulse = 0.015;  // m the ring grows per N s (at most spark_reach_max_m)
  double spark_reach_max_m = 0.25;
  int sparks_min = 6, sparks_max = 14;
  double spark_dot_px = 4.0, spark_dot_px_per_impulse = 0.4, spark_dot_max_px = 9.0;  // each spark's head
  double min_impulse = 0.3;       // N s: lighter touches show nothing
};

// The hit's weight (1: heavy; HitFeedbackTuning::heavy_*).
double hit_weight(const Interaction::Flash& fl, const HitFeedbackTuning& t = {});
// Real seconds a hit holds the simulation (0: not a heavy hit); never more than max_stop_s.
double hit_stop_seconds(const Interaction::Flash& fl, const HitFeedbackTuning& t = {});

// The camera's offset this simulated instant from the recent heavy hits (a decaying shake, zero after shake_s).
glm::vec3 camera_shake(const Interaction& in, double now, const HitFeedbackTuning& t = {});

// The sparks of one hit at `now` (none outside its life or under min_impulse): a streak and a dot at its head each,
// appended to the frame's debug lines and points.
void hit_sparks(const Interaction::Flash& fl, double now, eng::render::FrameDesc& f, const HitFeedbackTuning& t = {});

}  // namespace boxing
