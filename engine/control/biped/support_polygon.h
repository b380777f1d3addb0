#pragma once
// The support polygon: the convex hull of the ground contact points projected on the floor, and the closest
// point of it (shrunk by a margin) to a desired centre-of-mass projection. The balance QP's com target is
// clamped into it: a target outside the support cannot be reached by ground forces (Kudoh sec. 2.3: the ZMP,
// and with it the com at rest, must lie in the support area), and chasing it only tips the body over the edge.
#include <Eigen/Core>
#include <vector>

namespace eng::control {

// Convex hull of 2-D points, counter-clockwise, collinear points dropped (Andrew's monotone chain).
// 0, 1 or 2 points come back for degenerate input (empty, one point, a segment).
void convex_hull_2d(const std::vector<Eigen::Vector2d>& pts, std::vector<Eigen::Vector2d>& hull);
// The same, sorting and deduplicating `pts` in place (no copy): for a scratch list the caller refills anyway.
void convex_hull_2d_in_place(std::vector<Eigen::Vector2d>& pts, std::vector<Eigen::Vector2d>& hull);

// The point of the hull shrunk by `margin` (toward its centroid, at most halfway) closest to p; p itself when
// it is inside. For a segment or a single point: the closest point of it.
Eigen::Vector2d clamp_to_polygon(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector2d& p, double margin);

}  // namespace eng::control
