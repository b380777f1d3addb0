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
  // Sweep along x over geoms sorted by lo.x; ties broken by index so the order is deterministic.
  thread_local std::vector<int> order;
  order.resize(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return boxes[a].lo.x() < boxes[b].lo.x() || (boxes[a].lo.x() == boxes[b].lo.x() && a < b);
  });
  for (int k = 0; k < n; ++k) {
    const int i = order[k];
    for (int l = k + 1; l < n; ++l) {
      const int j = order[l];
      if (boxes[j].lo.x() > boxes[i].hi.x()) break;
      if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace eng::physics
