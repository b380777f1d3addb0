#include "game/match/match.h"

#include <algorithm>
#include <cmath>

#include "engine/anim/motion_graph.h"
#include "engine/physics/dynamics.h"
#include "game/boxer_stepping.h"
#include "game/character_builder.h"
#include "game/match/punch_aim.h"
#include "game/world.h"

namespace boxing {

namespace {

using eng::anim::Clip;

constexpr double kFallWithoutHitWindow = 1.5;  // s: a fall this long after a landed hit is the hit's (issue 15)
// m: punches aim this far THROUGH the target's centre (a boxer hits through the target: the glove meets it while
// still accelerating, not at the end of its reach where it has slowed to a stop).
constexpr double kAimThrough = 0.2;
// m: a straight punch's glove centre ahead of the chest at full extension (measured from the desired pose at the
// jab's impact frame: 0.74 m).
constexpr double kReach = 0.74;
// In range within a head's depth of the reach. Out of range both ways is "apart" for the referee: the same bound, or
// boxers hovering between the two (seed 12: 0.86-0.87 m for 110 s) neither punch nor get brought together.
constexpr double kInRange = kReach + 0.08;
// m: a boxer set back on its mark is lifted when a body sinks deeper than this into the crates under it.
constexpr double kResetClearance = 0.03;

const Clip* clip_of(const World& w, const Boxer& b) {
  const eng::anim::GraphWalker* walker = b.source.walker();
  return walker ? &w.graph.clips[walker->current_clip_index()] : nullptr;
}

bool is_punch(const Clip* c) { return c && c->has_tag("punch") && c->glove >= 0; }

// A bone's centre of mass in the world (m).
Eigen::Vector3d bone_centre(const World& w, const Boxer& b, int bone) {
  const auto& x = w.data.x[b.bodies.body[bone]];
  return x.p + x.R * w.boxer_desc.bones[bone].com;
}

Eigen::Vector3d body_velocity_at(const World& w, int body, const Eigen::Vector3d& p) {
  return eng::physics::point_velocity(w.data, body, p);
}

// The boxer's facing in the world (the pelvis's forward axis, +X of the bone, on the floor; unit).
Eigen::Vector2d facing(const World& w, const Boxer& b) {
  const Eigen::Vector3d f = w.data.x[b.bodies.body[0]].R * Eigen::Vector3d::UnitX();
  const Eigen::Vector2d h = f.head<2>();
  return h.norm() > 1e-6 ? Eigen::Vector2d(h.normalized()) : Eigen::Vector2d(std::cos(b.stance.heading), std::sin(b.stance.heading));
}

// The other boxer's head from boxer k's chest, on the floor (m): the AI's range and the referee's "apart".
double reach_distance(const World& w, int k) {
  const MatchBones& mb = w.match.bones;
  return (bone_centre(w, w.boxers[1 - k], mb.head) - bone_centre(w, w.boxers[k], mb.chest)).head<2>().norm();
}

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

bool standing_state(BoxerState s) { return s == BoxerState::Guard || s == BoxerState::Stunned; }

void knock_down(World& w, int k, const Eigen::Vector3d& push_dir, const char* reason) {
  Boxer& b = w.boxers[k];
  MatchFighter& f = w.match.fighter[k];
  const double t = w.data.time;
  // Backward when the push goes against the boxer's facing (a punch to the face), forward otherwise (a body shot
  // folds the boxer over it, a push from behind).
  const bool back = push_dir.head<2>().dot(facing(w, b)) < 0.0;
  if (eng::anim::GraphWalker* walker = b.source.walker()) walker->force_clip(back ? "fall_back" : "fall_forward");
  b.ctl.root_spring.set_consciousness(0.0);
  b.ctl.gain_scale = w.match.tuning.stunned_gain_scale;
  boxer_state_enter(b.ctl.state, BoxerState::Falling, t, reason);
  ++f.knockdowns;
  f.getup = static_cast<int>(w.match.getups.size());
  w.match.getups.push_back(down_at(k, t));
  f.still = 0.0;
}

// A boxer getting up passes through its opponent (its geoms' collision mask leaves the other boxer's group out):
// rising where it fell, into a standing opponent, it stuck crouched against him (seeds 2, 7, 9: not up in 10 s).
// Nobody punches a downed boxer, so no hit is lost. Its thighs pass through each other too (getup_thighs_pass).
// World::model's masks and self-collision flags are read by every step's collision.
void pass_through_opponent(World& w, int k, bool on) {
  const Boxer& b = w.boxers[k];
  const uint32_t other_group = 2u << w.boxers[1 - k].index;  // add_boxer's group
  for (size_t i = 0; i < b.bodies.first_geom.size(); ++i)
    for (int g = b.bodies.first_geom[i]; g < b.bodies.first_geom[i] + b.bodies.geom_count[i]; ++g)
      w.model.geoms[g].mask = on ? ~other_group : 0xffffffffu;
  if (w.match.tuning.getup_thighs_pass)
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

}  // namespace

// The referee brings both boxers back to their marks once the downed one is up (a reset, as a fighting game's next
// exchange: the boxers' steps do not carry them, arena.h, and a fall and get-up leave a boxer up to 0.8 m off its
// mark, out of reach). Each body is set at rest on its starting pose (the walk in guard again), controllers start over.
void back_to_marks(World& w, int only) {
  for (Boxer& b : w.boxers) {
    if (only >= 0 && b.index != only) continue;
    eng::anim::GraphWalker* walker = b.source.walker();
    if (!walker) continue;  // (the match's boxers always walk the graph)
    // The walk starts over in guard and the body is set on its pose placed as at the start (place_boxer): the start's
    // stance on the same crates, facing the opponent. Why not the desired pose moved onto the mark: its legs reach for
    // the feet where the boxer got up, and turned and moved with it they put seed 5's red down cross-legged, a foot
    // 21 cm inside a crate (lifted out, it sank and fell 1 s later with no punch on it); the clip's legs at the clip's
    // time placed by the foot line turned the pelvis up to 25 deg off the opponent (docs/decisions/match-fight.md).
    b.ctl.have_support_base = false;  // placed on the stance's crates (place_desired_pose), not where it got up
    walker->restart("guard");
    b.ctl.yaw_offset = 0.0;
    b.ctl.anchor.setZero();
    b.desired.pose = walker->preview(0.0);
    place_desired_pose(w.boxer_desc, w.arena, b, b.desired);
    set_character_pose(w.model, w.data, b.bodies, w.boxer_desc, b.desired.pose.root_position, b.desired.pose.rotation);
    // A body that starts inside a crate stays wedged in it (the chaos soak, issue 19): lifted until nothing is below
    // the tops under it (a guard: the walk's pose is placed on the crates, reset_lift reports any lift).
    const double sunk = deepest_below_crates(w, b);  // (its forward kinematics: the ankles below)
    MatchFighter& f = w.match.fighter[b.index];
    f.reset_lift = std::max(0.0, sunk);
    f.reset_feet_off = 0.0;
    for (int k = 0; k < 2; ++k)
      f.reset_feet_off = std::max(f.reset_feet_off, (w.data.x[b.bodies.body[b.bones.foot[k]]].p - b.metrics.foot0[k]).head<2>().norm());
    if (sunk > kResetClearance) {
      b.desired.pose.root_position.z() += sunk;
      set_character_pose(w.model, w.data, b.bodies, w.boxer_desc, b.desired.pose.root_position, b.desired.pose.rotation);
    }
    for (auto& s : b.ctl.step) s.active = false;
    for (auto& g : b.ctl.gate) g = {};
    // The balance's steps start over too (a recovery, a return step's weight shift): kept across the reset, the
    // weight shift leaned the boxer toward the stance it had left and the AI asked for no footwork meanwhile
    // (feet_busy); in a variant's match seed 11 the referee reset the two for "apart" five times in 10 s
    // (docs/decisions/footwork.md, sixth round).
    b.ctl.balance_steps = {};
  }
  ++w.match.resets;
}

namespace {

// A landed punch's impulse is summed over the touch; then the damage, the reaction or the knockdown.
void resolve_landing(World& w, int attacker) {
  Match& mt = w.match;
  MatchFighter& fa = mt.fighter[attacker];
  PunchEvent& e = mt.events[fa.landing];
  fa.landing = -1;
  const int k = 1 - attacker;
  Boxer& def = w.boxers[k];
  MatchFighter& fd = mt.fighter[k];
  const bool head = e.hit_part == "head";
  e.damage = e.impulse * (head ? mt.tuning.head_damage_per_ns : mt.tuning.body_damage_per_ns);
  def.ctl.root_spring.hit(def.settings.root_params, e.damage);
  fd.last_hit_at = w.data.time;
  if (!standing_state(def.ctl.state.state)) return;
  if (mt.over) return;
  const Eigen::Vector3d dir = bone_centre(w, def, 0) - bone_centre(w, w.boxers[attacker], 0);
  if (e.damage >= mt.tuning.knockdown_damage || def.ctl.root_spring.consciousness() < mt.tuning.knockdown_below) {
    knock_down(w, k, e.hit_part == "head" ? dir : Eigen::Vector3d(-dir), "knocked down by a punch");
    return;
  }
  const bool rocked = mt.tuning.rock_damage > 0.0 && e.damage >= mt.tuning.rock_damage;
  if (rocked) fd.rocked_at = w.data.time, ++fd.rocked;
  if (eng::anim::GraphWalker* walker = def.source.walker())
    walker->force_clip(rocked ? "stagger" : head ? "hit_head" : "hit_body");
}

// Where to hit: points on the opponent's head (face, chin, both temples, crown) or torso (solar plexus, both sides
// of the ribs), in the bone's frame (+X forward, +Y left, +Z up); the one the guard covers least along the punch's
// approach is chosen: straight punches come from the striking shoulder, hooks from the side of the striking hand at the
// target's height, uppercuts from below. Clearance = the least distance between the approach line and the opponent's
// gloves and arms (spheres of their capsules' radii; two along each forearm and upper arm), near ties broken by `jitter` (the
// seeded AI's; null: none). A punch can still be blocked: the guard moves while it flies, and a tight guard leaves no
// opening. Pure: the caller keeps the aim (track_punches).
struct Opening {
  double clear = -1e9;  // m, the approach's distance to the nearest part of the guard
  int bone = -1;
  Eigen::Vector3d local = Eigen::Vector3d::Zero(), dir_local = Eigen::Vector3d::UnitX();
};

Opening best_opening(const World& w, int k, const Clip& c, bool body, Rng* jitter) {
  const Boxer& b = w.boxers[k];
  const Boxer& o = w.boxers[1 - k];
  const auto& skel = w.boxer_desc.skeleton;
  const MatchBones& mb = w.match.bones;
  const int bone = body ? mb.chest : mb.head;
  static const Eigen::Vector3d kHead[] = {{0.09, 0, 0.0}, {0.07, 0, -0.07}, {0.03, 0.08, 0.02}, {0.03, -0.08, 0.02},
                                          {0.05, 0, 0.09}};
  static const Eigen::Vector3d kTorso[] = {{0.12, 0, -0.08}, {0.08, 0.13, -0.05}, {0.08, -0.13, -0.05}};
  const Eigen::Vector3d* cand = body ? kTorso : kHead;
  const int n = body ? 3 : 5;
  const int shoulder_bone = skel.parent[skel.parent[c.glove]];
  const Eigen::Vector3d shoulder = w.data.x[b.bodies.body[shoulder_bone]].p;
  const bool hook = c.name.find("hook") != std::string::npos, uppercut = c.name.find("uppercut") != std::string::npos;
  // The striking hand's side of the attacker (its left for glove_l), horizontal.
  const Eigen::Matrix3d& Ra = w.data.x[b.bodies.body[0]].R;
  const Eigen::Vector3d fwd = Eigen::Vector3d(Ra(0, 0), Ra(1, 0), 0.0).normalized();
  const Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(fwd);
  const bool left_hand = skel.name[c.glove].back() == 'l';
  // The opponent's guard: gloves, forearms and upper arms (two spheres along each). Without the upper arms the body
  // looked open behind the elbows, and punches sent there met them: 3-8 % of straights to the body landed, 88-94 % of
  // the body hooks and uppercuts hit an arm (seeds 1-20).
  Eigen::Vector3d guard[12];
  double radius[12];
  int ng = 0;
  for (const int gb : {mb.glove[0], mb.glove[1], mb.forearm[0], mb.forearm[1], mb.upper_arm[0], mb.upper_arm[1]}) {
    if (gb < 0) continue;
    const auto& x = w.data.x[o.bodies.body[gb]];
    if (gb == mb.glove[0] || gb == mb.glove[1]) {
      guard[ng] = x.p + x.R * w.boxer_desc.bones[gb].com, radius[ng++] = 0.07;
    } else if (gb == mb.upper_arm[0] || gb == mb.upper_arm[1]) {
      guard[ng] = x.p + x.R * w.boxer_desc.bones[gb].com, radius[ng++] = 0.055;  // mid upper arm
      guard[ng] = x.p + x.R * (1.8 * w.boxer_desc.bones[gb].com), radius[ng++] = 0.055;  // the elbow
    } else {
      guard[ng] = x.p + x.R * (0.5 * w.boxer_desc.bones[gb].com), radius[ng++] = 0.05;
      guard[ng] = x.p + x.R * (1.5 * w.boxer_desc.bones[gb].com), radius[ng++] = 0.05;
    }
  }
  const auto& xt = w.data.x[o.bodies.body[bone]];
  const Eigen::Vector3d centre = w.boxer_desc.bones[bone].com;
  Opening best;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = xt.p + xt.R * (centre + cand[i]);
    Eigen::Vector3d from = shoulder;
    if (hook) from = p + 0.35 * (left_hand ? left : Eigen::Vector3d(-left)) - 0.1 * fwd;
    if (uppercut) from = p - Eigen::Vector3d(0, 0, 0.35) - 0.15 * fwd;
    const Eigen::Vector3d d = p - from;
    double clear = 1e9;
    for (int g = 0; g < ng; ++g) {
      const double s = std::clamp((guard[g] - from).dot(d) / d.squaredNorm(), 0.0, 1.0);
      clear = std::min(clear, (from + s * d - guard[g]).norm() - radius[g]);
    }
    if (jitter) clear += 0.01 * jitter->uniform();
    if (clear > best.clear) {
      best.clear = clear, best.bone = bone, best.local = centre + cand[i];
      best.dir_local = xt.R.transpose() * d.normalized();  // the approach, kept in the target's frame
    }
  }
  return best;
}

// Punches starting (clip changes) and the AI's view of the other's.
void track_punches(World& w, const char* started[2]) {
  Match& mt = w.match;
  for (int k = 0; k < 2; ++k) {
    Boxer& b = w.boxers[k];
    MatchFighter& f = mt.fighter[k];
    eng::anim::GraphWalker* walker = b.source.walker();
    started[k] = nullptr;
    if (!walker) continue;
    const int idx = walker->current_clip_index();
    if (idx == f.last_clip) continue;
    f.last_clip = idx;
    f.open_punch = -1;
    const Clip& c = w.graph.clips[idx];
    if (!is_punch(&c) || !standing_state(b.ctl.state.state)) continue;
    ++f.thrown;
    if (const int pi = punch_index(c.name); pi >= 0) ++f.ai.thrown_of[pi];
    PunchEvent e;
    e.t = w.data.time;
    e.boxer = k;
    e.punch = c.name;
    // The AI reads the guard: a head the guard covers (no opening wider than switch_to_body_below along the
    // punch's approach) sends the punch to the body if the body is more open there (the player's aim is kept).
    Opening aim = best_opening(w, k, c, f.ai.aim_body, &f.ai.rng);
    if (!f.player && !f.ai.aim_body && aim.clear < mt.tuning.switch_to_body_below) {
      const Opening body = best_opening(w, k, c, true, &f.ai.rng);
      if (body.clear > aim.clear) f.ai.aim_body = true, aim = body;
    }
    f.aim_bone = aim.bone, f.aim_local = aim.local, f.aim_dir_local = aim.dir_local;
    e.opening = aim.clear;
    e.consciousness = {b.ctl.root_spring.consciousness(), w.boxers[1 - k].ctl.root_spring.consciousness()};
    e.target = f.ai.aim_body ? "torso" : "head";
    f.open_punch = static_cast<int>(mt.events.size());
    mt.events.push_back(std::move(e));
    started[k] = c.name.c_str();
  }
}

// The solver's hit events: a punch's striking glove on the opponent.
void read_hits(World& w) {
  Match& mt = w.match;
  const double t = w.data.time;
  for (const auto& h : w.data.hit_events) {
    const BodyOwner& oa = mt.owners[h.body_a];
    const BodyOwner& ob = mt.owners[h.body_b];
    if (oa.boxer < 0 || ob.boxer < 0 || oa.boxer == ob.boxer) continue;
    for (int side = 0; side < 2; ++side) {
      const BodyOwner& att = side == 0 ? oa : ob;
      const BodyOwner& def = side == 0 ? ob : oa;
      MatchFighter& f = mt.fighter[att.boxer];
      if (att.part != BodyPart::Glove || f.open_punch < 0) continue;
      const Clip* c = clip_of(w, w.boxers[att.boxer]);
      if (!is_punch(c) || c->glove != att.bone) continue;  // the other glove, or not punching
      PunchEvent& e = mt.events[f.open_punch];
      if (!e.hit_part.empty()) continue;  // the punch's first touch decided it
      e.hit_part = body_part_name(def.part);
      {
        const Boxer& ab = w.boxers[att.boxer];
        const int gb = ab.bodies.body[att.bone];
        const Eigen::Vector3d centre = w.data.x[gb].p + w.data.x[gb].R * w.boxer_desc.bones[att.bone].com;
        e.fist_speed = body_velocity_at(w, gb, centre).norm();
      }
      if (const Clip* dc = clip_of(w, w.boxers[def.boxer])) e.other_clip = dc->name;
      e.speed = h.approach_speed;
      if (def.part == BodyPart::Glove || def.part == BodyPart::Arm) {
        e.blocked = true;
      } else if ((def.part == BodyPart::Head || def.part == BodyPart::Torso) && h.approach_speed >= mt.tuning.land_speed) {
        e.landed = true;
        ++f.landed;
        if (const int pi = punch_index(e.punch); pi >= 0) ++f.ai.landed_of[pi];
        f.landing = f.open_punch;
        f.landing_until = t + mt.tuning.impact_window;
        e.impulse = 0.0;  // summed from the touching pairs below, this step included
      }
    }
  }
  // Landed punches sum the impulse between the striking glove and the opponent over the impact window.
  for (int k = 0; k < 2; ++k) {
    MatchFighter& f = mt.fighter[k];
    if (f.landing < 0) continue;
    PunchEvent& e = mt.events[f.landing];
    const Clip* c = clip_of(w, w.boxers[k]);
    const int glove_body = c && c->glove >= 0 ? w.boxers[k].bodies.body[c->glove] : -1;
    for (const auto& tp : w.data.touching) {
      const BodyOwner& oa = mt.owners[tp.body_a];
      const BodyOwner& ob = mt.owners[tp.body_b];
      const bool pair = (tp.body_a == glove_body && ob.boxer == 1 - k) || (tp.body_b == glove_body && oa.boxer == 1 - k);
      if (pair) e.impulse += tp.impulse;
    }
    if (t >= f.landing_until) resolve_landing(w, k);
  }
}

// Consciousness -> stunned; falls; lying still -> the stand-up; up -> guard; the count.
void referee(World& w) {
  Match& mt = w.match;
  const MatchTuning& tu = mt.tuning;
  const double t = w.data.time, dt = kPhysicsDt;
  for (int k = 0; k < 2; ++k) {
    Boxer& b = w.boxers[k];
    MatchFighter& f = mt.fighter[k];
    BoxerStateMachine& s = b.ctl.state;
    const double c = b.ctl.root_spring.consciousness();
    if (s.state == BoxerState::Guard && c < tu.stun_below) {
      boxer_state_enter(s, BoxerState::Stunned, t, "consciousness low");
      b.ctl.gain_scale = tu.stunned_gain_scale;
    } else if (s.state == BoxerState::Stunned && c >= tu.stun_below + 0.05) {
      boxer_state_enter(s, BoxerState::Guard, t, "recovered");
      b.ctl.gain_scale = 1.0;
    }
    // A fall the match did not call (detected Down from Guard / Stunned this tick).
    if (s.state == BoxerState::Down && s.since == t && f.getup < 0) {
      if (t - f.last_hit_at > kFallWithoutHitWindow) {
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
    if (f.getup < 0) continue;
    GetUp& g = mt.getups[f.getup];
    const int pelvis = b.bodies.body[0];
    const double speed = body_velocity_at(w, pelvis, w.data.x[pelvis].p).norm();
    if (s.state == BoxerState::Down) {
      f.still = speed < tu.still_speed ? f.still + dt : 0.0;
      // (Also after a knock-out: the beaten boxer comes round and stands, the fight does not go on; the chaos soak's
      // falls after it end in get-ups too.)
      if (f.still >= tu.still_time && t - g.down_at >= tu.min_down_time) {
        // Lying on the back: the chest's front (+X of the bone) looks up.
        const int chest = mt.bones.chest;
        const Eigen::Vector3d front = w.data.x[b.bodies.body[chest >= 0 ? chest : 0]].R * Eigen::Vector3d::UnitX();
        g.lying = front.z() > 0.0 ? "back" : "front";
        if (eng::anim::GraphWalker* walker = b.source.walker()) walker->force_clip(g.lying == "back" ? "getup_back" : "getup_front");
        b.ctl.root_spring.set_consciousness(0.6);
        pass_through_opponent(w, k, true);
        boxer_state_enter(s, BoxerState::GettingUp, t, "getting up");
        // The standing boxer goes to a neutral corner, as a referee sends him (here: to its mark, a reset of that
        // boxer only): standing over the downed one, the get-up rose into him and stuck crouched (seed 2: counted out).
        const Boxer& o = w.boxers[1 - k];
        const Eigen::Vector3d po = w.data.x[o.bodies.body[0]].p, pk = w.data.x[pelvis].p;
        if (standing_state(o.ctl.state.state) && (po - pk).head<2>().norm() < tu.neutral_corner_within)
          back_to_marks(w, 1 - k);
      }
    } else if (s.state == BoxerState::GettingUp) {
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
        // Given up: down again, limp; lying still, the Down branch above starts the stand-up anew (the same GetUp:
        // its assist time and the count run on).
        boxer_state_enter(s, BoxerState::Down, t, "stand-up given up");
        b.ctl.root_spring.set_consciousness(0.0);
        f.still = 0.0;
        ++g.retries;
      } else if (f.settled >= tu.settle_time) {
        boxer_state_enter(s, BoxerState::Guard, t, "up");
        b.ctl.gain_scale = 1.0;
        g.up_at = t;
        f.getup = -1;
        // Up inside the count: the referee lets the boxer fight on, clear-headed enough not to be stunned (stunned
        // and teleported to its mark, a boxer fell again within seconds with no punch: seed 2, 3 falls).
        b.ctl.root_spring.set_consciousness(std::max(b.ctl.root_spring.consciousness(), tu.after_count));
        pass_through_opponent(w, k, false);
        back_to_marks(w);
        g.reset_lift = f.reset_lift, g.reset_feet_off = f.reset_feet_off;
      }
    }
    // The count: not up in count_seconds is a knock-out.
    if (f.getup >= 0 && !mt.over && t - g.down_at > tu.count_seconds) {
      mt.over = true;
      mt.result = "KO: boxer " + std::to_string(1 - k) + " wins (boxer " + std::to_string(k) + " not up at " +
                  std::to_string(static_cast<int>(tu.count_seconds)) + ")";
    }
  }
}

}  // namespace

bool in_range(const World& w, int k) { return reach_distance(w, k) < kInRange; }

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
  }
  return "";
}

