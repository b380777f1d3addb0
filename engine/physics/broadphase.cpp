#include "engine/physics/broadphase.h"

#include <algorithm>

namespace eng::physics {

Aabb shape_aabb(const Shape& s, const Pose& x, double margin) {
  Vec3 ext;
  switch (s.type) {
    case ShapeType::Sphere:
      ext.setConstant(s.radius);
      break;
    case ShapeType::Capsule:
      // The segment's extent along each world axis plus the radius.
      ext = (x.R.col(2) * s.half_length).cwiseAbs() + Vec3::Constant(s.radius);
      break;
    case ShapeType::Box:
      // |R| h: the extent of an oriented box (Ericson 4.2.6).
      ext = x.R.cwiseAbs() * s.half_extents;
      break;
    case ShapeType::Plane:
    default:
      return Aabb{Vec3::Constant(-1e18), Vec3::Constant(1e18)};
  }
  ext.array() += margin;
  return Aabb{x.p - ext, x.p + ext};
}

void broadphase_pairs(const Aabb* boxes, int n, std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  // Sweep and prune along the axis with the largest spread of (finite) box centres, so that rows of
  // objects laid out along y (several fighters side by side) do not make the sweep O(n^2). Geoms
  // sorted by lo on that axis, ties broken by index; the pair list is sorted afterwards, so the output
  // does not depend on the axis (deterministic).
  Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
  int nf = 0;
  for (int i = 0; i < n; ++i) {
    if (boxes[i].lo.x() < -1e17 || boxes[i].hi.x() > 1e17) continue;  // planes
    const Vec3 c = 0.5 * (boxes[i].lo + boxes[i].hi);
    sum += c;
    sum2 += c.cwiseProduct(c);
    ++nf;
  }
  int ax = 0;
  if (nf > 1) {
    const Vec3 var = sum2 / nf - (sum / nf).cwiseProduct(sum / nf);
    if (var.y() > var[ax]) ax = 1;
    if (var.z() > var[ax]) ax = 2;
  }
  thread_local std::vector<int> order;
  order.resize(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return boxes[a].lo[ax] < boxes[b].lo[ax] || (boxes[a].lo[ax] == boxes[b].lo[ax] && a < b);
  });
  for (int k = 0; k < n; ++k) {
    const int i = order[k];
    for (int l = k + 1; l < n; ++l) {
      const int j = order[l];
      if (boxes[j].lo[ax] > boxes[i].hi[ax]) break;
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace eng::physics
