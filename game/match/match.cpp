#include "game/match/match.h"

#include <algorithm>
#include <utility>

#include "engine/anim/motion_graph.h"
#include "game/footwork.h"
#include "game/character_builder.h"
#include "game/match/hits.h"
#include "game/match/match_internal.h"
#include "game/world.h"

namespace boxing {

namespace {

using eng::anim::Clip;

// A footwork command's move and turn (rad, + left): a pivot turns the stance by the most a move may
// (FootworkTuning::max_turn clamps it); None for the graph's commands.
std::pair<FootworkMove, double> fight_command_move(FightCommand c) {
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

// The player's next command, taken when the boxer stands and the walk is free of a plan (a punch asked for during
// another is taken once that one lets the graph go, like a buffered input in a fighting game).
void take_player_command(MatchFighter& f, Boxer& b, eng::anim::GraphWalker& walker, bool can) {
  if (f.queued > 0 && can && !walker.has_plan()) {
    // Steps are footwork moves (footwork.h: the balance steps carry the feet); the rest are the graph's clips.
    const FightCommand c = f.commands[0];
    if (const auto [move, turn] = fight_command_move(c); move != FootworkMove::None) {
      if (footwork_busy(b)) return;  // (kept queued until the move under way ends)
      if (request_footwork(b, move, turn)) ++f.commands_taken;
    } else if (walker.request_clip(fight_command_clip(c))) {
      ++f.commands_taken;
    }
    f.ai.aim_body = false;
    std::copy(f.commands.begin() + 1, f.commands.end(), f.commands.begin());
    --f.queued;
  }
}

}  // namespace

const char* fight_command_clip(FightCommand c) {
  switch (c) {
    case FightCommand::None: return "";
    case FightCommand::Jab: return "jab";
    case FightCommand::Cross: return "cross";
    case FightCommand::LeadHook: return "lead_hook";
    case FightCommand::RearHook: return "rear_hook";
    case FightCommand::LeadUppercut: return "lead_uppercut";
    case FightCommand::RearUppercut: return "rear_uppercut";
    case FightCommand::Block: return "block_high";
    case FightCommand::SlipLeft: return "slip_left";
    case FightCommand::SlipRight: return "slip_right";
    case FightCommand::Duck: return "duck";
    case FightCommand::StepForward: return "step_forward";
    case FightCommand::StepBack: return "step_back";
    case FightCommand::StepLeft: return "step_left";
    case FightCommand::StepRight: return "step_right";
    case FightCommand::PivotLeft: return "pivot_left";
    case FightCommand::PivotRight: return "pivot_right";
  }
  return "";
}

void match_command(World& w, int k, FightCommand c) {
  if (!w.match->active || k < 0 || k > 1) return;
  MatchFighter& f = w.match->fighter[k];
  f.player = true;
  if (c != FightCommand::None && f.queued < MatchFighter::kCommandBuffer) f.commands[f.queued++] = c;
}

void match_setup(World& w) {
  Match& mt = *w.match;
  mt.active = true;
  mt.owners = body_owners(static_cast<int>(w.model.bodies.size()), w.boxers, w.boxer_desc.skeleton);
  const auto& skel = w.boxer_desc.skeleton;
  mt.bones.head = skel.find("head");
  mt.bones.chest = skel.find("chest");
  mt.bones.glove[0] = skel.find("glove_l"), mt.bones.glove[1] = skel.find("glove_r");
  mt.bones.forearm[0] = skel.find("forearm_l"), mt.bones.forearm[1] = skel.find("forearm_r");
  mt.bones.upper_arm[0] = skel.find("upper_arm_l"), mt.bones.upper_arm[1] = skel.find("upper_arm_r");
  mt.replay.init(static_cast<int>(kReplaySeconds * 60.0), static_cast<int>(w.data.q.size()));
  for (int k = 0; k < 2 && k < static_cast<int>(w.boxers.size()); ++k) {
    MatchFighter& f = mt.fighter[k];
    f.ai.rng = Rng(w.options.seed * 0x9E3779B97F4A7C15ull + 0xF16A7ull + static_cast<uint64_t>(k));
    apply_ai_level(f.ai.tuning, w.options.ai[k]);  // the CLI checked the level; normal changes nothing
    f.ai.style = draw_fighter_style(f.ai.rng, f.ai.tuning);
    // Both settle into guard first.
    f.ai.next_attack = f.ai.tuning.first_attack + f.ai.rng.uniform(0.0, f.ai.tuning.first_attack_spread);
    f.player = w.options.player == k || w.options.mode == "versus";  // versus: both are players' (front_end.h)
    Boxer& b = w.boxers[k];
    // The AI (or the player) decides what is thrown: the walk takes no random transition (a punch, a slip) of its own
    // and guard loops until asked for something else; continuations, hits and knockdowns go on as in any walk.
    if (eng::anim::GraphWalker* walker = b.source.walker()) {
      walker->transition_probability = 0.0;
      walker->loop_probability = 1.0;
    }
    // No leash: the AI keeps the distance (its steps, like the leash's, move the clip, not the feet: arena.h).
    b.source.set_leash(1e9);
    // Consciousness: the match decides knockdowns (no outright knock-out threshold); recovery is slow, so damage
    // accumulates over a round.
    b.settings.root_params.knockout_threshold = 1e9;
    b.settings.root_params.stun_time = mt.tuning.recovery_delay;
    b.settings.root_params.recovery_rate = mt.tuning.recovery_rate;
    b.settings.tuning.balance_step.replace_edge_foot = mt.tuning.replace_edge_feet;
    // The legs collide with each other whole (add_boxer: the thighs only): in the ring's footwork the shanks and feet
    // passed through each other (legs_through_s).
    set_self_colliding(w.model, b.bodies, {b.bones.leg[0].shank, b.bones.leg[1].shank, b.bones.leg[0].foot,
                                           b.bones.leg[1].foot});
    // The fight's balance: Kudoh's priorities, the trunk held upright over the com (balance_qp.h BalanceQpTuning).
    if (w.options.priorities != "off") {
      b.settings.tuning.qp.trunk_weight = mt.tuning.trunk_weight;
      b.settings.tuning.qp.com_weight = mt.tuning.com_weight;
    }
  }
  footwork_setup(w);
  bout_setup(w);
}

void match_before_control(World& w) {
  Match& mt = *w.match;
  if (!mt.active || w.boxers.size() < 2) return;
  for (int k = 0; k < 2; ++k) {
    Boxer& b = w.boxers[k];
    MatchFighter& f = mt.fighter[k];
    eng::anim::GraphWalker* walker = b.source.walker();
    if (!walker) continue;
    const Clip& c = w.graph.clips[walker->current_clip_index()];
    const bool standing = standing_state(b.ctl.state.state);
    aim_punch(w, k, c, standing);
    if (f.player) {
      take_player_command(f, b, *walker, standing && mt.bout.phase == BoutPhase::Fighting);
      if (f.go_to_active) footwork_ai_tick(w, k, standing && !walker->has_plan(), false);  // the referee's errand
      continue;
    }
    if (mt.over) continue;
    if (mt.bout.phase == BoutPhase::Rest) {  // to the corner, no punches
      if (f.go_to_active) footwork_ai_tick(w, k, standing && !walker->has_plan(), false);
      continue;
    }
    const FighterView v = fighter_view(w, k, c, standing);
    f.saw_punch = nullptr;
    if (v.punching) f.punching_until = w.data.time;
    const bool just_punched = !v.punching && w.data.time - f.punching_until < mt.tuning.footwork.exit_within;
    // A boxer that has stood still too long moves its feet first; otherwise punches and defences first (the graph
    // takes a request when it can), and the feet move when nothing was asked for.
    if (footwork_restless(w, k) && footwork_ai_tick(w, k, v.free, just_punched)) continue;
    fighter_ai_tick(f.ai, *walker, v, kPhysicsDt);
    if (!walker->has_plan()) footwork_ai_tick(w, k, v.free, just_punched);
  }
}

void match_after_step(World& w) {
  Match& mt = *w.match;
  if (!mt.active || w.boxers.size() < 2) return;
  const char* started[2];
  track_punches(w, started);
  measure_defences(w);
  for (int k = 0; k < 2; ++k) mt.fighter[1 - k].saw_punch = started[k];
  if ((w.steps + 1) % kStepsPerFrame == 0) mt.replay.record(w.data.q, w.data.time);  // one per 60 Hz frame
  track_peak_speed(w);
  read_hits(w);
  count_balance_steps_after_hit(w);
  referee(w);
  measure_clinch(w);
  bout_tick(w);
  measure_footwork(w);
}

}  // namespace boxing
