#include "engine/anim/skeleton.h"

#include <cmath>

namespace eng::anim {

void forward_kinematics(const Skeleton& s, const Pose& p, std::vector<Eigen::Vector3d>* world_pos,
                        std::vector<Eigen::Quaterniond>* world_rot) {
  const int n = s.size();
  world_pos->resize(n);
  world_rot->resize(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Quaterniond local =
        i < static_cast<int>(p.rotation.size()) ? p.rotation[i] : Eigen::Quaterniond::Identity();
    if (s.parent[i] < 0) {
      (*world_pos)[i] = p.root_position;
      (*world_rot)[i] = local;
    } else {
      const int q = s.parent[i];
      (*world_pos)[i] = (*world_pos)[q] + (*world_rot)[q] * s.offset[i];
      (*world_rot)[i] = ((*world_rot)[q] * local).normalized();
    }
  }
}

Eigen::Quaterniond quat_exp(const Eigen::Vector3d& v) {
  const double a = v.norm();
  if (a < 1e-12) return Eigen::Quaterniond(1.0, 0.5 * v.x(), 0.5 * v.y(), 0.5 * v.z()).normalized();
  const double s = std::sin(0.5 * a) / a;
  return Eigen::Quaterniond(std::cos(0.5 * a), s * v.x(), s * v.y(), s * v.z());
}

Eigen::Vector3d quat_log(const Eigen::Quaterniond& qin) {
  Eigen::Quaterniond q = qin;
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // shortest arc
  const Eigen::Vector3d v = q.vec();
  const double sn = v.norm();
  if (sn < 1e-12) return 2.0 * v;
  const double a = 2.0 * std::atan2(sn, q.w());
  return v * (a / sn);
}

}  // namespace eng::anim
