#pragma once
// The arena: a platform of uneven wooden crates the two boxers stand on, laid out from the seed.
// Plain data; the game turns it into static physics geoms and render instances.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "engine/control/biped/ground.h"

namespace boxing {

struct Crate {
  Eigen::Vector3d center;
  Eigen::Vector3d half_extents;
  Eigen::Vector3f color;  // linear RGB, a wood tone
};

// Where a boxer stands: pelvis position over the stance, heading (yaw, rad; 0 = facing +X), and the heights of
// the tops under the lead (left) and rear (right) foot.
struct Stance {
  Eigen::Vector2d position;
  double heading = 0.0;
  double lead_top = 0.0;
  double rear_top = 0.0;
};

// The match's ring (make_ring): the inside square's crates, a one-cell apron of crates outside the ropes, a post at
// each corner and three ropes a side (game/ring_ropes.h pushes a boxer past a rope line back in). Centred on the
// origin, the ropes' lines at x, y = +-half_inside. Corners: [0] red (boxer 0's, -X -Y), [1] blue (boxer 1's, +X +Y),
// [2] and [3] the neutral corners (-X +Y, +X -Y), each the inside corner of the ropes (floor plane, m).
struct Ring {
  bool present = false;
  double half_inside = 0.0;  // m, half the inside square's side: the ropes' lines
  double top_mean = 0.0;     // m, the inside crates' mean top (the ropes' heights are above it)
  std::array<Eigen::Vector2d, 4> corners{};
  std::array<double, 3> rope_heights{0.45, 0.85, 1.25};  // m above top_mean, bottom to top
  double post_half = 0.06;    // m, a post's half width (its centre on the corner, drawn and collided)
  double post_height = 1.35;  // m above top_mean
  static constexpr int kRed = 0, kBlue = 1, kNeutral0 = 2, kNeutral1 = 3;
  // Inside the ropes' square (floor plane), less margin.
  bool inside(const Eigen::Vector2d& p, double margin = 0.0) const {
    return std::abs(p.x()) <= half_inside - margin && std::abs(p.y()) <= half_inside - margin;
  }
};

// The crates bucketed by the grid cells their footprints cover (index_crates), so a height query reads the few
// crates of one cell instead of all of them (the ring has 170; footholds and stances ask thousands of times a second).
struct CrateIndex {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  int nx = 0, ny = 0;
  size_t indexed = 0;        // the crate count it was built for (another count: top_at scans every crate)
  std::vector<int> first;    // per cell (x-major), its run in `items`: [first[c], first[c + 1])
  std::vector<int> items;    // crate indices
};

struct Arena {
  std::vector<Crate> crates;
  std::array<Stance, 2> stances;
  double cell = 0.5;  // crate footprint (m)
  Ring ring;          // the match's (present only from make_ring)
  CrateIndex index;   // index_crates; rebuilt after the crates change
  // Height of the crate top under the world point (x, y); 0 (the floor) outside the platform.
  double top_at(double x, double y) const;
};

// Builds a.index over a.crates (make_arena and make_ring call it; call it again after changing the crates).
void index_crates(Arena& a);

// A top lower than this is the floor around the platform (Arena::top_at reads 0 there; every crate's top is 0.14 m
// or more: 0.20-0.44, less up to 6 cm where make_arena sets the feet's step).
inline constexpr double kFloorTop = 0.05;  // m

// Columns of one or two stacked crates on a grid; the two cells under each boxer's feet differ by at least
// min_step metres so every boxer stands with one foot higher than the other.
// The arena as the biped layer's height query (footholds, leg fitting); the arena must outlive it.
inline eng::control::GroundHeight ground_of(const Arena& a) {
  return {&a, [](const void* c, double x, double y) { return static_cast<const Arena*>(c)->top_at(x, y); }};
}

// flat: every crate 0.30 m high (the papers' level floor, for like-for-like push comparisons; --flat).
Arena make_arena(uint64_t seed, double min_step = 0.10, double separation = 1.20, bool flat = false);
// A stance at a pelvis position and heading: the tops under its lead and rear feet read from the arena.
Stance stance_at(const Arena& a, const Eigen::Vector2d& position, double heading);

// Stance geometry shared by the arena layout and the boxer placement (orthodox stance, facing +X at heading 0):
// the lead (left) foot is ahead and to the left of the pelvis, the rear foot behind and to the right.
inline constexpr double kStanceHalfLength = 0.20;  // m along the heading
inline constexpr double kStanceHalfWidth = 0.12;   // m sideways
inline constexpr double kBoxerSeparation = 1.20;   // pelvis to pelvis (m)
// The match's: a straight punch reaches the other's head at full extension (the glove's centre 0.74 m ahead of the
// chest; at 1.20 m it stopped 0.2 m short, in the guard). The boxers' steps barely carry them (the clips' quick
// shuffles lift off, but the pressed sole drags: a tenth of the clip's travel), so the match starts at fighting distance.
inline constexpr double kFightSeparation = 0.95;
// The ring's marks: the boxers start out of reach (issue 62: they step in on their own feet), 2.8 m pelvis to pelvis,
// and the step between the feet at a mark smaller than the plain arena's (the ring's tops vary by 8 cm at most).
inline constexpr double kRingSeparation = 2.8;
inline constexpr double kRingMinStep = 0.05;

// The match's ring (Ring): 10 x 10 cells inside (5 m square), crate tops 0.30 +- 0.04 m (neighbours differ by 8 cm at
// most), an apron of one cell around outside the ropes, the boxers' marks `separation` apart along X (pelvis to
// pelvis), the two cells under each boxer's feet differing by min_step + 2 cm as in make_arena.
Arena make_ring(uint64_t seed, double min_step = kRingMinStep, double separation = kRingSeparation);

}  // namespace boxing
