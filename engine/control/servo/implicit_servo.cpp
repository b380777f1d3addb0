// Eq. 3 as an implicit joint spring-damper rooted at the support (see implicit_servo.h).
#include "engine/control/servo/implicit_servo.h"

#include <cassert>
#include <cmath>

#include "engine/control/servo/orientation_error.h"

namespace eng::control {

std::vector<bool> support_path(const anim::Skeleton& skel, const std::vector<int>& feet) {
  std::vector<bool> s(skel.size(), false);
  for (int f : feet)
    for (int a = f; a > 0; a = skel.parent[a]) s[a] = true;  // the root itself is not a joint
  return s;
}

std::vector<double> servo_inertias(const anim::Skeleton& skel, const std::vector<double>& mass,
                                   const std::vector<Eigen::Vector3d>& com,
                                   const std::vector<Eigen::Matrix3d>& inertia, const std::vector<bool>& support,
                                   int support_legs) {
  const int n = skel.size();
  std::vector<Eigen::Vector3d> joint(n, Eigen::Vector3d::Zero());
  for (int i = 1; i < n; ++i) joint[i] = joint[skel.parent[i]] + skel.offset[i];
  auto in_subtree = [&](int j, int i) {
    for (int a = j; a >= 0; a = skel.parent[a])
      if (a == i) return true;
    return false;
  };
  const Eigen::Matrix3d E = Eigen::Matrix3d::Identity();
  std::vector<double> out(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const bool load_side = i > 0 && i < static_cast<int>(support.size()) && support[i];
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    for (int j = 0; j < n; ++j) {
      if (in_subtree(j, i) == load_side) continue;  // subtree for free bones, the rest for support bones
      const Eigen::Vector3d r = joint[j] + com[j] - joint[i];
      J += inertia[j] + mass[j] * (r.squaredNorm() * E - r * r.transpose());
    }
    out[i] = J.trace() / 3.0;
    if (load_side && support_legs > 1) out[i] /= support_legs;
  }
  return out;
}

namespace {

double hinge_angle(Eigen::Quaterniond q, const Eigen::Vector3d& axis) {
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const double proj = q.vec().dot(axis);
  return 2.0 * std::atan2(proj, q.w());
}

}  // namespace

void implicit_servo_refs(const anim::Skeleton& skel, const std::vector<ImplicitServoJoint>& joints,
                         const std::vector<Eigen::Quaterniond>& W_d, const std::vector<Eigen::Vector3d>& omega_d,
                         const std::vector<Eigen::Quaterniond>& W_a, const std::vector<Eigen::Vector3d>& omega_a,
                         const std::vector<Eigen::Vector3d>& q_a, double dt, std::vector<Eigen::Vector3d>& ref) {
  const int n = skel.size();
  ref.resize(n);
  for (int i = 0; i < n; ++i) {
    ref[i].setZero();
    const ImplicitServoJoint& j = joints[i];
    if (i == 0 || j.kind == JointKind::None || j.K <= 0.0) continue;
    const int p = skel.parent[i];
    // Target joint rotation and relative rate (bone i's frame), eq. 3 measured on the controlled bone.
    Eigen::Quaterniond qt;
    Eigen::Vector3d w_rel;  // world
    if (!j.support) {  // controls bone i: W_a[p] * q = W_d[i]
      qt = W_a[p].conjugate() * W_d[i];
      w_rel = omega_d[i] - omega_d[p];
    } else if (!j.planted) {  // controls the parent: W_d[p] * q = W_a[i]
      qt = W_d[p].conjugate() * W_a[i];
      w_rel = omega_d[i] - omega_d[p];
    } else {  // planted foot: taken at its desired (flat) orientation, see ImplicitServoJoint::planted
      qt = W_d[p].conjugate() * W_d[i];
      w_rel = omega_d[i] - omega_d[p];
    }
    const Eigen::Vector3d v_ref = W_a[i].conjugate() * w_rel;  // joint rate in bone i's frame
    const double lead = j.D / j.K + dt;  // velocity target folded into the spring reference
    if (j.kind == JointKind::Ball) {
      const Eigen::Quaterniond qa = rotation_from_vector(q_a[i]);
      Eigen::Quaterniond qr = (qt * rotation_from_vector(lead * v_ref)).normalized();
      Eigen::Vector3d e = quaternion_log_vector(qa.conjugate() * qr);  // ref relative to actual (bone frame)
      if (j.support && !j.planted) {
        // Twist about the bone's own axis (a support thigh's swivel) servoed as a free bone would be: bone i
        // toward its own W_d from the actual parent. The support law holds the parent's tilt and heading; the
        // leg's swivel has no other actuator than the planted foot's torsional grip.
        const Eigen::Quaterniond qn =
            (W_a[p].conjugate() * W_d[i]) * rotation_from_vector(lead * v_ref);
        const Eigen::Vector3d e_free = quaternion_log_vector(qa.conjugate() * qn.normalized());
        e.z() = e_free.z();
        if (j.free_roll) e.x() = e_free.x();
      }
      if (j.planted) e.z() *= j.twist_scale;  // weaker twist spring on a planted foot (no torsional friction)
      if (j.limit > 0.0 && j.K * e.norm() > j.limit) e *= j.limit / (j.K * e.norm());
      qr = qa * rotation_from_vector(e);
      ref[i] = quaternion_log_vector(qr);
    } else {
      const double qa = q_a[i].x();
      double e = hinge_angle(qt, j.axis) + lead * v_ref.dot(j.axis) - qa;
      e = std::remainder(e, 2.0 * M_PI);
      if (j.limit > 0.0 && j.K * std::abs(e) > j.limit) e = std::copysign(j.limit / j.K, e);
      ref[i].x() = qa + e;
    }
  }
}

Eigen::Vector3d implicit_servo_spring_torque(const ImplicitServoJoint& j, const Eigen::Quaterniond& W_child,
                                             const Eigen::Vector3d& ref, const Eigen::Vector3d& q_a) {
  if (j.kind == JointKind::Ball) {
    const Eigen::Vector3d e =
        quaternion_log_vector(rotation_from_vector(q_a).conjugate() * rotation_from_vector(ref));
    return W_child * (j.K * e);
  }
  if (j.kind == JointKind::Hinge) return W_child * (j.K * (ref.x() - q_a.x()) * j.axis);
  return Eigen::Vector3d::Zero();
}

}  // namespace eng::control
