#include "game/match/footwork_metrics.h"

#include <algorithm>

#include "game/boxer.h"
#include "game/match/fighter_view.h"
#include "game/match/match.h"
#include "game/match/match_internal.h"
#include "game/segment_distance.h"
#include "game/world.h"
#include "engine/physics/dynamics.h"

namespace boxing {

namespace {

// The deepest overlap between the two legs' geoms (m, > 0 overlapping).
double legs_overlap(const World& w, const FootworkMetrics& m) {
  if (m.leg_geoms[0].empty()) return -1e9;
  double deepest = -1e9;
  for (int ga : m.leg_geoms[0]) {
    const SweptSegment a = swept_segment(w.model.geoms[ga].shape, w.data.geom_x[ga]);
    for (int gb : m.leg_geoms[1])
      deepest = std::max(deepest, -swept_distance(a, swept_segment(w.model.geoms[gb].shape, w.data.geom_x[gb])));
  }
  return deepest;
}

// The feet's lifts and landings (steps) and whether either is out of the ring (exits).
void measure_feet(World& w, int k, bool standing) {
  const Boxer& b = w.boxers[k];
  Match& mt = *w.match;
  FootworkMetrics& m = mt.footwork[k];
  const FootworkMetricsTuning& tu = mt.footwork_tuning;
  const double t = w.data.time;
  bool outside = false;
  for (int f = 0; f < 2; ++f) {
    const Eigen::Vector2d at = w.data.x[b.bodies.body[b.bones.foot[f]]].p.head<2>();
    const bool grounded = b.ctl.contacts.on_ground[f];  // a ground contact within 2 mm (FootContactThresholds::load)
    if (!m.airborne[f] && !grounded) {
      m.airborne[f] = true, m.lift_standing[f] = standing, m.lift_t[f] = t, m.lift_at[f] = at;
    } else if (m.airborne[f] && b.ctl.contacts.on_top[f]) {
      m.airborne[f] = false;
      if (standing && m.lift_standing[f] && t - m.lift_t[f] >= tu.min_air && (at - m.lift_at[f]).norm() >= tu.min_travel)
        ++m.steps;
    }
    if (w.arena.ring.present && !w.arena.ring.inside(at)) outside = true;
  }
  if (outside && !m.outside) {
    ++m.ring_exits;
    if (t - mt.fighter[k].last_hit_at <= tu.exit_after_hit) ++m.ring_exits_after_hit;
  }
  m.outside = outside;
}

}  // namespace

double legs_overlap(const World& w, int k) { return legs_overlap(w, w.match->footwork[k]); }

void footwork_setup(World& w) {
  for (int k = 0; k < 2 && k < static_cast<int>(w.boxers.size()); ++k) {
    FootworkMetrics& m = w.match->footwork[k];
    m = FootworkMetrics{};
    list_leg_geoms(w.boxers[k], m.leg_geoms);
    m.last_sample = w.data.x[w.boxers[k].bodies.body[0]].p.head<2>();
    m.last_pelvis = w.data.x[w.boxers[k].bodies.body[0]].p;
  }
}

void measure_footwork(World& w) {
  Match& mt = *w.match;
  const FootworkMetricsTuning& tu = mt.footwork_tuning;
  const double dt = kPhysicsDt;
  const int every = std::max(1, static_cast<int>(std::lround(tu.sample_every / dt)));
  for (int k = 0; k < 2; ++k) {
    const Boxer& b = w.boxers[k];
    FootworkMetrics& m = mt.footwork[k];
    const bool standing = standing_state(b.ctl.state.state);
    // A jump of the pelvis no velocity explains: the pose was set (a teleport); path and steps not carried across it.
    const int pelvis = b.bodies.body[0];
    const Eigen::Vector3d p3 = w.data.x[pelvis].p;
    const Eigen::Vector3d moved = p3 - m.last_pelvis - eng::physics::point_velocity(w.data, pelvis, p3) * dt;
    if (w.steps > 0 && moved.norm() > tu.teleport_jump) {
      ++m.teleports, ++mt.teleports;
      m.have_sample = false;
      m.airborne = {};
    }
    m.last_pelvis = p3;
    measure_feet(w, k, standing);
    if (standing) {
      m.standing_s += dt;
      if (in_range(w, k)) m.time_in_range_s += dt;
      if (legs_overlap(w, m) > tu.legs_through) m.legs_through_s += dt;
    }
    if (w.steps % every == 0) {
      const Eigen::Vector2d p = w.data.x[b.bodies.body[0]].p.head<2>();
      if (standing && m.have_sample) m.path_m += (p - m.last_sample).norm();
      m.last_sample = p;
      m.have_sample = standing;
    }
    // A knockdown: how close the other came to the downed one (pelvis to pelvis, floor plane), while the count ran
    // and over the whole knockdown.
    const int g = mt.fighter[k].getup;
    if (g >= 0 && g < static_cast<int>(mt.getups.size())) {
      GetUp& up = mt.getups[g];
      const double d = (w.data.x[b.bodies.body[0]].p - w.data.x[w.boxers[1 - k].bodies.body[0]].p).head<2>().norm();
      auto closer = [d](double& closest) { closest = closest < 0.0 ? d : std::min(closest, d); };
      closer(up.down_distance_min);
      if (up.counting) closer(up.count_distance_min);
    }
  }
}

}  // namespace boxing
