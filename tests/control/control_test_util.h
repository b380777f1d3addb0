#pragma once
// Small helpers shared by the control tests (no physics dependency: a tiny rigid-body integrator lives here).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "engine/anim/skeleton.h"
#include "engine/control/servo/orientation_error.h"

namespace eng::control::test {

inline Eigen::Quaterniond aa(double angle, const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

// Free rigid body: world angular velocity, body-frame principal inertia. Semi-implicit Euler like a game
// physics engine: omega += dt I_w^-1 (tau - omega x I_w omega); q = exp(omega dt) q.
struct RigidBody {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  Eigen::Vector3d I_body = Eigen::Vector3d::Ones();
  void step(const Eigen::Vector3d& tau, double dt) {
    const Eigen::Matrix3d R = q.toRotationMatrix();
    const Eigen::Matrix3d Iw = R * I_body.asDiagonal() * R.transpose();
    const Eigen::Vector3d wdot = Iw.ldlt().solve(tau - omega.cross(Iw * omega));
    omega += dt * wdot;
    q = integrate_rotation(q, omega, dt);
  }
};

// A small 5-bone skeleton: pelvis, spine, head, upper arm, forearm.
inline anim::Skeleton test_skeleton() {
  anim::Skeleton s;
  s.name = {"pelvis", "spine", "head", "upperarm", "forearm"};
  s.parent = {-1, 0, 1, 1, 3};
  s.offset = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 0.3), Eigen::Vector3d(0, 0, 0.4),
              Eigen::Vector3d(0, 0.2, 0.35), Eigen::Vector3d(0, 0.3, 0)};
  return s;
}

}  // namespace eng::control::test
