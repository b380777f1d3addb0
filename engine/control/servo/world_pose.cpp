// Lift to world space and desired world angular velocity (paper section IV, eq. 2).
#include "engine/control/servo/world_pose.h"

#include <cassert>

#include "engine/control/servo/orientation_error.h"

namespace eng::control {

void pose_fk(const anim::Skeleton& skel, const anim::Pose& pose, std::vector<Eigen::Quaterniond>& W,
             std::vector<Eigen::Vector3d>& P) {
  const int n = skel.size();
  W.resize(n);
  P.resize(n);
  for (int i = 0; i < n; ++i) {
    if (i == 0) {
      W[0] = pose.rotation[0].normalized();
      P[0] = pose.root_position;
    } else {
      const int p = skel.parent[i];
      W[i] = (W[p] * pose.rotation[i]).normalized();
      P[i] = P[p] + W[p] * skel.offset[i];
    }
  }
}

void lift_to_world(const anim::Skeleton& skel, const anim::Pose& desired, const Eigen::Quaterniond& root_world,
                   std::vector<Eigen::Quaterniond>& W_d) {
  const int n = skel.size();
  assert(static_cast<int>(desired.rotation.size()) >= n);
  W_d.resize(n);
  if (n == 0) return;
  W_d[0] = root_world.normalized();
  for (int i = 1; i < n; ++i) {
    // parent[i] < i: the parent is already lifted. Only DESIRED relative rotations enter (paper section IV).
    W_d[i] = (W_d[skel.parent[i]] * desired.rotation[i]).normalized();
  }
}

void desired_world_velocity_lookahead(const anim::Skeleton& skel, const anim::Pose& now,
                                      const Eigen::Quaterniond& root_now, const anim::Pose& ahead,
                                      const Eigen::Quaterniond& root_ahead, double delta,
                                      WorldPoseScratch& scratch, std::vector<Eigen::Vector3d>& omega_d) {
  const int n = skel.size();
  assert(delta > 0.0);
  lift_to_world(skel, now, root_now, scratch.W_now);
  lift_to_world(skel, ahead, root_ahead, scratch.W_ahead);
  omega_d.resize(n);
  const double inv = 1.0 / delta;
  for (int i = 0; i < n; ++i)  // eq. 2
    omega_d[i] = inv * orientation_error(scratch.W_ahead[i], scratch.W_now[i]);
}

void desired_world_velocity(const anim::Skeleton& skel, const anim::PoseSample& now,
                            const Eigen::Quaterniond& root_now, const Eigen::Quaterniond& root_ahead,
                            double delta, DesiredVelocityMode mode, WorldPoseScratch& scratch,
                            std::vector<Eigen::Vector3d>& omega_d) {
  const int n = skel.size();
  const bool have_rates = static_cast<int>(now.angular_velocity.size()) >= n;
  if (mode == DesiredVelocityMode::LookAhead && delta > 0.0) {
    // Extrapolate each relative rotation at its sampled constant rate (parent frame => left-multiply).
    scratch.ahead.root_position = now.pose.root_position + delta * now.root_velocity;
    scratch.ahead.rotation.resize(n);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d w = (have_rates && i > 0) ? now.angular_velocity[i] : Eigen::Vector3d::Zero();
      scratch.ahead.rotation[i] = integrate_rotation(now.pose.rotation[i], w, delta);
    }
    desired_world_velocity_lookahead(skel, now.pose, root_now, scratch.ahead, root_ahead, delta, scratch,
                                     omega_d);
    return;
  }
  // Analytic composition: omega_child = omega_parent + R(W_parent) w_rel (w_rel expressed in the parent).
  lift_to_world(skel, now.pose, root_now, scratch.W_now);
  omega_d.resize(n);
  if (n == 0) return;
  omega_d[0] = delta > 0.0 ? Eigen::Vector3d(orientation_error(root_ahead, root_now) / delta)
                           : Eigen::Vector3d::Zero();
  for (int i = 1; i < n; ++i) {
    const int p = skel.parent[i];
    const Eigen::Vector3d w = have_rates ? now.angular_velocity[i] : Eigen::Vector3d::Zero();
    omega_d[i] = omega_d[p] + scratch.W_now[p] * w;
  }
}

}  // namespace eng::control
