#include "game/match/footwork_ai.h"

#include <algorithm>
#include <cmath>

#include "game/footwork.h"
#include "game/match/fighter_view.h"
#include "game/match/match.h"
#include "game/match/match_internal.h"

namespace boxing {

Eigen::Vector2d ring_half_size(const World& w) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e9), hi = Eigen::Vector2d::Constant(-1e9);
  for (const Crate& c : w.arena.crates) {
    lo = lo.cwiseMin((c.center - c.half_extents).head<2>());
    hi = hi.cwiseMax((c.center + c.half_extents).head<2>());
  }
  return lo.x() > hi.x() ? Eigen::Vector2d::Zero() : Eigen::Vector2d(0.5 * (hi - lo));
}

Eigen::Vector2d neutral_corner(const World& w, int standing) {
  const MatchTuning& tu = w.match->tuning;
  const Eigen::Vector2d half = ring_half_size(w) - Eigen::Vector2d::Constant(tu.footwork.corner_inset);
  const Eigen::Vector2d down = w.data.x[w.boxers[1 - standing].bodies.body[0]].p.head<2>();
  Eigen::Vector2d best = Eigen::Vector2d::Zero();
  double far = -1.0;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      const Eigen::Vector2d c(sx * half.x(), sy * half.y());
      if ((c - down).norm() > far) far = (c - down).norm(), best = c;
    }
  return best;
}

namespace {

double wrap(double a) { return std::remainder(a, 2.0 * M_PI); }

Eigen::Vector2d pelvis_xy(const World& w, int k) { return w.data.x[w.boxers[k].bodies.body[0]].p.head<2>(); }

// The stance's centre after move m stays inside the ring's margin.
bool stays_inside(const World& w, int k, FootworkMove m, double heading) {
  const Boxer& b = w.boxers[k];
  const Eigen::Vector2d half = ring_half_size(w) - Eigen::Vector2d::Constant(w.match->tuning.footwork.ring_margin);
  const Eigen::Vector2d p = pelvis_xy(w, k) + footwork_delta(m, heading, b.settings.tuning.footwork);
  return std::abs(p.x()) <= half.x() && std::abs(p.y()) <= half.y();
}

// A lateral move: toward the side that cuts the opponent off from the ring's centre when he is near the ropes, else
// the style's way round (changed now and then), and the other way where the ropes are.
FootworkMove circle_move(World& w, int k, double heading) {
  MatchFighter& f = w.match->fighter[k];
  const Eigen::Vector2d me = pelvis_xy(w, k), other = pelvis_xy(w, 1 - k);
  const Eigen::Vector2d half = ring_half_size(w);
  const double room = std::min(half.x() - std::abs(other.x()), half.y() - std::abs(other.y()));
  const Eigen::Vector2d fwd(std::cos(heading), std::sin(heading)), left(-fwd.y(), fwd.x());
  int side = f.circle_side;
  if (room < 1.0) {
    // Cut off: stand between him and the centre (the centre on my left of the line to him: step left).
    side = left.dot(-me) > 0.0 ? 1 : -1;
  } else if (f.ai.rng.uniform() < 0.25) {
    side = -side;
  }
  f.circle_side = side;
  FootworkMove m = side > 0 ? FootworkMove::Left : FootworkMove::Right;
  if (!stays_inside(w, k, m, heading)) m = side > 0 ? FootworkMove::Right : FootworkMove::Left;
  return stays_inside(w, k, m, heading) ? m : FootworkMove::Pivot;
}

}  // namespace

