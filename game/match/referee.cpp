#include "game/match/referee.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "game/boxer_stepping.h"
#include "game/character_builder.h"
#include "game/getup_metrics.h"
#include "game/match/fighter_view.h"
#include "game/match/footwork_ai.h"
#include "game/match/footwork_metrics.h"
#include "game/match/match.h"
#include "game/match/match_internal.h"

namespace boxing {

namespace {

using eng::anim::Clip;

// The pelvis over the ground under the feet now (the lower of the two tops: a boxer knocked off the platform
// stands up on the floor, 0.3 m below its stance's crates, and is up all the same).
double pelvis_height(const World& w, const Boxer& b) {
  double ground = 1e9;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d& p = w.data.x[b.bodies.body[b.bones.foot[k]]].p;
    ground = std::min(ground, w.arena.top_at(p.x(), p.y()));
  }
  return w.data.x[b.bodies.body[0]].p.z() - ground;
}

GetUp down_at(int boxer, double t) {
  GetUp g;
  g.boxer = boxer;
  g.down_at = t;
  return g;
}

// Boxer k's legs pass through each other (on) or collide again (match_setup's leg pairs).
void legs_pass(World& w, int k, bool on) {
  const Boxer& b = w.boxers[k];
  if (w.match->tuning.getup_thighs_pass)
    set_self_colliding(w.model, b.bodies, {b.bones.leg[0].thigh, b.bones.leg[1].thigh, b.bones.leg[0].shank,
                                           b.bones.leg[1].shank, b.bones.leg[0].foot, b.bones.leg[1].foot},
                       !on);
}

// A boxer getting up passes through its opponent (its geoms' collision mask leaves the other boxer's group out):
// rising where it fell, into a standing opponent, it stuck crouched against him and was counted out
// (docs/decisions/match-fight.md). Nobody punches a downed boxer, so no hit is lost. Its thighs pass through each
// other too (getup_thighs_pass). World::model's masks and self-collision flags are read by every step's collision.
void pass_through_opponent(World& w, int k, bool on) {
  const Boxer& b = w.boxers[k];
  const uint32_t other_group = 2u << w.boxers[1 - k].index;  // add_boxer's group
  for (size_t i = 0; i < b.bodies.first_geom.size(); ++i)
    for (int g = b.bodies.first_geom[i]; g < b.bodies.first_geom[i] + b.bodies.geom_count[i]; ++g)
      w.model.geoms[g].mask = on ? ~other_group : 0xffffffffu;
  legs_pass(w, k, on);
}

// The get-up starts where the body lies: the stance re-based under it, so the stand-up clip is placed at the pelvis
// (kept where it was, the clip's placement would be up to a metre away and the root assist would haul the body there).
void rise_where_lying(World& w, Boxer& b) {
  eng::anim::GraphWalker* walker = b.source.walker();
  if (!walker) return;
  const eng::anim::Pose& p0 = walker->preview(0.0);  // the stand-up's first frame, in the clip's frame
  const Eigen::Rotation2Dd R(b.stance.heading + b.ctl.yaw_offset);
  const Eigen::Vector2d clip = R * (p0.root_position.head<2>() + Eigen::Vector2d(b.settings.tuning.stance.clip_forward, 0.0));
  const Eigen::Vector2d pelvis = w.data.x[b.bodies.body[0]].p.head<2>();
  b.stance = stance_at(w.arena, pelvis - clip - b.ctl.anchor, b.stance.heading);
}

// The standing boxer goes to a neutral corner while the other is down (the referee's order; standing over the downed
// one, a get-up rises into him). It walks there (footwork_ai.h).
void send_to_neutral_corner(World& w, int standing) {
  MatchFighter& f = w.match->fighter[standing];
  f.go_to = neutral_corner(w, standing);
  f.go_to_active = true;
}

// Consciousness low: stunned (softer gains); back over stun_below + unstun_margin: in guard again.
void update_stun(Boxer& b, const MatchTuning& tu, double t) {
  BoxerStateMachine& s = b.ctl.state;
  const double c = b.ctl.root_spring.consciousness();
  if (s.state == BoxerState::Guard && c < tu.stun_below) {
    boxer_state_enter(s, BoxerState::Stunned, t, "consciousness low");
    b.ctl.gain_scale = tu.stunned_gain_scale;
  } else if (s.state == BoxerState::Stunned && c >= tu.stun_below + tu.unstun_margin) {
    boxer_state_enter(s, BoxerState::Guard, t, "recovered");
    b.ctl.gain_scale = 1.0;
  }
}

// A fall the match did not call (detected Down from Guard / Stunned this tick): a knockdown if a landed hit came
// within fall_after_hit_window, else a fall without a hit; either way a GetUp for the count.
void count_fall(Match& mt, Boxer& b, int k, double t) {
  MatchFighter& f = mt.fighter[k];
  if (t - f.last_hit_at > mt.tuning.fall_after_hit_window) {
    ++f.falls_without_hit;
  } else {
    ++f.knockdowns;
    ++f.falls_after_hit;
  }
  f.getup = static_cast<int>(mt.getups.size());
  mt.getups.push_back(down_at(k, t));
  b.ctl.root_spring.set_consciousness(0.0);
  f.still = 0.0;
}

// Down: lying still long enough, the stand-up starts (chosen from the lying pose). Also after a knock-out: the
// beaten boxer comes round and stands, the fight does not go on; the chaos soak's falls after it end in get-ups too.
void while_down(World& w, int k, GetUp& g, double speed) {
  Match& mt = *w.match;
  const MatchTuning& tu = mt.tuning;
  Boxer& b = w.boxers[k];
  MatchFighter& f = mt.fighter[k];
  BoxerStateMachine& s = b.ctl.state;
  const double t = w.data.time, dt = kPhysicsDt;
  f.still = speed < tu.still_speed ? f.still + dt : 0.0;
  if (!(f.still >= tu.still_time && t - g.down_at >= tu.min_down_time)) return;
  g.lying = lying_of(w, b);
  if (eng::anim::GraphWalker* walker = b.source.walker()) walker->force_clip(g.lying == "back" ? "getup_back" : "getup_front");
  b.ctl.root_spring.set_consciousness(tu.getup_consciousness);
  pass_through_opponent(w, k, true);
  boxer_state_enter(s, BoxerState::GettingUp, t, "getting up");
  rise_where_lying(w, b);
}

// Getting up: the root assist summed; up (guard playing, pelvis at standing height, both feet on the ground,
// settled) long enough, the fight goes on from the marks; too long without getting up, the stand-up is given up.
void while_getting_up(World& w, int k, GetUp& g, double speed) {
  Match& mt = *w.match;
  const MatchTuning& tu = mt.tuning;
  Boxer& b = w.boxers[k];
  MatchFighter& f = mt.fighter[k];
  BoxerStateMachine& s = b.ctl.state;
  const double t = w.data.time, dt = kPhysicsDt;
  g.assist_sq_dt += b.ctl.root_torque.squaredNorm() * dt;
  g.assist_force_sq_dt += b.ctl.root_force.squaredNorm() * dt;
  g.assist_time += dt;
  const Clip* cl = clip_of(w, b);
  // Up: guard playing, the pelvis at standing height, both feet on the ground, the body settled (the QP takes a
  // boxer over only once it stands), and the legs out of each other. They pass through each other while it rises
  // (pass_through_opponent); risen with them crossed, they collide again and push apart before the fight goes on.
  const bool risen = cl && cl->has_tag("guard") && pelvis_height(w, b) >= tu.up_height * s.standing_height &&
                     b.ctl.contacts.support[0] && b.ctl.contacts.support[1] && speed < tu.still_speed;
  const bool legs_apart = legs_overlap(w, k) <= mt.footwork_tuning.legs_through;
  if (risen && !legs_apart) legs_pass(w, k, false);
  const bool up = risen && legs_apart;
  f.settled = up ? f.settled + dt : 0.0;
  if (f.settled <= 0.0 && t - s.since > tu.stand_up_give_up) {
    // Given up: down again, limp; lying still, while_down starts the stand-up anew (the same GetUp: its assist time
    // and the count run on).
    boxer_state_enter(s, BoxerState::Down, t, "stand-up given up");
    b.ctl.root_spring.set_consciousness(0.0);
    f.still = 0.0;
    ++g.retries;
  } else if (f.settled >= tu.settle_time) {
    boxer_state_enter(s, BoxerState::Guard, t, "up");
    b.ctl.gain_scale = 1.0;
    g.up_at = t;
    f.getup = -1;
    // Up inside the count: the referee lets the boxer fight on, clear-headed enough not to be stunned (stunned and
    // set on its mark, a boxer fell again within seconds with no punch on it).
    b.ctl.root_spring.set_consciousness(std::max(b.ctl.root_spring.consciousness(), tu.after_count));
    pass_through_opponent(w, k, false);
    mt.fighter[1 - k].go_to_active = false;  // the fight goes on from where both stand
  }
}

}  // namespace

