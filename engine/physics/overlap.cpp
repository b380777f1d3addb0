#include "engine/physics/overlap.h"

#include <algorithm>

#include "engine/physics/narrowphase.h"

namespace eng::physics {

double deepest_overlap(const Model& m, const Data& d, const std::vector<int>& a, const std::vector<int>& b) {
  double deepest = 0.0;
  ContactPoint c[kMaxContactsPerPair];
  for (int ga : a)
    for (int gb : b) {
      const Geom &A = m.geoms[ga], &B = m.geoms[gb];
      const int n = collide_shapes(A.shape, d.x[A.body] * A.local, B.shape, d.x[B.body] * B.local, 0.0, c,
                                   kMaxContactsPerPair);
      for (int k = 0; k < n; ++k) deepest = std::max(deepest, c[k].depth);
    }
  return deepest;
}

}  // namespace eng::physics
