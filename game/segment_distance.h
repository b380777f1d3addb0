#pragma once
// Closest points between two 3D segments (closed form: Ericson, Real-Time Collision Detection, 2005, 5.1.9), and a
// geom as a swept sphere on a segment, for the distance between two bodies' shapes without the collision pipeline
// (the match's legs_through_s, game/match/footwork_metrics.h).
#include <Eigen/Core>

namespace eng::physics {
struct Shape;
struct Pose;
}  // namespace eng::physics

namespace boxing {

struct SegmentClosest {
  double distance = 0.0;  // m, between the two closest points
  double s = 0.0, t = 0.0;  // their parameters on p0-p1 and q0-q1, in [0, 1]
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), q = Eigen::Vector3d::Zero();
};

// Segments p0-p1 and q0-q1 (either may be a point).
SegmentClosest segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                                const Eigen::Vector3d& q1);

// A geom as a segment swept by a sphere: a capsule exactly, a sphere as a point, a box as its inscribed capsule
// (along its longest axis, the radius its smaller other half extent: an underestimate of the box).
struct SweptSegment {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  double radius = 0.0;
};
SweptSegment swept_segment(const eng::physics::Shape& s, const eng::physics::Pose& x);
// Their surfaces' distance (m; < 0: overlapping by that much).
double swept_distance(const SweptSegment& u, const SweptSegment& v);

}  // namespace boxing
