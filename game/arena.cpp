#include "game/arena.h"

#include <algorithm>
#include <cmath>

#include "game/rng.h"

namespace boxing {

namespace {

inline bool under(const Crate& c, double x, double y) {
  return std::abs(x - c.center.x()) <= c.half_extents.x() && std::abs(y - c.center.y()) <= c.half_extents.y();
}

}  // namespace

double Arena::top_at(double x, double y) const {
  double top = 0.0;
  if (index.indexed != crates.size() || crates.empty()) {
    for (const Crate& c : crates)
      if (under(c, x, y)) top = std::max(top, c.center.z() + c.half_extents.z());
    return top;
  }
  const double fx = std::floor((x - index.origin.x()) / cell), fy = std::floor((y - index.origin.y()) / cell);
  if (!(fx >= 0.0 && fy >= 0.0 && fx < index.nx && fy < index.ny)) return top;  // off the platform (or NaN)
  const int cidx = static_cast<int>(fx) * index.ny + static_cast<int>(fy);
  for (int k = index.first[cidx]; k < index.first[cidx + 1]; ++k) {
    const Crate& c = crates[index.items[k]];
    if (under(c, x, y)) top = std::max(top, c.center.z() + c.half_extents.z());
  }
  return top;
}

void index_crates(Arena& a) {
  CrateIndex& ix = a.index;
  ix = CrateIndex{};
  if (a.crates.empty()) return;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  for (const Crate& c : a.crates) {
    lo = lo.cwiseMin((c.center - c.half_extents).head<2>());
    hi = hi.cwiseMax((c.center + c.half_extents).head<2>());
  }
  // One cell of margin each way, and each crate listed in every cell its footprint (grown by a hair, for points on
  // an edge) touches: a point's own cell lists every crate that can be under it.
  ix.origin = lo - Eigen::Vector2d::Constant(a.cell);
  ix.nx = static_cast<int>(std::ceil((hi.x() - ix.origin.x()) / a.cell)) + 1;
  ix.ny = static_cast<int>(std::ceil((hi.y() - ix.origin.y()) / a.cell)) + 1;
  const auto cell_of = [&](double v, double o, int n) {
    return std::clamp(static_cast<int>(std::floor((v - o) / a.cell)), 0, n - 1);
  };
  std::vector<std::vector<int>> cells(static_cast<size_t>(ix.nx) * ix.ny);
  constexpr double kHair = 1e-9;
  for (int i = 0; i < static_cast<int>(a.crates.size()); ++i) {
    const Crate& c = a.crates[i];
    const int x0 = cell_of(c.center.x() - c.half_extents.x() - kHair, ix.origin.x(), ix.nx);
    const int x1 = cell_of(c.center.x() + c.half_extents.x() + kHair, ix.origin.x(), ix.nx);
    const int y0 = cell_of(c.center.y() - c.half_extents.y() - kHair, ix.origin.y(), ix.ny);
    const int y1 = cell_of(c.center.y() + c.half_extents.y() + kHair, ix.origin.y(), ix.ny);
    for (int cx = x0; cx <= x1; ++cx)
      for (int cy = y0; cy <= y1; ++cy) cells[static_cast<size_t>(cx) * ix.ny + cy].push_back(i);
  }
  ix.first.assign(cells.size() + 1, 0);
  for (size_t k = 0; k < cells.size(); ++k) {
    ix.first[k + 1] = ix.first[k] + static_cast<int>(cells[k].size());
    ix.items.insert(ix.items.end(), cells[k].begin(), cells[k].end());
  }
  ix.indexed = a.crates.size();
}

Stance stance_at(const Arena& a, const Eigen::Vector2d& position, double heading) {
  Stance s{position, heading, 0.0, 0.0};
  const double c = std::cos(heading), sn = std::sin(heading);
  s.lead_top = a.top_at(position.x() + c * kStanceHalfLength - sn * kStanceHalfWidth,
                        position.y() + sn * kStanceHalfLength + c * kStanceHalfWidth);
  s.rear_top = a.top_at(position.x() - c * kStanceHalfLength + sn * kStanceHalfWidth,
                        position.y() - sn * kStanceHalfLength - c * kStanceHalfWidth);
  return s;
}

Arena make_arena(uint64_t seed, double min_step, double separation, bool flat) {
  Rng rng(seed * 0x9E3779B97F4A7C15ull + 17);
  Arena a;
  constexpr int kNx = 6, kNy = 4;  // 3 m x 2 m platform
  const double cell = a.cell;
  const double x0 = -0.5 * kNx * cell, y0 = -0.5 * kNy * cell;
  double height[kNx][kNy];
  for (int i = 0; i < kNx; ++i)
    for (int j = 0; j < kNy; ++j) height[i][j] = flat ? 0.30 : 0.30 + rng.uniform(-0.10, 0.14);

  // Boxers face each other along X: boxer 0 at -X facing +X, boxer 1 at +X facing -X.
  const double sx = 0.5 * separation;
  a.stances[0] = Stance{{-sx, 0.0}, 0.0, 0, 0};
  a.stances[1] = Stance{{sx, 0.0}, M_PI, 0, 0};
  auto cell_of = [&](double x, double y, int& i, int& j) {
    i = static_cast<int>(std::floor((x - x0) / cell));
    j = static_cast<int>(std::floor((y - y0) / cell));
  };
  for (Stance& s : a.stances) {
    const double c = std::cos(s.heading), sn = std::sin(s.heading);
    auto foot = [&](double fwd, double left, int& i, int& j) {
      cell_of(s.position.x() + c * fwd - sn * left, s.position.y() + sn * fwd + c * left, i, j);
    };
    int li, lj, ri, rj;
    foot(kStanceHalfLength, kStanceHalfWidth, li, lj);
    foot(-kStanceHalfLength, -kStanceHalfWidth, ri, rj);
    // Enforce the step between the two feet (the arena's rule: one foot at least min_step higher), keeping the random
    // sign of which foot is higher.
    double& hl = height[li][lj];
    double& hr = height[ri][rj];
    if (!flat && std::abs(hl - hr) < min_step) {
      const double mid = 0.5 * (hl + hr);
      const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
      hl = mid + sign * 0.5 * (min_step + 0.02);
      hr = mid - sign * 0.5 * (min_step + 0.02);
    }
  }

  constexpr double kGap = 0.006;  // visible seams between neighbouring crates
  for (int i = 0; i < kNx; ++i) {
    for (int j = 0; j < kNy; ++j) {
      const double h = height[i][j];
      const double cx = x0 + (i + 0.5) * cell, cy = y0 + (j + 0.5) * cell;
      const float tone = static_cast<float>(rng.uniform(0.85, 1.1));
      const Eigen::Vector3f wood(0.42f * tone, 0.26f * tone, 0.13f * tone);
      // Tall columns are two crates stacked (a lower one and a slightly smaller one on top); all static.
      if (h > 0.34) {
        const double lower = 0.16 + rng.uniform(0.0, 0.04);
        a.crates.push_back(Crate{{cx, cy, 0.5 * lower}, {0.5 * cell - kGap, 0.5 * cell - kGap, 0.5 * lower}, wood});
        const double shrink = rng.uniform(0.0, 0.02);
        a.crates.push_back(Crate{{cx, cy, lower + 0.5 * (h - lower)},
                                 {0.5 * cell - kGap - shrink, 0.5 * cell - kGap - shrink, 0.5 * (h - lower)},
                                 Eigen::Vector3f(wood.x() * 1.08f, wood.y() * 1.05f, wood.z())});
      } else {
        a.crates.push_back(Crate{{cx, cy, 0.5 * h}, {0.5 * cell - kGap, 0.5 * cell - kGap, 0.5 * h}, wood});
      }
    }
  }
  index_crates(a);
  for (Stance& s : a.stances) s = stance_at(a, s.position, s.heading);
  return a;
}

}  // namespace boxing

