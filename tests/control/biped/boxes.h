#pragma once
// Test terrain for the biped layer: axis-aligned boxes on a floor at z = 0; the height under (x, y) is the highest
// top whose footprint holds the point (edges included), the same rule as the game's crates (game/arena.cpp).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/control/biped/ground.h"

namespace control_test {

struct Box {
  Eigen::Vector3d center, half_extents;
};

struct Boxes {
  std::vector<Box> boxes;
  double operator()(double x, double y) const {
    double top = 0.0;
    for (const Box& c : boxes)
      if (std::abs(x - c.center.x()) <= c.half_extents.x() && std::abs(y - c.center.y()) <= c.half_extents.y())
        top = std::max(top, c.center.z() + c.half_extents.z());
    return top;
  }
  eng::control::GroundHeight ground() const { return eng::control::GroundHeight::of(*this); }
};

// Two crates side by side along X with a 1.2 cm seam: the low one (top 0.30) at x < 0, the high one (top 0.40) at
// x > 0, both 0.488 m square (the arena's cells).
inline Boxes two_crates() {
  Boxes a;
  a.boxes.push_back(Box{{-0.25, 0.0, 0.15}, {0.244, 0.244, 0.15}});
  a.boxes.push_back(Box{{0.25, 0.0, 0.20}, {0.244, 0.244, 0.20}});
  return a;
}

}  // namespace control_test
