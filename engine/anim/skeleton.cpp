#include "engine/anim/skeleton.h"

#include <cmath>

namespace eng::anim {

Skeleton boxer_skeleton() {
  Skeleton s;
  auto add = [&](const char* n, int p, double x, double y, double z) {
    s.name.push_back(n);
    s.parent.push_back(p);
    s.offset.emplace_back(x, y, z);
  };
  add("pelvis", -1, 0, 0, 0.97);
  add("abdomen", 0, 0, 0, 0.10);
  add("chest", 1, 0, 0, 0.18);
  add("head", 2, 0, 0, 0.25);
  add("upper_arm_l", 2, 0, 0.19, 0.19);
  add("forearm_l", 4, 0, 0, -0.30);
  add("glove_l", 5, 0, 0, -0.26);
  add("upper_arm_r", 2, 0, -0.19, 0.19);
  add("forearm_r", 7, 0, 0, -0.30);
  add("glove_r", 8, 0, 0, -0.26);
  add("thigh_l", 0, 0, 0.09, -0.04);
  add("shank_l", 10, 0, 0, -0.43);
  add("foot_l", 11, 0, 0, -0.42);
  add("thigh_r", 0, 0, -0.09, -0.04);
  add("shank_r", 13, 0, 0, -0.43);
  add("foot_r", 14, 0, 0, -0.42);
  return s;
}

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