void match_command(World& w, int k, FightCommand c) {
  if (!w.match.active || k < 0 || k > 1) return;
  MatchFighter& f = w.match.fighter[k];
  f.player = true;
  if (c != FightCommand::None && f.queued < MatchFighter::kCommandBuffer) f.commands[f.queued++] = c;
}

void match_setup(World& w) {
  Match& mt = w.match;
  mt.active = true;
  mt.owners = body_owners(static_cast<int>(w.model.bodies.size()), w.boxers, w.boxer_desc.skeleton);
  const auto& skel = w.boxer_desc.skeleton;
  mt.bones.head = skel.find("head");
  mt.bones.chest = skel.find("chest");
  mt.bones.glove[0] = skel.find("glove_l"), mt.bones.glove[1] = skel.find("glove_r");
  mt.bones.forearm[0] = skel.find("forearm_l"), mt.bones.forearm[1] = skel.find("forearm_r");
  mt.bones.upper_arm[0] = skel.find("upper_arm_l"), mt.bones.upper_arm[1] = skel.find("upper_arm_r");
  mt.round_seconds = w.options.round_seconds;
  mt.replay.init(static_cast<int>(kReplaySeconds * 60.0), static_cast<int>(w.data.q.size()));
  for (int k = 0; k < 2 && k < static_cast<int>(w.boxers.size()); ++k) {
    MatchFighter& f = mt.fighter[k];
    w.boxers[k].ctl.mark = w.boxers[k].desired.pose.root_position.head<2>();  // where the pelvis starts
    f.ai.rng = Rng(w.options.seed * 0x9E3779B97F4A7C15ull + 0xF16A7ull + static_cast<uint64_t>(k));
    f.ai.style = draw_fighter_style(f.ai.rng);
    f.ai.next_attack = 1.0 + f.ai.rng.uniform(0.0, 1.0);  // both settle into guard first
    f.player = w.options.player == k;
    Boxer& b = w.boxers[k];
    // The AI (or the player) decides what is thrown: the walk takes no random transition (a punch, a slip) of its own
    // and guard loops until asked for something else; continuations, hits and knockdowns go on as before.
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
    // The fight's balance: Kudoh's priorities, the trunk held upright over the com (balance_qp.h BalanceQpTuning).
    if (w.options.priorities != "off") {
      b.settings.tuning.qp.trunk_weight = mt.tuning.trunk_weight;
      b.settings.tuning.qp.com_weight = mt.tuning.com_weight;
    }
  }
}

