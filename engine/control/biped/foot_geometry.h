#pragma once
// Points of the foot in the foot frame (origin at the ankle, +X toward the toe, metres), from the content's foot
// box (half extents 0.13 x 0.05 x 0.04 at (0.05, 0, -0.04)).
#include <Eigen/Core>

namespace eng::control {

struct FootGeometry {
  Eigen::Vector3d centre{0.05, 0.0, 0.0};   // middle of the sole, at ankle height (support centres, footholds)
  Eigen::Vector3d heel{-0.08, 0.0, -0.08};  // the sole's ends: the sole's lowest point is one of them
  Eigen::Vector3d toe{0.18, 0.0, -0.08};
  // The sole's centre (on the sole) from the ankle, in the foot frame of a flat foot.
  Eigen::Vector3d sole_offset() const { return {centre.x(), centre.y(), heel.z()}; }
};

}  // namespace eng::control
