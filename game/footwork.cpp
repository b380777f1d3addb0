#include "game/footwork.h"

#include <algorithm>
#include <cmath>

#include "game/boxer.h"

namespace boxing {

const char* footwork_move_name(FootworkMove m) {
  switch (m) {
    case FootworkMove::None: return "none";
    case FootworkMove::Forward: return "forward";
    case FootworkMove::Back: return "back";
    case FootworkMove::Left: return "left";
    case FootworkMove::Right: return "right";
    case FootworkMove::Pivot: return "pivot";
  }
  return "none";
}

Eigen::Vector2d footwork_delta(FootworkMove m, double heading, const FootworkTuning& t) {
  const Eigen::Vector2d fwd(std::cos(heading), std::sin(heading)), left(-fwd.y(), fwd.x());
  switch (m) {
    case FootworkMove::Forward: return t.stride * fwd;
    case FootworkMove::Back: return -t.stride * fwd;
    case FootworkMove::Left: return t.side_stride * left;
    case FootworkMove::Right: return -t.side_stride * left;
    default: return Eigen::Vector2d::Zero();
  }
}

namespace {

// The balance's own steps hold the feet (a recovery, its return, a weight shift): no move starts or goes on.
bool balance_has_feet(const Boxer& b) {
  const eng::control::BalanceStepState& st = b.ctl.balance_steps;
  return st.recovering || st.follow_up || (!b.ctl.footwork.asked && (st.step.active || st.shifting >= 0));
}

// The foot that goes first: the one on the side the move goes (lead foot forward and left, rear foot back and right),
// so the other follows without crossing it; a pivot swings the rear foot round the lead.
int first_foot(FootworkMove m) {
  return m == FootworkMove::Forward || m == FootworkMove::Left ? 0 : 1;
}

void finish(Boxer& b, bool done) {
  FootworkState& f = b.ctl.footwork;
  if (done) ++f.moves; else ++f.dropped;
  f.move = FootworkMove::None;
  f.asked = false;
  f.turn_left = 0.0;
}

}  // namespace

bool footwork_busy(const Boxer& b) { return b.ctl.footwork.move != FootworkMove::None; }

void cancel_footwork(Boxer& b) {
  if (footwork_busy(b)) finish(b, false);
}

bool request_footwork(Boxer& b, FootworkMove m, double turn) {
  FootworkState& f = b.ctl.footwork;
  const FootworkTuning& t = b.settings.tuning.footwork;
  if (m == FootworkMove::None || footwork_busy(b) || balance_has_feet(b) || b.ctl.state.fallen() || b.limp) return false;
  f.move = m;
  f.turn_left = std::clamp(turn, -t.max_turn, t.max_turn);
  f.delta = footwork_delta(m, b.stance.heading + f.turn_left, t);
  f.first = first_foot(m);
  f.phase = 0;
  f.asked = false;
  f.started = f.clock;
  return true;
}

void footwork_turn(Boxer& b, double dt) {
  FootworkState& f = b.ctl.footwork;
  f.clock += dt;
  if (!footwork_busy(b)) return;
  if (b.ctl.state.fallen() || b.ctl.state.state == BoxerState::GettingUp || f.clock - f.started > b.settings.tuning.footwork.give_up) {
    finish(b, false);
    return;
  }
  if (f.phase != 0) return;
  // The heading turns first (the desired body turns on its planted feet; the anchor keeps them under it), at most
  // turn_rate: a pivot's upper body leads its feet.
  const double step = std::clamp(f.turn_left, -b.settings.tuning.footwork.turn_rate * dt, b.settings.tuning.footwork.turn_rate * dt);
  b.stance.heading = std::remainder(b.stance.heading + step, 2.0 * M_PI);
  f.turn_left -= step;
  if (std::abs(f.turn_left) < 1e-9) f.phase = 1;
}

void footwork_steps(const Arena& arena, Boxer& b, const Eigen::Vector2d sole[2], const Eigen::Vector2d want[2]) {
  FootworkState& f = b.ctl.footwork;
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  if (!footwork_busy(b) || f.phase == 0) return;
  if (st.recovering) {  // a push took the feet over: its recovery re-forms the stance
    finish(b, false);
    return;
  }
  if (f.asked) {
    if (st.shifting >= 0 || st.step.active) return;  // the weight shift, then the swing, under way
    f.asked = false;
    ++f.phase;
  }
  while (f.phase <= 2) {
    const int j = f.phase == 1 ? f.first : 1 - f.first, o = 1 - j;
    // The stance the desired pose has (its feet relative to each other, on the heading now), the first foot also
    // carrying the move's displacement; the second foot follows to its place beside the first.
    const Eigen::Vector2d to = sole[o] + (want[j] - want[o]) + (f.phase == 1 ? f.delta : Eigen::Vector2d::Zero());
    if ((to - sole[j]).norm() < b.settings.tuning.footwork.skip_within) {
      ++f.phase;
      continue;
    }
    if (f.phase == 1) f.goal = 0.5 * (sole[0] + sole[1]) + f.delta;  // (qp_balance.cpp support_target)
    st.shifting = j;
    st.shift_time = 0.0;
    st.return_to = to;
    st.return_duration = b.settings.tuning.footwork.swing;
    f.asked = true;
    ++f.steps;
    return;
  }
  // Done: the anchor (how far the feet carried the desired body) folded into the stance, so the walk's placement
  // starts from where the boxer stands now.
  b.stance = stance_at(arena, b.stance.position + b.ctl.anchor, b.stance.heading);
  b.ctl.anchor.setZero();
  finish(b, true);
}

}  // namespace boxing