void match_before_control(World& w) {
  Match& mt = w.match;
  if (!mt.active || w.boxers.size() < 2) return;
  const double t = w.data.time;
  for (int k = 0; k < 2; ++k) {
    Boxer& b = w.boxers[k];
    const Boxer& o = w.boxers[1 - k];
    MatchFighter& f = mt.fighter[k];
    eng::anim::GraphWalker* walker = b.source.walker();
    if (!walker) continue;
    const Clip& c = w.graph.clips[walker->current_clip_index()];
    const bool standing = standing_state(b.ctl.state.state);
    // The aim: the punch playing bends the striking arm onto the opponent's head or torso, through it by a few cm
    // (the servo lags its target: aimed at the surface, the glove would arrive slow).
    b.ctl.aim.active = standing && is_punch(&c) && f.open_punch >= 0 && f.aim_bone >= 0;
    if (b.ctl.aim.active) {
      const auto& xt = w.data.x[o.bodies.body[f.aim_bone]];
      b.ctl.aim.glove = c.glove;
      b.ctl.aim.arm_gain = mt.tuning.punch_arm_gain;
      b.ctl.aim.target = xt.p + xt.R * (f.aim_local + kAimThrough * f.aim_dir_local);
      b.ctl.aim.weight = aim_weight(walker->clip_time(), c.impact_time, c.duration());
      // The strike drives the glove in until its first touch (of anything); from there the arm's momentum and the
      // bent pose carry it: driven on, the task pushed on into the head (impulses to 60 N s, twice a power punch's).
      const bool touched = !mt.events[f.open_punch].hit_part.empty();
      b.ctl.aim.strike = touched ? 0.0 : strike_weight(walker->clip_time(), c.impact_time, mt.tuning.strike_follow);
      b.ctl.aim.strike_speed = mt.tuning.strike_speed;
      b.ctl.aim.strike_rate = mt.tuning.strike_rate;
      b.ctl.aim.strike_omega = mt.tuning.strike_omega;
      b.ctl.aim.strike_weight = mt.tuning.strike_weight;
    }
    if (f.player) {
      // The player's command, taken when the boxer stands and the walk is free of a plan (a punch asked for during
      // another is taken once that one lets the graph go, like a buffered input in a fighting game).
      if (f.queued > 0 && standing && !walker->has_plan() && !mt.over) {
        if (walker->request_clip(fight_command_clip(f.commands[0]))) ++f.commands_taken;
        f.ai.aim_body = false;
        std::copy(f.commands.begin() + 1, f.commands.end(), f.commands.begin());
        --f.queued;
      }
      continue;
    }
    if (mt.over) continue;
    FighterView v;
    v.time = t;
    v.punching = is_punch(&c);
    v.free = standing && !walker->has_plan() && c.has_tag("guard");
    // Distance: the opponent's head from this boxer's chest, on the floor. A straight punch puts the glove's centre
    // about kReach ahead of the chest at full extension (measured: 0.74 m); in range within a head's depth of that.
    const double dist = reach_distance(w, k);
    const bool opponent_up = standing_state(o.ctl.state.state);  // no hitting a downed man
    v.in_range = dist < kInRange && opponent_up;
    // A boxer just hit gathers itself before it steps in: the step's lean on legs still taking the hit floored
    // boxers 1-1.5 s after a punch (3 of 4 falls without a hit, seeds 1-20).
    v.too_far = dist > kReach + 0.03 && opponent_up && t - f.last_hit_at > mt.tuning.step_in_after_hit;
    v.too_close = dist < kReach - 0.25;
    v.press = t - mt.fighter[1 - k].rocked_at < mt.tuning.press_for;
    // A balance step, its settling or its return under way (balance_step.h phases 1-3), or a stance the body cannot
    // fight from: the feet are the balance's, and the AI asks for no footwork (fighter_ai.h).
    const auto& bst = b.ctl.balance_steps;
    v.feet_busy = bst.step.active || bst.recovering || bst.shifting >= 0 || !stance_can_fight(w.data, b);
    v.other_started = f.saw_punch;
    v.slow = b.ctl.state.state == BoxerState::Stunned ? 0.4 : 1.0;
    f.saw_punch = nullptr;
    fighter_ai_tick(f.ai, *walker, v, kPhysicsDt);
  }
}

