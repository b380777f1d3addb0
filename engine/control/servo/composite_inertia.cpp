// Composite (subtree) rigid-body inertia per joint, rest pose -- the gain scaling of eq. 3.
#include "engine/control/servo/composite_inertia.h"

#include <Eigen/Eigenvalues>
#include <cassert>

namespace eng::control {

std::vector<double> composite_inertias(const anim::Skeleton& skel, const std::vector<double>& mass,
                                       const std::vector<Eigen::Vector3d>& com,
                                       const std::vector<Eigen::Matrix3d>& inertia, InertiaScalar mode,
                                       std::vector<Eigen::Matrix3d>* tensors_out) {
  const int n = skel.size();
  assert(static_cast<int>(mass.size()) >= n && static_cast<int>(com.size()) >= n &&
         static_cast<int>(inertia.size()) >= n);
  // Rest joint positions in the root frame.
  std::vector<Eigen::Vector3d> joint(n, Eigen::Vector3d::Zero());
  for (int i = 1; i < n; ++i) joint[i] = joint[skel.parent[i]] + skel.offset[i];

  std::vector<Eigen::Matrix3d> J(n, Eigen::Matrix3d::Zero());
  const Eigen::Matrix3d E = Eigen::Matrix3d::Identity();
  for (int j = 0; j < n; ++j) {
    const Eigen::Vector3d c = joint[j] + com[j];
    // Add body j to every ancestor's (and its own) composite, each about that ancestor's joint
    // (parallel-axis theorem: I_about_p = I_com + m (|r|^2 E - r r^T), r = c - p).
    for (int a = j; a >= 0; a = skel.parent[a]) {
      const Eigen::Vector3d r = c - joint[a];
      J[a] += inertia[j] + mass[j] * (r.squaredNorm() * E - r * r.transpose());
    }
  }
  std::vector<double> out(n, 0.0);
  for (int i = 0; i < n; ++i) {
    if (mode == InertiaScalar::MeanPrincipal) {
      out[i] = J[i].trace() / 3.0;
    } else {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(J[i], Eigen::EigenvaluesOnly);
      out[i] = es.eigenvalues().maxCoeff();
    }
  }
  if (tensors_out) *tensors_out = std::move(J);
  return out;
}

std::vector<double> subtree_masses(const anim::Skeleton& skel, const std::vector<double>& mass) {
  const int n = skel.size();
  std::vector<double> m(mass.begin(), mass.begin() + n);
  for (int i = n - 1; i > 0; --i) m[skel.parent[i]] += m[i];  // children after parents
  return m;
}

}  // namespace eng::control
