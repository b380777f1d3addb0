#pragma once
// The match's footwork as measured (issue 62), independently of how the steps come about: each tick after the
// referee (match_after_step) from the physics alone: the feet's contacts and positions, the pelvis, the legs' geoms.
//   steps: a foot off the ground (no ground contact) for min_air s or more lands on a crate top again min_travel m or
//     more from where it lifted, the boxer standing (in guard or stunned) at the lift and the landing;
//   path_m: the pelvis's path on the floor plane while standing, sampled every sample_every s (no jitter), not
//     across a teleport;
//   time_in_range_s: standing and in punching range (fighter_view.h in_range);
//   legs_through_s: standing with the two legs' geoms (thigh, shank, foot) overlapping by more than legs_through m
//     (game/segment_distance.h: capsules exactly, a foot's box as its inscribed capsule);
//   ring_exits: a foot going out of the ring's inside square (the transition), and of those within exit_after_hit s
//     of a landed hit on the boxer;
//   teleports: a boxer's pelvis jumping between two ticks: moved more than teleport_jump m farther than its velocity
//     carried it (a pose set directly; a physical body at 300 m/s would be needed for that in one 1/600 s tick).
// The ropes' contact time is the ropes' own (RingRopesState::contact_s, game/ring_ropes.h).
#include <Eigen/Core>
#include <array>
#include <vector>

namespace boxing {

struct World;

struct FootworkMetricsTuning {
  double min_air = 0.08;        // s off the ground for a step
  double min_travel = 0.05;     // m between lift and landing for a step
  double sample_every = 0.05;   // s between the path's samples
  double legs_through = 0.01;   // m of overlap between the legs counted
  double exit_after_hit = 2.0;  // s after a landed hit a ring exit is the hit's
  double teleport_jump = 0.05;  // m a pelvis moved in one tick beyond what its velocity explains
};

struct FootworkMetrics {
  int steps = 0;
  double standing_s = 0.0, path_m = 0.0, time_in_range_s = 0.0, legs_through_s = 0.0;
  int ring_exits = 0, ring_exits_after_hit = 0;
  int teleports = 0;  // of Match::teleports, this boxer's
  // The feet's state: off the ground since lift_t from lift_at (standing then), outside the ring.
  std::array<bool, 2> airborne{}, lift_standing{};
  std::array<double, 2> lift_t{};
  std::array<Eigen::Vector2d, 2> lift_at{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  bool outside = false;
  bool have_sample = false;  // last_sample is a standing pelvis since the last teleport
  Eigen::Vector3d last_pelvis = Eigen::Vector3d::Zero();  // the last tick's (the teleport detector)
  Eigen::Vector2d last_sample = Eigen::Vector2d::Zero();
  std::vector<int> leg_geoms[2];  // listed at setup (no allocation in the step)
};

// At the match's setup: each boxer's leg geoms listed.
void footwork_setup(World& w);
// Each tick after the referee: the metrics above, and each get-up's count_distance_min.
void measure_footwork(World& w);
// The deepest overlap between boxer k's two legs now (m, > 0: through each other; very negative before setup).
double legs_overlap(const World& w, int k);

}  // namespace boxing