namespace boxing {

namespace {

// One column of the ring's crates at (cx, cy) with its top at h: two stacked crates when tall (as make_arena's).
void add_column(Arena& a, Rng& rng, double cx, double cy, double h, double tone_scale) {
  constexpr double kGap = 0.006;
  const double half = 0.5 * a.cell - kGap;
  const float tone = static_cast<float>(rng.uniform(0.85, 1.1) * tone_scale);
  const Eigen::Vector3f wood(0.42f * tone, 0.26f * tone, 0.13f * tone);
  if (h > 0.32) {
    const double lower = 0.16 + rng.uniform(0.0, 0.04);
    a.crates.push_back(Crate{{cx, cy, 0.5 * lower}, {half, half, 0.5 * lower}, wood});
    const double shrink = rng.uniform(0.0, 0.02);
    a.crates.push_back(Crate{{cx, cy, lower + 0.5 * (h - lower)}, {half - shrink, half - shrink, 0.5 * (h - lower)},
                             Eigen::Vector3f(wood.x() * 1.08f, wood.y() * 1.05f, wood.z())});
  } else {
    a.crates.push_back(Crate{{cx, cy, 0.5 * h}, {half, half, 0.5 * h}, wood});
  }
}

}  // namespace

Arena make_ring(uint64_t seed, double min_step, double separation) {
  Rng rng(seed * 0x9E3779B97F4A7C15ull + 0x5171ull);
  Arena a;
  constexpr int kInside = 10, kApron = 1, kN = kInside + 2 * kApron;
  constexpr double kTop = 0.30, kSpread = 0.04;  // inside tops: kTop +- kSpread (neighbours 8 cm apart at most)
  const double cell = a.cell;
  const double half = 0.5 * kInside * cell, x0 = -0.5 * kN * cell;
  double height[kN][kN];
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      const bool apron = i < kApron || j < kApron || i >= kN - kApron || j >= kN - kApron;
      // The apron a little lower than the ring's floor (a step down of 0-8 cm past the ropes).
      height[i][j] = apron ? kTop - 0.03 + rng.uniform(-0.01, 0.01) : kTop + rng.uniform(-kSpread, kSpread);
    }
  const double sx = 0.5 * separation;
  a.stances[0] = Stance{{-sx, 0.0}, 0.0, 0, 0};
  a.stances[1] = Stance{{sx, 0.0}, M_PI, 0, 0};
  auto cell_index = [&](double v) { return std::clamp(static_cast<int>(std::floor((v - x0) / cell)), 0, kN - 1); };
  for (Stance& s : a.stances) {
    const double c = std::cos(s.heading), sn = std::sin(s.heading);
    const Eigen::Vector2d lead = s.position + Eigen::Vector2d(c * kStanceHalfLength - sn * kStanceHalfWidth,
                                                              sn * kStanceHalfLength + c * kStanceHalfWidth);
    const Eigen::Vector2d rear = 2.0 * s.position - lead;
    double& hl = height[cell_index(lead.x())][cell_index(lead.y())];
    double& hr = height[cell_index(rear.x())][cell_index(rear.y())];
    // The arena's rule (one foot min_step or more higher, the random sign kept), about the ring's mean top: the two
    // cells then stay within 8 cm of any neighbour.
    const double sign = rng.uniform() < 0.5 ? -1.0 : 1.0;
    hl = kTop + sign * 0.5 * (min_step + 0.02);
    hr = kTop - sign * 0.5 * (min_step + 0.02);
  }
  double sum = 0.0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      const bool apron = i < kApron || j < kApron || i >= kN - kApron || j >= kN - kApron;
      if (!apron) sum += height[i][j];
      add_column(a, rng, x0 + (i + 0.5) * cell, x0 + (j + 0.5) * cell, height[i][j], apron ? 0.8 : 1.0);
    }
  Ring& r = a.ring;
  r.present = true;
  r.half_inside = half;
  r.top_mean = sum / (kInside * kInside);
  r.corners[Ring::kRed] = {-half, -half};
  r.corners[Ring::kBlue] = {half, half};
  r.corners[Ring::kNeutral0] = {-half, half};
  r.corners[Ring::kNeutral1] = {half, -half};
  index_crates(a);
  for (Stance& s : a.stances) s = stance_at(a, s.position, s.heading);
  return a;
}

}  // namespace boxing
