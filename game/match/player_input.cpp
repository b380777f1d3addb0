#include "game/match/player_input.h"

#include <utility>

#include "engine/anim/motion_graph.h"
#include "game/footwork.h"
#include "game/match/match.h"
#include "game/match/match_internal.h"
#include "game/world.h"

namespace boxing {

namespace {

using eng::anim::Clip;

// A footwork command's move and turn (rad, + left): a pivot turns the stance by the most a move may
// (FootworkTuning::max_turn clamps it); None for the graph's commands.
std::pair<FootworkMove, double> command_move(FightCommand c) {
  constexpr double kPivot = 0.5;
  switch (c) {
    case FightCommand::StepForward: return {FootworkMove::Forward, 0.0};
    case FightCommand::StepBack: return {FootworkMove::Back, 0.0};
    case FightCommand::StepLeft: return {FootworkMove::Left, 0.0};
    case FightCommand::StepRight: return {FootworkMove::Right, 0.0};
    case FightCommand::PivotLeft: return {FootworkMove::Pivot, kPivot};
    case FightCommand::PivotRight: return {FootworkMove::Pivot, -kPivot};
    default: return {FootworkMove::None, 0.0};
  }
}

bool is_punch_command(FightCommand c) { return c >= FightCommand::Jab && c <= FightCommand::RearUppercut; }

// Why boxer k cannot take command c, now or once free (nullptr: it can).
const char* refusal(const World& w, int k, FightCommand c) {
  const Match& mt = *w.match;
  if (mt.over) return "over";
  if (mt.bout.phase != BoutPhase::Fighting) return "rest";
  const Boxer& b = w.boxers[k];
  const MatchFighter& f = mt.fighter[k];
  if (f.getup >= 0 || !standing_state(b.ctl.state.state)) return "down";
  if (f.go_to_active) return "neutral corner";  // the referee sends it there while the other is down
  if (const Clip* clip = clip_of(w, b); clip && clip->has_tag("reaction")) return "hurt";
  if (is_punch_command(c) && !stamina_can_punch(f.stamina)) return "tired";
  return nullptr;
}

// In guard with nothing under way: no blend (a forced clip's), no plan, no carried step's foot in the air, no
// footwork move. A clip started now starts from the guard's pose.
bool free_now(const World& w, int k) {
  const Boxer& b = w.boxers[k];
  const eng::anim::GraphWalker* walker = b.source.walker();
  if (!walker) return false;
  const Clip& clip = w.graph.clips[walker->current_clip_index()];
  return clip.has_tag("guard") && !walker->blending() && !walker->has_plan() && !walker->hold_transitions &&
         !footwork_busy(b);
}

void pop(PlayerQueue& q) {
  for (int i = 1; i < q.queued; ++i) q.press[i - 1] = q.press[i];
  --q.queued;
}

void refuse(World& w, int k, int press, const char* why) {
  w.match->presses[press].refused = why;
  PlayerQueue& q = w.match->fighter[k].input;
  q.notice = why;
  q.notice_at = w.data.time;
}

// Starts press i's motion now (true), or finds it cannot (false, with the reason in *why).
bool start(World& w, int k, FightCommand c, const char** why) {
  Boxer& b = w.boxers[k];
  if (const auto [move, turn] = command_move(c); move != FootworkMove::None) {
    if (request_footwork(b, move, turn)) return true;
    *why = "off balance";  // a balance step has the feet (footwork.h request_footwork)
    return false;
  }
  // The clip from the guard's pose at once (a short blend), not at the graph's next transition point.
  if (b.source.walker()->force_clip(fight_command_clip(c))) return true;
  *why = "no such move";
  return false;
}

}  // namespace

void player_press(World& w, int k, FightCommand c) {
  Match& mt = *w.match;
  MatchFighter& f = mt.fighter[k];
  f.player = true;
  if (c == FightCommand::None) return;
  PlayerPress p;
  p.t_pressed = w.data.time;
  p.action = c;
  p.boxer = k;
  const int i = static_cast<int>(mt.presses.size());
  mt.presses.push_back(p);  // (a press is an event, not a tick: capacity reserved at match_setup)
  PlayerQueue& q = f.input;
  if (const char* why = refusal(w, k, c)) {
    refuse(w, k, i, why);
    return;
  }
  int buffered = 0;
  for (int j = 0; j < q.queued; ++j) buffered += mt.presses[q.press[j]].waited == PressWait::Buffered;
  if (q.queued == 0 && free_now(w, k)) {
    mt.presses[i].waited = PressWait::Free;
  } else if (buffered < mt.tuning.input.buffer && q.queued < PlayerQueue::kMax) {
    mt.presses[i].waited = PressWait::Buffered;
  } else {
    mt.presses[i].waited = PressWait::Buffered;
    refuse(w, k, i, "busy");
    return;
  }
  q.press[q.queued++] = i;
}

void player_take_input(World& w, int k) {
  Match& mt = *w.match;
  MatchFighter& f = mt.fighter[k];
  PlayerQueue& q = f.input;
  while (q.queued > 0) {
    const int i = q.press[0];
    const FightCommand c = mt.presses[i].action;
    if (const char* why = refusal(w, k, c)) {  // can no longer start: refused now, with the reason
      refuse(w, k, i, why);
      pop(q);
      continue;
    }
    if (!free_now(w, k)) return;  // waits for the boxer to be back in guard
    const char* why = nullptr;
    if (start(w, k, c, &why)) {
      // This tick's control drives the motion: the physics tick after the press (its end) is its start.
      mt.presses[i].t_started = w.data.time + kPhysicsDt;
      ++f.commands_taken;
      f.ai.aim_body = false;
    } else {
      refuse(w, k, i, why);
    }
    pop(q);
    return;  // one motion per tick
  }
}

const char* player_notice(const World& w, int k) {
  const PlayerQueue& q = w.match->fighter[k].input;
  if (!q.notice || w.data.time - q.notice_at > w.match->tuning.input.notice_seconds) return "";
  return q.notice;
}

}  // namespace boxing