void match_after_step(World& w) {
  Match& mt = w.match;
  if (!mt.active || w.boxers.size() < 2) return;
  // Pushed apart by the punches (the feet slide; the boxers cannot step back in): the referee brings them together.
  {
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
  const char* started[2];
  track_punches(w, started);
  for (int k = 0; k < 2; ++k) mt.fighter[1 - k].saw_punch = started[k];
  if ((w.steps + 1) % kStepsPerFrame == 0) mt.replay.record(w.data.q, w.data.time);  // one per 60 Hz frame
  for (int k = 0; k < 2; ++k) {  // the striking glove's speed over the punch
    const MatchFighter& f = mt.fighter[k];
    const Clip* c = clip_of(w, w.boxers[k]);
    if (f.open_punch < 0 || !is_punch(c)) continue;
    const int body = w.boxers[k].bodies.body[c->glove];
    PunchEvent& e = mt.events[f.open_punch];
    e.peak_speed = std::max(e.peak_speed, body_velocity_at(w, body, w.data.x[body].p).norm());
  }
  read_hits(w);
  for (int k = 0; k < 2; ++k) {
    MatchFighter& f = mt.fighter[k];
    const int started_steps = w.boxers[k].metrics.balance_steps - f.balance_steps_seen;
    if (w.data.time - f.last_hit_at <= kFallWithoutHitWindow) f.balance_steps_after_hit += started_steps;
    f.balance_steps_seen += started_steps;
  }
  referee(w);
}

MatchHud match_hud(const World& w) {
  const Match& mt = w.match;
  MatchHud h;
  const double t = w.data.time;
  h.round = static_cast<int>(t / mt.round_seconds) + 1;
  h.clock_s = std::max(0.0, h.round * mt.round_seconds - t);
  for (int k = 0; k < 2 && k < static_cast<int>(w.boxers.size()); ++k) {
    const MatchFighter& f = mt.fighter[k];
    h.side[k].consciousness = static_cast<float>(w.boxers[k].ctl.root_spring.consciousness());
    h.side[k].landed = f.landed, h.side[k].thrown = f.thrown, h.side[k].knockdowns = f.knockdowns;
    h.side[k].player = f.player;
    h.side[k].state = boxer_state_name(w.boxers[k].ctl.state.state);
    if (f.getup >= 0 && !mt.over) {
      const int count = std::min(10, static_cast<int>(t - mt.getups[f.getup].down_at) + 1);
      h.banner = std::string(k == 0 ? "RED" : "BLUE") + " DOWN   " + std::to_string(count);
    }
  }
  if (mt.over) h.banner = mt.result;
  return h;
}

nlohmann::json match_report(const World& w) {
  const Match& mt = w.match;
  nlohmann::json events = nlohmann::json::array();
  for (const PunchEvent& e : mt.events)
    events.push_back({{"t", e.t},
                      {"boxer", e.boxer},
                      {"punch", e.punch},
                      {"target", e.target},
                      {"landed", e.landed},
                      {"blocked", e.blocked},
                      {"hit", e.hit_part},
                      {"other_clip", e.other_clip},
                      {"speed", e.speed},
                      {"fist_speed", e.fist_speed},
                      {"peak_speed", e.peak_speed},
                      {"opening_m", e.opening},
                      {"consciousness", e.consciousness},
                      {"impulse", e.impulse},
                      {"damage", e.damage}});
  nlohmann::json getups = nlohmann::json::array();
  for (const GetUp& g : mt.getups)
    getups.push_back({{"boxer", g.boxer},
                      {"down_at_s", g.down_at},
                      {"up_at_s", g.up_at >= 0.0 ? nlohmann::json(g.up_at) : nlohmann::json(nullptr)},
                      {"lying", g.lying.empty() ? nlohmann::json(nullptr) : nlohmann::json(g.lying)},
                      {"root_assist_rms_nm", g.assist_time > 0 ? std::sqrt(g.assist_sq_dt / g.assist_time) : 0.0},
                      {"reset_lift_m", g.reset_lift},
                      {"reset_feet_off_m", g.reset_feet_off},
                      {"root_assist_force_rms_n", g.assist_time > 0 ? std::sqrt(g.assist_force_sq_dt / g.assist_time) : 0.0},
                      {"stand_up_s", g.assist_time},
                      {"stand_up_retries", g.retries}});
  auto pair = [&mt](auto get) { return nlohmann::json::array({get(mt.fighter[0]), get(mt.fighter[1])}); };
  std::string result = mt.result;
  if (result.empty()) {
    const int a = mt.fighter[0].landed, b = mt.fighter[1].landed;
    result = a == b ? "draw on points (" + std::to_string(a) + "-" + std::to_string(b) + " landed)"
                    : "points: boxer " + std::to_string(a > b ? 0 : 1) + " wins (" + std::to_string(a) + "-" +
                          std::to_string(b) + " landed)";
  }
  std::vector<double> speeds, fists;
  for (const PunchEvent& e : mt.events)
    if (e.landed) speeds.push_back(e.speed), fists.push_back(e.fist_speed);
  std::sort(speeds.begin(), speeds.end());
  std::sort(fists.begin(), fists.end());
  return {{"punches_thrown", pair([](const MatchFighter& f) { return f.thrown; })},
          {"punches_landed", pair([](const MatchFighter& f) { return f.landed; })},
          {"knockdowns", pair([](const MatchFighter& f) { return f.knockdowns; })},
          {"falls_without_hit", pair([](const MatchFighter& f) { return f.falls_without_hit; })},
          {"falls_after_hit", pair([](const MatchFighter& f) { return f.falls_after_hit; })},
          {"balance_steps_after_hit", pair([](const MatchFighter& f) { return f.balance_steps_after_hit; })},
          {"rocked", pair([](const MatchFighter& f) { return f.rocked; })},
          {"landed_speed_median", speeds.empty() ? 0.0 : speeds[speeds.size() / 2]},
          {"landed_fist_speed_median", fists.empty() ? 0.0 : fists[fists.size() / 2]},
          {"consciousness", pair([&w](const MatchFighter& f) {
             const int k = static_cast<int>(&f - &w.match.fighter[0]);
             return w.boxers[k].ctl.root_spring.consciousness();
           })},
          {"players", pair([](const MatchFighter& f) { return f.player; })},
          {"styles", pair([](const MatchFighter& f) {
             const FighterStyle& s = f.ai.style;
             return nlohmann::json{{"attack_rate", s.attack_rate}, {"combo", s.combo}, {"defence", s.defence},
                                   {"reaction_s", s.reaction_s}, {"body_share", s.body_share},
                                   {"punch_weight", s.punch_weight}};
           })},
          {"player_commands_taken", pair([](const MatchFighter& f) { return f.commands_taken; })},
          {"round_seconds", mt.round_seconds},
          {"resets_to_marks", mt.resets},
          {"apart_resets", mt.apart_resets},
          {"round", static_cast<int>(w.data.time / mt.round_seconds) + 1},
          {"ended_at_s", w.data.time},  // the run's end: a knockdown less than the count before it has no up_at_s yet
          {"getups", getups},
          {"result", result},
          {"events", events}};
}

}  // namespace boxing
