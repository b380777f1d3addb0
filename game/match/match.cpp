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

// Stamina (stamina.h), both boxers after the step: a clip started costs by its kind (a punch as track_punches counts
// it: standing), a footwork move started costs, and the level recovers while not punching.
void track_stamina(World& w) {
  Match& mt = *w.match;
  const StaminaTuning& tu = mt.tuning.stamina;
  for (int k = 0; k < 2; ++k) {
    Boxer& b = w.boxers[k];
    Stamina& s = mt.fighter[k].stamina;
    const eng::anim::GraphWalker* walker = b.source.walker();
    if (!walker) continue;
    const Clip& c = w.graph.clips[walker->current_clip_index()];
    const bool punching = is_punch(&c);
    if (walker->current_clip_index() != s.last_clip) {
      s.last_clip = walker->current_clip_index();
      const bool defence = c.has_tag("defence");
      if ((punching || defence) && standing_state(b.ctl.state.state)) {
        // A combination's clip counts once: counted twice (and a flurry's follow-up after it), the AI's combinations
        // took an aggressive style (seed 1) out of the band within 15 s (docs/decisions/stamina.md).
        stamina_spend(s, tu, stamina_clip_cost(s, tu, punching, 1, defence, w.data.time), punching, w.data.time);
      }
    }
    const bool moving = footwork_busy(b);
    if (moving && !s.was_moving) stamina_spend(s, tu, tu.move_cost, false, w.data.time);
    s.was_moving = moving;
    stamina_recover(s, tu, punching, kPhysicsDt);
  }
}

// Low stamina (stamina.h): the punch now playing plays slower (its clip's rate; 1 in the band, where the fight is the
// same as without stamina). Down or getting up the clips play as authored, or at the unassisted get-up plan's rate
// (getup_plan.h, set by the balance).
void set_clip_rates(World& w) {
  Match& mt = *w.match;
  for (int k = 0; k < 2; ++k) {
    Boxer& b = w.boxers[k];
    if (!standing_state(b.ctl.state.state)) {
      if (!b.settings.tuning.stand_up.unassisted) b.ctl.clip_rate = 1.0;
      continue;
    }
    b.ctl.clip_rate = is_punch(clip_of(w, b)) ? stamina_speed(mt.fighter[k].stamina, mt.tuning.stamina) : 1.0;
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
  player_press(w, k, c);
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
  mt.presses.reserve(4096);  // a long session's presses without a reallocation mid-fight
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
      player_take_input(w, k);
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
  set_clip_rates(w);
}

void match_after_step(World& w) {
  Match& mt = *w.match;
  if (!mt.active || w.boxers.size() < 2) return;
  const char* started[2];
  track_punches(w, started);
  measure_defences(w);
  track_stamina(w);
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