bool footwork_ai_tick(World& w, int k, bool free, bool just_punched) {
  Match& mt = *w.match;
  const FootworkAiTuning& t = mt.tuning.footwork;
  Boxer& b = w.boxers[k];
  MatchFighter& f = mt.fighter[k];
  const double now = w.data.time;
  if (footwork_busy(b)) {
    f.was_moving = true;
    return false;
  }
  if (f.was_moving) f.was_moving = false, f.last_move_end = now;
  if (!free || !standing_state(b.ctl.state.state)) return false;
  // A stunned boxer only backs away or circles out (hurt, below), at half the cadence: its softer legs step less.
  const bool stunned = b.ctl.state.state == BoxerState::Stunned;
  const auto& bst = b.ctl.balance_steps;
  if (bst.step.active || bst.recovering || bst.shifting >= 0) return false;
  const Eigen::Vector2d me = pelvis_xy(w, k), other = pelvis_xy(w, 1 - k);
  const double heading = b.stance.heading;
  FootworkMove m = FootworkMove::None;
  double turn = 0.0;
  if (f.go_to_active) {
    // To the neutral corner, facing the downed boxer (backing off or sidling there), then waiting there.
    const Eigen::Vector2d to = f.go_to - me;
    turn = wrap(std::atan2(other.y() - me.y(), other.x() - me.x()) - heading);
    if (to.norm() < t.at_corner) {
      m = std::abs(turn) > t.face_within ? FootworkMove::Pivot : FootworkMove::None;
    } else {
      const Eigen::Rotation2Dd R(-(heading + turn));
      const Eigen::Vector2d local = R * to;  // along the turned heading (+ forward), across it (+ left)
      m = std::abs(local.x()) >= std::abs(local.y()) ? (local.x() > 0 ? FootworkMove::Forward : FootworkMove::Back)
                                                     : (local.y() > 0 ? FootworkMove::Left : FootworkMove::Right);
    }
  } else {
    const bool opponent_up = standing_state(w.boxers[1 - k].ctl.state.state);
    if (!opponent_up) return false;
    if (now < f.next_move) return false;
    const double dist = reach_distance(w, k);
    turn = wrap(std::atan2(other.y() - me.y(), other.x() - me.x()) - heading);
    const double reach = mt.tuning.reach;
    const bool hurt = b.ctl.root_spring.consciousness() < t.hurt_below;
    const bool hit_lately = now - f.last_hit_at < mt.tuning.step_in_after_hit;
    // Stunned deeper than stunned_steps_above, the softer legs do not step on purpose (the balance steps still
    // catch the body): stepping, they fell without a hit in 14-18 of 20 matches where they stood still in 10.
    if (stunned && b.ctl.root_spring.consciousness() < t.stunned_steps_above) return false;
    if (std::abs(turn) > t.pivot_beyond) {
      m = FootworkMove::Pivot;
    } else if (hurt && dist < reach + t.hurt_gap) {
      m = f.ai.rng.uniform() < 0.5 ? FootworkMove::Back : circle_move(w, k, heading);
    } else if (dist > reach + t.band_out && !(hit_lately && dist < reach + 0.3)) {
      m = FootworkMove::Forward;
    } else if (dist < reach - t.band_in) {
      m = f.ai.rng.uniform() < 0.6 ? FootworkMove::Back : circle_move(w, k, heading);
    } else if (just_punched && f.ai.rng.uniform() < t.exit_share) {
      m = f.ai.rng.uniform() < 0.5 ? FootworkMove::Back : circle_move(w, k, heading);
    } else if (std::abs(turn) > t.face_within) {
      m = FootworkMove::Pivot;
    } else if (f.ai.rng.uniform() < 1.0 - std::exp(-t.circle_rate * (now - f.last_move_end))) {
      m = circle_move(w, k, heading);
    }
    if (m != FootworkMove::None && m != FootworkMove::Pivot && !stays_inside(w, k, m, heading + turn))
      m = m == FootworkMove::Forward ? FootworkMove::Pivot : circle_move(w, k, heading);
  }
  if (m == FootworkMove::None) return false;
  if (!request_footwork(b, m, turn)) return false;
  f.next_move = now + (stunned ? t.stunned_pause_scale : 1.0) * f.ai.rng.uniform(t.pause_min, t.pause_max);
  return true;
}

}  // namespace boxing
