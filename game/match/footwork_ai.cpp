#include "game/match/footwork_ai.h"

#include <algorithm>
#include <cmath>

#include "game/footwork.h"
#include "game/match/fighter_view.h"
#include "game/match/match.h"
#include "game/match/match_internal.h"

namespace boxing {

Eigen::Vector2d ring_half_size(const World& w) {
  // The ropes' square where there is a ring (its apron's crates reach past them), else the crates' extent.
  if (w.arena.ring.present) return Eigen::Vector2d::Constant(w.arena.ring.half_inside);
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

// How far a stance centre at p is outside the ring's margin (0 inside it).
double past_margin(const World& w, const Eigen::Vector2d& p) {
  const Eigen::Vector2d half = ring_half_size(w) - Eigen::Vector2d::Constant(w.match->tuning.footwork.ring_margin);
  return std::max({0.0, std::abs(p.x()) - half.x(), std::abs(p.y()) - half.y()});
}

// Where move m takes the stance's centre.
Eigen::Vector2d after_move(const World& w, int k, FootworkMove m, double heading) {
  return pelvis_xy(w, k) + footwork_delta(m, heading, w.boxers[k].settings.tuning.footwork);
}

// The stance's centre after move m stays inside the ring's margin, or (pushed past it) comes back toward it.
bool stays_inside(const World& w, int k, FootworkMove m, double heading) {
  const double now = past_margin(w, pelvis_xy(w, k)), after = past_margin(w, after_move(w, k, m, heading));
  return after <= 0.0 || after < now - 0.05;
}

// Pushed past the margin (a clinch, a flurry on the ropes): the move that brings the stance furthest back in.
FootworkMove off_the_ropes(const World& w, int k, double heading) {
  FootworkMove best = FootworkMove::None;
  double least = past_margin(w, pelvis_xy(w, k)) - 0.05;
  const bool close = reach_distance(w, k) < w.match->tuning.reach + 0.3;
  for (FootworkMove m : {FootworkMove::Left, FootworkMove::Right, FootworkMove::Back, FootworkMove::Forward}) {
    if (m == FootworkMove::Forward && close) continue;  // not into him (a clinch's push, the QP's recovery steps)
    const double after = past_margin(w, after_move(w, k, m, heading));
    if (after < least) least = after, best = m;
  }
  return best;
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

// Away from p (the downed boxer, rising toward me): the move that leaves the stance's centre farthest from it, kept
// inside the ring's margin where it can be (each metre past the margin counts as 4 m closer: in a corner it sidles
// along the ropes rather than into them).
FootworkMove away_from(const World& w, int k, double heading, const Eigen::Vector2d& p) {
  FootworkMove best = FootworkMove::None;
  double far = -1e9;
  for (FootworkMove m : {FootworkMove::Back, FootworkMove::Left, FootworkMove::Right}) {
    const Eigen::Vector2d to = after_move(w, k, m, heading);
    const double score = (to - p).norm() - 4.0 * past_margin(w, to);
    if (score > far) far = score, best = m;
  }
  return best;
}

}  // namespace

bool footwork_restless(const World& w, int k) {
  const MatchFighter& f = w.match->fighter[k];
  return !footwork_busy(w.boxers[k]) && !f.was_moving && w.data.time - f.last_move_end > w.match->tuning.footwork.max_still;
}

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
    // To a corner (a neutral one while the other is down, its own between rounds), facing the other boxer (backing
    // off or sidling there), then waiting there. Away from a downed boxer first; between rounds both walk past.
    const Eigen::Vector2d to = f.go_to - me;
    turn = wrap(std::atan2(other.y() - me.y(), other.x() - me.x()) - heading);
    if (!standing_state(w.boxers[1 - k].ctl.state.state) && (other - me).norm() < t.count_keep_away) {
      m = away_from(w, k, heading + turn, other);
    } else if (to.norm() < t.at_corner) {
      m = std::abs(turn) > t.face_within ? FootworkMove::Pivot : FootworkMove::None;
    } else {
      const Eigen::Rotation2Dd R(-(heading + turn));
      const Eigen::Vector2d local = R * to;  // along the turned heading (+ forward), across it (+ left)
      m = std::abs(local.x()) >= std::abs(local.y()) ? (local.x() > 0 ? FootworkMove::Forward : FootworkMove::Back)
                                                     : (local.y() > 0 ? FootworkMove::Left : FootworkMove::Right);
    }
  } else {
    if (!t.on) return false;
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
    const FootworkMove inward = past_margin(w, me) > t.off_ropes ? off_the_ropes(w, k, heading + turn) : FootworkMove::None;
    if (std::abs(turn) > t.pivot_beyond) {
      m = FootworkMove::Pivot;
    } else if (inward != FootworkMove::None) {
      m = inward;
    } else if (hurt && dist < reach + t.hurt_gap) {
      m = f.ai.rng.uniform() < 0.5 ? FootworkMove::Back : circle_move(w, k, heading);
    } else if (dist > reach + t.band_out && !(hit_lately && dist < reach + 0.3)) {
      m = FootworkMove::Forward;
    } else if (dist < reach - t.band_in) {
      m = f.ai.rng.uniform() < 0.6 ? FootworkMove::Back : circle_move(w, k, heading);
    } else if (just_punched && f.ai.rng.uniform() < t.exit_share * f.ai.tuning.exit_scale) {
      m = f.ai.rng.uniform() < 0.5 ? FootworkMove::Back : circle_move(w, k, heading);
    } else if (std::abs(turn) > t.face_within) {
      m = FootworkMove::Pivot;
    } else if (now - f.last_move_end > t.max_still ||
               f.ai.rng.uniform() < 1.0 - std::exp(-t.circle_rate * f.ai.tuning.circle_scale * (now - f.last_move_end))) {
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
