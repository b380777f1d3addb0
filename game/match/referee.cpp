#include "game/match/referee.h"

#include <algorithm>
#include <string>

#include "game/boxer_stepping.h"
#include "game/character_builder.h"
#include "game/match/fighter_view.h"
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
  if (w.match->tuning.getup_thighs_pass)
    set_self_colliding(w.model, b.bodies, {b.bones.leg[0].thigh, b.bones.leg[1].thigh}, !on);  // add_boxer's pair
}

// How far the boxer's lowest geom point is below the crate top (or the floor) under it (m; < 0: all clear), for the
// pose in w.data.q: every box corner and the bottom of every capsule cap and sphere, against Arena::top_at there.
double deepest_below_crates(World& w, const Boxer& b) {
  eng::physics::forward_kinematics(w.model, w.data);
  double deepest = -1e9;
  auto below = [&](const Eigen::Vector3d& p) { deepest = std::max(deepest, w.arena.top_at(p.x(), p.y()) - p.z()); };
  for (size_t i = 0; i < b.bodies.first_geom.size(); ++i)
    for (int g = b.bodies.first_geom[i]; g < b.bodies.first_geom[i] + b.bodies.geom_count[i]; ++g) {
      const auto& G = w.model.geoms[g];
      const eng::physics::Pose x = w.data.x[G.body] * G.local;
      const auto& sh = G.shape;
      switch (sh.type) {
        case eng::physics::ShapeType::Box:
          for (int k = 0; k < 8; ++k) {
            const Eigen::Vector3d c((k & 1 ? 1 : -1) * sh.half_extents.x(), (k & 2 ? 1 : -1) * sh.half_extents.y(),
                                    (k & 4 ? 1 : -1) * sh.half_extents.z());
            below(x.apply(c));
          }
          break;
        case eng::physics::ShapeType::Capsule:
          for (int k = -1; k <= 1; k += 2) below(x.apply(Eigen::Vector3d(0, 0, k * sh.half_length)) - sh.radius * Eigen::Vector3d::UnitZ());
          break;
        case eng::physics::ShapeType::Sphere: below(x.p - sh.radius * Eigen::Vector3d::UnitZ()); break;
        case eng::physics::ShapeType::Plane: break;
      }
    }
  return deepest;
}

// Boxer b set at rest on its mark: its walk restarted in guard, its body on the start's pose (lifted out of any
// crate it sinks into), the placement's report in its MatchFighter.
void place_on_mark(World& w, Boxer& b, eng::anim::GraphWalker& walker) {
  // The walk starts over in guard and the body is set on its pose placed as at the start (place_boxer): the start's
  // stance on the same crates, facing the opponent. Not the desired pose moved onto the mark: its legs reach for the
  // feet where the boxer got up, and moved with it they can put the boxer down cross-legged with a foot inside a
  // crate (docs/decisions/match-fight.md).
  b.ctl.have_support_base = false;  // placed on the stance's crates (place_desired_pose), not where it got up
  walker.restart("guard");
  b.ctl.yaw_offset = 0.0;
  b.ctl.anchor.setZero();
  b.desired.pose = walker.preview(0.0);
  place_desired_pose(w.boxer_desc, w.arena, b, b.desired);
  set_character_pose(w.model, w.data, b.bodies, w.boxer_desc, b.desired.pose.root_position, b.desired.pose.rotation);
  count_teleport(w, b.index);
  // A body that starts inside a crate stays wedged in it: lifted until nothing is below the tops under it (a guard:
  // the walk's pose is placed on the crates, reset_lift reports any lift).
  const double sunk = deepest_below_crates(w, b);  // (its forward kinematics: the ankles below)
  MatchFighter& f = w.match->fighter[b.index];
  f.reset_lift = std::max(0.0, sunk);
  f.reset_feet_off = 0.0;
  for (int k = 0; k < 2; ++k)
    f.reset_feet_off = std::max(f.reset_feet_off, (w.data.x[b.bodies.body[b.bones.foot[k]]].p - b.metrics.foot0[k]).head<2>().norm());
  if (sunk > w.match->tuning.reset_clearance) {
    b.desired.pose.root_position.z() += sunk;
    set_character_pose(w.model, w.data, b.bodies, w.boxer_desc, b.desired.pose.root_position, b.desired.pose.rotation);
  }
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
  // Lying on the back: the chest's front (+X of the bone) looks up.
  const int chest = mt.bones.chest;
  const Eigen::Vector3d front = w.data.x[b.bodies.body[chest >= 0 ? chest : 0]].R * Eigen::Vector3d::UnitX();
  g.lying = front.z() > 0.0 ? "back" : "front";
  if (eng::anim::GraphWalker* walker = b.source.walker()) walker->force_clip(g.lying == "back" ? "getup_back" : "getup_front");
  b.ctl.root_spring.set_consciousness(tu.getup_consciousness);
  pass_through_opponent(w, k, true);
  boxer_state_enter(s, BoxerState::GettingUp, t, "getting up");
  // The standing boxer goes to a neutral corner, as a referee sends him (here: to its mark, a reset of that boxer
  // only): standing over the downed one, the get-up rose into him and stuck crouched.
  const Boxer& o = w.boxers[1 - k];
  const int pelvis = b.bodies.body[0];
  const Eigen::Vector3d po = w.data.x[o.bodies.body[0]].p, pk = w.data.x[pelvis].p;
  if (standing_state(o.ctl.state.state) && (po - pk).head<2>().norm() < tu.neutral_corner_within)
    back_to_marks(w, 1 - k);
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
  // Up: guard playing, the pelvis at standing height, both feet on the ground and the body settled (the QP takes
  // a boxer over only once it stands).
  const bool up = cl && cl->has_tag("guard") && pelvis_height(w, b) >= tu.up_height * s.standing_height &&
                  b.ctl.contacts.support[0] && b.ctl.contacts.support[1] && speed < tu.still_speed;
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
    back_to_marks(w);
    g.reset_lift = f.reset_lift, g.reset_feet_off = f.reset_feet_off;
  }
}

}  // namespace

