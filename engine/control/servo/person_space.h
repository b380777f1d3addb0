#pragma once
// Egocentric world space ("person coordinates"), paper section IV: absolute world space forces the root to the
// clip's orientation ("super-balancing"); person space replaces the clip root's heading by the game's heading
// so higher-level decision making commands where the boxer faces, while the clip still commands the tilt.
// World is Z-up; the boxer faces +X at rest.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace eng::control {

// Heading (yaw about +Z, radians in (-pi, pi]) of the body's +X axis projected on the floor.
// If +X is (nearly) vertical the projection is undefined; we then fall back to the twist of the swing-twist
// decomposition of q about Z (2 atan2(q.z, q.w)), which is continuous with the projection for pure yaw.
double heading_of(const Eigen::Quaterniond& q);

// Pure yaw rotation about +Z.
Eigen::Quaterniond yaw_rotation(double yaw);

// The clip root's tilt relative to the clip's own heading: Rz(-heading_of(q)) * q (heading removed).
Eigen::Quaterniond remove_heading(const Eigen::Quaterniond& q);

// Desired root orientation in person space: Rz(heading_yaw) * remove_heading(clip_root).
// Guarantees heading_of(person_space_root(q, psi)) == psi (mod 2 pi) and keeps the clip's lean/pitch/roll.
// (Removing the heading with the same forward-axis projection that heading_of uses -- rather than the
// swing-twist twist angle, which differs from it once the body is both pitched and rolled -- is what makes
// the game's heading exact.)
Eigen::Quaterniond person_space_root(const Eigen::Quaterniond& clip_root, double heading_yaw);

}  // namespace eng::control
