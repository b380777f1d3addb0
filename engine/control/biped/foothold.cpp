#include "engine/control/biped/foothold.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace eng::control {

namespace {
constexpr int kAlong = 7, kAcross = 3;  // sample grid over a rectangle (ends and sides included)

// Samples the rectangle [a0, a1] x [-w, w] of the foot frame; calls f(top) for each sample's crate top.
template <class F>
void sample_rect(GroundHeight ground, const Eigen::Vector2d& ankle, double yaw, double a0, double a1, double w, F f) {
  const Eigen::Vector2d ex(std::cos(yaw), std::sin(yaw)), ey(-ex.y(), ex.x());
  for (int i = 0; i < kAlong; ++i) {
    const double a = a0 + (a1 - a0) * i / (kAlong - 1);
    for (int j = 0; j < kAcross; ++j) {
      const double s = -w + 2.0 * w * j / (kAcross - 1);
      const Eigen::Vector2d q = ankle + a * ex + s * ey;
      f(ground(q.x(), q.y()));
    }
  }
}
}  // namespace

bool foothold_ok(GroundHeight ground, const Eigen::Vector2d& ankle, double yaw, const FootholdParams& p) {
  const SoleShape& s = p.sole;
  double highest = -1e9;
  sample_rect(ground, ankle, yaw, s.heel - p.clearance, s.toe + p.clearance, s.half_width + p.clearance,
              [&](double t) { highest = std::max(highest, t); });
  bool ok = true;
  sample_rect(ground, ankle, yaw, s.heel + p.end_margin, s.toe - p.end_margin, s.half_width - p.side_margin,
              [&](double t) { ok = ok && t >= highest - p.level_tol; });
  return ok;
}

namespace {
// Candidates in order of cost (ties: the grid order, deterministic); a search takes the first good one. The order
// depends on the search's shape alone, so it is sorted once per thread and shape, not per call: a balance step
// searches every tick it re-plans, and the step allocates nothing once warm. A few shapes are kept (balance steps'
// and carried steps' footholds alternate; re-sorted at each switch, the sort would allocate in the world's step).
struct Candidate {
  double cost;
  int i, j;
};
struct CandidateOrder {
  double max_shift = -1.0, grid = 0.0, lateral_cost = 0.0, back_cost = 0.0;
  std::vector<Candidate> cand;
};
const CandidateOrder& candidate_order(const FootholdParams& p) {
  thread_local std::array<CandidateOrder, 4> orders;
  thread_local size_t next = 0;
  for (const CandidateOrder& o : orders)
    if (o.max_shift == p.max_shift && o.grid == p.grid && o.lateral_cost == p.lateral_cost && o.back_cost == p.back_cost)
      return o;
  CandidateOrder& o = orders[next];
  next = (next + 1) % orders.size();
  const int n = static_cast<int>(std::floor(p.max_shift / p.grid));
  o.cand.clear();
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      const double a = i * p.grid, c = j * p.grid;
      if (a * a + c * c > p.max_shift * p.max_shift + 1e-12) continue;
      o.cand.push_back({(i < 0 ? p.back_cost : 1.0) * a * a + p.lateral_cost * c * c, i, j});
    }
  // Ties in the grid order (i, then j): std::sort with them is stable_sort's order, without its buffer.
  std::sort(o.cand.begin(), o.cand.end(), [](const Candidate& x, const Candidate& y) {
    return x.cost != y.cost ? x.cost < y.cost : x.i != y.i ? x.i < y.i : x.j < y.j;
  });
  o.max_shift = p.max_shift, o.grid = p.grid, o.lateral_cost = p.lateral_cost, o.back_cost = p.back_cost;
  return o;
}

}  // namespace

void prepare_foothold_search(const FootholdParams& p) { candidate_order(p); }

Foothold find_foothold(GroundHeight ground, const Eigen::Vector2d& ankle, double yaw, double frame_yaw,
                       const FootholdParams& p) {
  const CandidateOrder& order = candidate_order(p);
  Foothold r;
  if (foothold_ok(ground, ankle, yaw, p)) {
    r.found = true;
    return r;
  }
  const Eigen::Vector2d ex(std::cos(frame_yaw), std::sin(frame_yaw)), ey(-ex.y(), ex.x());
  for (const Candidate& c : order.cand) {
    const Eigen::Vector2d s = c.i * p.grid * ex + c.j * p.grid * ey;
    if (foothold_ok(ground, ankle + s, yaw, p)) {
      r.shift = s;
      r.found = true;
      return r;
    }
  }
  return r;
}

}  // namespace eng::control