// The referee brings both boxers back to their marks once the downed one is up (a reset, as a fighting game's next
// exchange: the boxers' steps do not carry them, arena.h, and a fall and get-up leave a boxer up to 0.8 m off its
// mark, out of reach). Each body is set at rest on its starting pose (the walk in guard again), controllers start over.
void back_to_marks(World& w, int only) {
  for (Boxer& b : w.boxers) {
    if (only >= 0 && b.index != only) continue;
    eng::anim::GraphWalker* walker = b.source.walker();
    if (!walker) continue;  // (the match's boxers always walk the graph)
    place_on_mark(w, b, *walker);
    for (auto& s : b.ctl.step) s.active = false;
    for (auto& g : b.ctl.gate) g = {};
    // The balance's steps start over too (a recovery, a return step's weight shift): kept across the reset, the
    // weight shift leans the boxer toward the stance it left and the AI asks for no footwork meanwhile (feet_busy),
    // and the referee resets the two for "apart" again and again (docs/decisions/footwork.md).
    b.ctl.balance_steps = {};
  }
  ++w.match->resets;
}

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
}

// Pushed apart by the punches (the feet slide; the boxers cannot step back in): the referee brings them together.
void bring_together(World& w) {
  Match& mt = *w.match;
  bool apart = standing_state(w.boxers[0].ctl.state.state) && standing_state(w.boxers[1].ctl.state.state);
  for (int k = 0; k < 2 && apart; ++k) apart = !in_range(w, k);
  // Not while a boxer presses a rocked opponent: its steps in close the gap (the stagger's 0.2-0.3 m).
  for (const MatchFighter& f : mt.fighter) apart = apart && w.data.time - f.rocked_at >= mt.tuning.press_for;
  mt.apart = apart && !mt.over ? mt.apart + kPhysicsDt : 0.0;
  if (mt.apart >= mt.tuning.apart_time) {
    back_to_marks(w);
    ++mt.apart_resets;
    mt.apart = 0.0;
  }
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
    if (s.state == BoxerState::Down && s.since == t && f.getup < 0) count_fall(mt, b, k, t);
    if (f.getup < 0) continue;
    GetUp& g = mt.getups[f.getup];
    const int pelvis = b.bodies.body[0];
    const double speed = body_velocity_at(w, pelvis, w.data.x[pelvis].p).norm();
    if (s.state == BoxerState::Down) while_down(w, k, g, speed);
    else if (s.state == BoxerState::GettingUp) while_getting_up(w, k, g, speed);
    // The count: not up in count_seconds is a knock-out.
    if (f.getup >= 0 && !mt.over && t - g.down_at > tu.count_seconds) {
      mt.over = true;
      mt.result = "KO: boxer " + std::to_string(1 - k) + " wins (boxer " + std::to_string(k) + " not up at " +
                  std::to_string(static_cast<int>(tu.count_seconds)) + ")";
    }
  }
}

}  // namespace boxing
