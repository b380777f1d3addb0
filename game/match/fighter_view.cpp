#include "game/match/fighter_view.h"

#include <cmath>

#include "game/boxer_stepping.h"
#include "game/footwork.h"
#include "game/match/match.h"
#include "game/match/match_internal.h"
#include "game/match/punch_aim.h"

namespace boxing {

using eng::anim::Clip;

Eigen::Vector2d facing(const World& w, const Boxer& b) {
  const Eigen::Vector3d f = w.data.x[b.bodies.body[0]].R * Eigen::Vector3d::UnitX();
  const Eigen::Vector2d h = f.head<2>();
  return h.norm() > 1e-6 ? Eigen::Vector2d(h.normalized()) : Eigen::Vector2d(std::cos(b.stance.heading), std::sin(b.stance.heading));
}

double reach_distance(const World& w, int k) {
  const MatchBones& mb = w.match->bones;
  return (bone_centre(w, w.boxers[1 - k], mb.head) - bone_centre(w, w.boxers[k], mb.chest)).head<2>().norm();
}

bool in_range(const World& w, int k) {
  const MatchTuning& tu = w.match->tuning;
  return reach_distance(w, k) < tu.reach + tu.in_range_margin;
}

// The aim: the punch playing bends the striking arm onto the opponent's head or torso, through it by aim_through
// (the servo lags its target: aimed at the surface, the glove would arrive slow).
void aim_punch(World& w, int k, const Clip& c, bool standing) {
  Match& mt = *w.match;
  Boxer& b = w.boxers[k];
  const Boxer& o = w.boxers[1 - k];
  const MatchFighter& f = mt.fighter[k];
  const eng::anim::GraphWalker* walker = b.source.walker();
  b.ctl.aim.active = standing && is_punch(&c) && f.open_punch >= 0 && f.aim_bone >= 0;
  if (!b.ctl.aim.active) return;
  const auto& xt = w.data.x[o.bodies.body[f.aim_bone]];
  b.ctl.aim.glove = c.glove;
  // A tired boxer's arm is slower and weaker (stamina.h: x1 in the band): its servo frequency, the strike's speed.
  const double tired = stamina_speed(f.stamina, mt.tuning.stamina);
  b.ctl.aim.arm_gain = mt.tuning.punch_arm_gain * tired;
  b.ctl.aim.target = xt.p + xt.R * (f.aim_local + mt.tuning.aim_through * f.aim_dir_local);
  b.ctl.aim.weight = aim_weight(walker->clip_time(), c.impact_time, c.duration());
  // The strike drives the glove in until its first touch (of anything); from there the arm's momentum and the bent
  // pose carry it: driven on, the task pushes on into the head (impulses up to twice a power punch's).
  const bool touched = !mt.events[f.open_punch].hit_part.empty();
  b.ctl.aim.strike = touched ? 0.0 : strike_weight(walker->clip_time(), c.impact_time, mt.tuning.strike_follow);
  b.ctl.aim.strike_speed = mt.tuning.strike_speed * tired;
  b.ctl.aim.strike_rate = mt.tuning.strike_rate;
  b.ctl.aim.strike_omega = mt.tuning.strike_omega;
  b.ctl.aim.strike_weight = mt.tuning.strike_weight;
}

FighterView fighter_view(const World& w, int k, const Clip& c, bool standing) {
  const Match& mt = *w.match;
  const Boxer& b = w.boxers[k];
  const Boxer& o = w.boxers[1 - k];
  const MatchFighter& f = mt.fighter[k];
  const double t = w.data.time;
  FighterView v;
  v.time = t;
  v.punching = is_punch(&c);
  // A footwork move under way (footwork.h) holds the punches until its feet are down.
  v.free = standing && !b.source.walker()->has_plan() && c.has_tag("guard") && !footwork_busy(b);
  // Distance: the opponent's head from this boxer's chest, on the floor. A straight punch puts the glove's centre
  // about MatchTuning::reach ahead of the chest at full extension; in range within a head's depth of that.
  const double dist = reach_distance(w, k);
  const bool opponent_up = standing_state(o.ctl.state.state);  // no hitting a downed man
  v.in_range = dist < mt.tuning.reach + mt.tuning.in_range_margin && opponent_up;
  // A boxer just hit gathers itself before it steps in: the step's lean on legs still taking the hit floors it
  // (docs/decisions/match-fight.md).
  v.too_far = dist > mt.tuning.reach + mt.tuning.too_far_margin && opponent_up &&
              t - f.last_hit_at > mt.tuning.step_in_after_hit;
  v.too_close = dist < mt.tuning.reach - mt.tuning.too_close_margin;
  v.press = t - mt.fighter[1 - k].rocked_at < mt.tuning.press_for;
  // A balance step, its settling or its return under way (balance_step.h phases 1-3), or a stance the body cannot
  // fight from: the feet are the balance's, and the AI asks for no footwork (fighter_ai.h).
  const auto& bst = b.ctl.balance_steps;
  v.feet_busy = bst.step.active || bst.recovering || bst.shifting >= 0 || footwork_busy(b) || !stance_can_fight(w.data, b);
  v.other_started = f.saw_punch;
  const MatchFighter& fo = mt.fighter[1 - k];
  if (f.saw_punch && fo.open_punch >= 0) v.other_to_body = mt.events[fo.open_punch].target == "torso";
  v.can_defend = standing && c.has_tag("guard") && !footwork_busy(b);
  // The other's last punch, over and not landed (the events are in time order: the last of his is the nearest).
  if (fo.open_punch < 0 && fo.thrown > 0)
    for (int i = static_cast<int>(mt.events.size()) - 1; i >= 0; --i)
      if (mt.events[i].boxer == 1 - k) {
        if (!mt.events[i].landed) v.other_missed = i;
        break;
      }
  v.slow = b.ctl.state.state == BoxerState::Stunned ? mt.tuning.stunned_attack_scale : 1.0;
  return v;
}

}  // namespace boxing