void knock_down(World& w, int k, const Eigen::Vector3d& push_dir, const char* reason) {
  Boxer& b = w.boxers[k];
  MatchFighter& f = w.match->fighter[k];
  const double t = w.data.time;
  // Backward when the push goes against the boxer's facing (a punch to the face), forward otherwise (a body shot
  // folds the boxer over it, a push from behind).
  const bool back = push_dir.head<2>().dot(facing(w, b)) < 0.0;
  if (eng::anim::GraphWalker* walker = b.source.walker()) walker->force_clip(back ? "fall_back" : "fall_forward");
  b.ctl.root_spring.set_consciousness(0.0);
  b.ctl.gain_scale = w.match->tuning.stunned_gain_scale;
  boxer_state_enter(b.ctl.state, BoxerState::Falling, t, reason);
  ++f.knockdowns;
  f.getup = static_cast<int>(w.match->getups.size());
  w.match->getups.push_back(down_at(k, t));
  f.still = 0.0;
  send_to_neutral_corner(w, 1 - k);
}

void referee(World& w) {
  Match& mt = *w.match;
  const MatchTuning& tu = mt.tuning;
  const double t = w.data.time;
  for (int k = 0; k < 2; ++k) {
    Boxer& b = w.boxers[k];
    MatchFighter& f = mt.fighter[k];
    const BoxerStateMachine& s = b.ctl.state;
    update_stun(b, tu, t);
    if (s.state == BoxerState::Down && s.since == t && f.getup < 0) {
      count_fall(mt, b, k, t);
      send_to_neutral_corner(w, 1 - k);
    }
    if (f.getup < 0) continue;
    GetUp& g = mt.getups[f.getup];
    const int pelvis = b.bodies.body[0];
    const double speed = body_velocity_at(w, pelvis, w.data.x[pelvis].p).norm();
    if (s.state == BoxerState::Down) while_down(w, k, g, speed);
    else if (s.state == BoxerState::GettingUp) while_getting_up(w, k, g, speed);
    if (f.getup < 0) continue;  // up this tick
    // The count, once the downed boxer is on the canvas (a fall carries the pelvis along). It runs only while the
    // standing boxer keeps count_when_away from the downed one; closer, the referee stops counting until he is back
    // in his corner, as the professional rules have it (docs/decisions/count-distance.md). Not up in count_seconds
    // of counting: a knock-out.
    g.counting = false;
    if (s.state != BoxerState::Falling && !mt.over) {
      const double apart = (w.data.x[pelvis].p - w.data.x[w.boxers[1 - k].bodies.body[0]].p).head<2>().norm();
      if (apart >= tu.count_when_away) {
        g.counting = true;
        if (g.count_from < 0.0) g.count_from = t;
        else ++g.counted_ticks;
      } else if (g.count_from >= 0.0) {
        ++g.paused_ticks;
      }
    }
    if (!mt.over && g.counted_ticks > std::lround(tu.count_seconds / kPhysicsDt)) {
      bout_end(w, 1 - k, "ko");
    }
  }
}

}  // namespace boxing
