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

namespace {

inline bool unbounded(const Aabb& b) { return b.lo.x() < -1e17 || b.hi.x() > 1e17; }

// The sweep axis: the one with the largest spread of the moving boxes' centres (all finite boxes when fewer than two
// move), so that rows of objects along y (fighters side by side) do not make the sweep O(n^2). It only sets the cost:
// the pair list is sorted at the end, so the output does not depend on it.
int sweep_axis(const Aabb* boxes, const std::vector<int>& moving, const std::vector<int>& fixed) {
  const std::vector<int>& from = moving.size() >= 2 ? moving : fixed;
  if (from.size() < 2) return 0;
  Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
  for (int i : from) {
    const Vec3 c = 0.5 * (boxes[i].lo + boxes[i].hi);
    sum += c;
    sum2 += c.cwiseProduct(c);
  }
  const double n = static_cast<double>(from.size());
  const Vec3 var = sum2 / n - (sum / n).cwiseProduct(sum / n);
  int ax = 0;
  if (var.y() > var[ax]) ax = 1;
  if (var.z() > var[ax]) ax = 2;
  return ax;
}

inline void emit(const Aabb* boxes, int i, int j, std::vector<std::pair<int, int>>& pairs) {
  if (boxes[i].overlaps(boxes[j])) pairs.emplace_back(std::min(i, j), std::max(i, j));
}

}  // namespace

void broadphase_pairs(const Aabb* boxes, int n, std::vector<std::pair<int, int>>& pairs) {
  broadphase_pairs(boxes, nullptr, n, pairs);
}

void broadphase_pairs(const Aabb* boxes, const unsigned char* fixed, int n, std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  // Three lists: the moving finite boxes, the fixed finite ones and the unbounded ones (planes). Fixed-fixed pairs
  // are never wanted (static geoms do not collide), and an arena of crates has hundreds of them: sweeping the
  // fixed boxes only against the moving ones keeps the cost at O(n log n + pairs found) with no fixed-fixed work.
  thread_local std::vector<int> moving, still, open;
  moving.clear();
  still.clear();
  open.clear();
  for (int i = 0; i < n; ++i) {
    if (unbounded(boxes[i]))
      open.push_back(i);
    else if (fixed && fixed[i])
      still.push_back(i);
    else
      moving.push_back(i);
  }
  const int ax = sweep_axis(boxes, moving, still);
  // sorted by lo on the axis, ties broken by index (a strict order across both lists)
  const auto before = [&](int a, int b) {
    return boxes[a].lo[ax] < boxes[b].lo[ax] || (boxes[a].lo[ax] == boxes[b].lo[ax] && a < b);
  };
  std::sort(moving.begin(), moving.end(), before);
  std::sort(still.begin(), still.end(), before);
  const int nm = static_cast<int>(moving.size()), ns = static_cast<int>(still.size());
  // moving x moving: sort and sweep (Ericson 7.5.2)
  for (int k = 0; k < nm; ++k) {
    const int i = moving[k];
    for (int l = k + 1; l < nm && boxes[moving[l]].lo[ax] <= boxes[i].hi[ax]; ++l) emit(boxes, i, moving[l], pairs);
  }
  // moving x fixed: a merge of the two sorted lists; whichever box starts first scans the other list's boxes that
  // start inside it, so each overlapping pair is found once, by its earlier-starting box.
  for (int a = 0, b = 0; a < nm && b < ns;) {
    if (before(moving[a], still[b])) {
      const int i = moving[a++];
      for (int l = b; l < ns && boxes[still[l]].lo[ax] <= boxes[i].hi[ax]; ++l) emit(boxes, i, still[l], pairs);
    } else {
      const int i = still[b++];
      for (int l = a; l < nm && boxes[moving[l]].lo[ax] <= boxes[i].hi[ax]; ++l) emit(boxes, i, moving[l], pairs);
    }
  }
  // unbounded boxes against everything they may touch
  for (size_t k = 0; k < open.size(); ++k) {
    const int i = open[k];
    const bool i_fixed = fixed && fixed[i];
    for (int j : moving) emit(boxes, i, j, pairs);
    if (!i_fixed)
      for (int j : still) emit(boxes, i, j, pairs);
    for (size_t l = k + 1; l < open.size(); ++l)
      if (!(i_fixed && fixed[open[l]])) emit(boxes, i, open[l], pairs);
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace eng::physics
