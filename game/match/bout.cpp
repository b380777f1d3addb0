#include "game/match/bout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "game/match/footwork_ai.h"
#include "game/match/match.h"
#include "game/world.h"

namespace boxing {

namespace {

const char* corner_name(int k) { return k == 0 ? "RED" : "BLUE"; }

// The judge's measure of one boxer's round: what it reads of that boxer's landed punches.
double judge_measure(JudgeReads what, const std::vector<PunchEvent>& events, double from, double to, int boxer) {
  double sum = 0.0;
  for (const PunchEvent& e : events) {
    if (!e.landed || e.boxer != boxer || e.t < from || e.t >= to) continue;
    sum += what == JudgeReads::Landed ? 1.0 : what == JudgeReads::Damage ? e.damage : e.impulse;
  }
  return sum;
}

bool count_under_way(const Match& mt) { return mt.fighter[0].getup >= 0 || mt.fighter[1].getup >= 0; }

// Both boxers walk to corners for the rest (the footwork AI's errand, as to a neutral corner): two diagonally opposite
// corners, the pair and who takes which chosen for the shortest walk of the two. Sent to their own posts' corners,
// boxers that had circled round each other walked into each other on the way, and one fell
// (docs/decisions/bout-rules.md).
void send_to_corners(World& w) {
  Bout& bt = w.match->bout;
  const Eigen::Vector2d half = ring_half_size(w) - Eigen::Vector2d::Constant(w.match->tuning.footwork.corner_inset);
  Eigen::Vector2d at[2];
  for (int k = 0; k < 2; ++k) at[k] = w.data.x[w.boxers[k].bodies.body[0]].p.head<2>();
  double best = 1e300;
  for (const Eigen::Vector2d& c : {Eigen::Vector2d(half.x(), half.y()), Eigen::Vector2d(half.x(), -half.y())})
    for (const double s : {1.0, -1.0}) {  // red to s c, blue to -s c
      const double walk = (at[0] - s * c).norm() + (at[1] + s * c).norm();
      if (walk >= best) continue;
      best = walk;
      bt.corner = {s * c, -s * c};
    }
  for (int k = 0; k < 2; ++k) {
    MatchFighter& f = w.match->fighter[k];
    f.go_to = bt.corner[k];
    f.go_to_active = true;
  }
}

void start_round(World& w, double t) {
  Match& mt = *w.match;
  Bout& bt = mt.bout;
  bt.phase = BoutPhase::Fighting;
  bt.phase_from = t;
  for (int k = 0; k < 2; ++k) {
    bt.landed0[k] = mt.fighter[k].landed, bt.thrown0[k] = mt.fighter[k].thrown;
    bt.knockdowns0[k] = mt.fighter[k].knockdowns;
    mt.fighter[k].go_to_active = false;
  }
}

std::string clock_text(double s) {
  char line[16];
  const int secs = static_cast<int>(std::max(0.0, s));
  std::snprintf(line, sizeof line, "%d:%02d", secs / 60, secs % 60);
  return line;
}

}  // namespace

std::array<int, 2> judge_round(JudgeReads what, const std::vector<PunchEvent>& events, double from, double to,
                               const std::array<int, 2>& knockdowns, const BoutTuning& t) {
  const double a = judge_measure(what, events, from, to, 0), b = judge_measure(what, events, from, to, 1);
  std::array<int, 2> s{10, 10};
  if (std::abs(a - b) > t.even_share * std::max(a, b)) s[a > b ? 1 : 0] = 9;
  for (int k = 0; k < 2; ++k) s[k] -= knockdowns[k];
  const int raise = 10 - std::max(s[0], s[1]);
  for (int k = 0; k < 2; ++k) s[k] = std::max(t.min_score, s[k] + raise);
  return s;
}

RoundCard score_round(const Match& mt, int round, double from, double to) {
  const Bout& bt = mt.bout;
  RoundCard c;
  c.round = round, c.from_s = from, c.to_s = to;
  for (int k = 0; k < 2; ++k) {
    c.landed[k] = mt.fighter[k].landed - bt.landed0[k];
    c.thrown[k] = mt.fighter[k].thrown - bt.thrown0[k];
    c.knockdowns[k] = mt.fighter[k].knockdowns - bt.knockdowns0[k];
  }
  for (size_t j = 0; j < kJudges.size(); ++j) c.judges[j] = judge_round(kJudges[j], mt.events, from, to, c.knockdowns, bt.tuning);
  return c;
}

std::array<int, 3> decide(const std::vector<RoundCard>& cards) {
  std::array<int, 3> out{-1, 0, 0};
  for (size_t j = 0; j < kJudges.size(); ++j) {
    int red = 0, blue = 0;
    for (const RoundCard& c : cards) red += c.judges[j][0], blue += c.judges[j][1];
    if (red != blue) ++out[red > blue ? 1 : 2];
  }
  // A majority of the judges (two of three) names the winner; otherwise a draw (split or majority).
  for (int k = 0; k < 2; ++k)
    if (2 * out[1 + k] > static_cast<int>(kJudges.size())) out[0] = k;
  return out;
}

void bout_setup(World& w) {
  Bout& bt = w.match->bout;
  bt = Bout{};
  bt.tuning.rounds = w.options.rounds;
  bt.round_seconds = w.options.round_seconds;
  bt.tuning.rest_seconds = w.options.rest_seconds;
}

void bout_end(World& w, int winner, const char* method) {
  Match& mt = *w.match;
  Bout& bt = mt.bout;
  const double t = w.data.time;
  mt.over = true;
  bt.phase = BoutPhase::Over;
  BoutResult& r = bt.result;
  r.winner = winner;
  r.method = method;
  r.round = bt.round;
  r.time_s = t - bt.phase_from;
  // The last round's card, to the stoppage (a KO or TKO ends the round; a decision scored it at the bell).
  if (bt.cards.empty() || bt.cards.back().round != bt.round) bt.cards.push_back(score_round(mt, bt.round, bt.phase_from, t));
  std::string how = r.method == "ko" ? "BY KO" : r.method == "tko" ? "BY TKO" : "ON POINTS";
  r.text = winner < 0 ? "DRAW" : std::string(corner_name(winner)) + " WINS " + how;
  if (r.method == "ko" || r.method == "tko") r.text += " IN ROUND " + std::to_string(r.round) + " (" + clock_text(r.time_s) + ")";
}

void bout_tick(World& w) {
  Match& mt = *w.match;
  Bout& bt = mt.bout;
  if (mt.over || w.boxers.size() < 2) return;
  const double t = w.data.time;
  if (bt.phase == BoutPhase::Fighting) {
    for (int k = 0; k < 2; ++k)
      if (mt.fighter[k].knockdowns - bt.knockdowns0[k] >= bt.tuning.tko_knockdowns) {
        bout_end(w, 1 - k, "tko");
        return;
      }
    // The bell: a knockdown's count under way is finished first (the count decides, not the clock).
    if (t + 1e-9 >= bt.phase_from + bt.round_seconds && !count_under_way(mt)) {
      bt.cards.push_back(score_round(mt, bt.round, bt.phase_from, t));
      if (bt.round >= bt.tuning.rounds) {
        const std::array<int, 3> d = decide(bt.cards);
        bout_end(w, d[0], d[0] < 0 ? "draw" : "decision");
        return;
      }
      bt.phase = BoutPhase::Rest;
      bt.phase_from = t;
      send_to_corners(w);
    }
  } else if (bt.phase == BoutPhase::Rest && t + 1e-9 >= bt.phase_from + bt.tuning.rest_seconds) {
    // The corner's work: back part of what the rounds took (BoutTuning::rest_recovery).
    for (Boxer& b : w.boxers) {
      const double c = b.ctl.root_spring.consciousness();
      b.ctl.root_spring.set_consciousness(c + bt.tuning.rest_recovery * (1.0 - c));
    }
    ++bt.round;
    start_round(w, t);
  }
}

double bout_clock_left(const World& w) {
  const Bout& bt = w.match->bout;
  const double t = w.data.time;
  if (bt.phase == BoutPhase::Rest) return std::max(0.0, bt.phase_from + bt.tuning.rest_seconds - t);
  if (bt.phase == BoutPhase::Over) return std::max(0.0, bt.round_seconds - bt.result.time_s);
  return std::max(0.0, bt.phase_from + bt.round_seconds - t);
}

}  // namespace boxing
