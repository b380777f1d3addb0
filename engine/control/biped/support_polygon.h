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

// How much of a move the support allows: the largest s in [0, 1] for which from + s * delta stays at least `margin`
// inside every edge of the (counter-clockwise) hull; 0 when `from` itself is not that far inside, 1 for a hull of
// fewer than three points (no area to stay in: the caller decides). The balance QP scales a com acceleration with
// it so that the centre of pressure it needs stays on the soles (ground_com_acceleration, below).
double share_inside(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector2d& from, const Eigen::Vector2d& delta,
                    double margin);

// How far the point lies outside the convex polygon (counter-clockwise hull; <= 0 inside: minus the distance to the
// nearest edge). An empty hull: +infinity.
double outside_distance(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector2d& x);

// The horizontal com acceleration the ground can give, the closest along the desired one: a com at height z over
// the contacts accelerating by acc needs its centre of pressure at p = com - z acc_xy / (g + acc_z) (the linear
// inverted pendulum's ZMP, Kajita et al. 2003; Kudoh sec. 2.3, eq. 2.39). acc's horizontal part is scaled down until
// p lies `margin` inside the hull. Unchanged when the hull has no area.
// Where the com's own projection is not `margin` inside, no acceleration is free (p = com there) and what the com
// task asks is the caller's to buy (the root assist). It is handed over in a ramp, none of it at `margin` inside, all
// of it `ramp` further out (0: all at once): handed over whole at the margin, the demand jumps from the soles' ~0 to
// the com task's full acceleration in one tick, and the root assist comes in bursts as a rolled foot's few contacts
// shrink the hull under the com (docs/decisions/com-acceleration-in-support.md).
Eigen::Vector3d ground_com_acceleration(const std::vector<Eigen::Vector2d>& hull, const Eigen::Vector3d& com,
                                        const Eigen::Vector3d& acc, double z, double margin, double ramp = 0.0,
                                        double g = 9.81);

}  // namespace eng::control
