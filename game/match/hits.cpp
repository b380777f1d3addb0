#include "game/match/hits.h"

#include <algorithm>
#include <string>

#include "game/match/match.h"
#include "game/match/match_internal.h"
#include "game/match/referee.h"

namespace boxing {

namespace {

using eng::anim::Clip;

// A landed punch's impulse is summed over the touch; then the damage, the reaction or the knockdown.
void resolve_landing(World& w, int attacker) {
  Match& mt = *w.match;
  MatchFighter& fa = mt.fighter[attacker];
  PunchEvent& e = mt.events[fa.landing];
  fa.landing = -1;
  const int k = 1 - attacker;
  Boxer& def = w.boxers[k];
  MatchFighter& fd = mt.fighter[k];
  const bool head = e.hit_part == "head";
  // A tired thrower's punch is weaker (stamina.h: x1 in the band): its power at the punch's start.
  e.damage = e.impulse * (head ? mt.tuning.head_damage_per_ns : mt.tuning.body_damage_per_ns) *
             stamina_power(Stamina{.level = e.stamina}, mt.tuning.stamina);
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

// Where to hit: points on the opponent's head or torso (OpeningTuning::head, torso); the one the guard covers least along the punch's
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
  const MatchBones& mb = w.match->bones;
  const int bone = body ? mb.chest : mb.head;
  const OpeningTuning& ot = w.match->tuning.opening;
  const Eigen::Vector3d* cand = body ? ot.torso.data() : ot.head.data();
  const int n = static_cast<int>(body ? ot.torso.size() : ot.head.size());
  const int shoulder_bone = skel.parent[skel.parent[c.glove]];
  const Eigen::Vector3d shoulder = w.data.x[b.bodies.body[shoulder_bone]].p;
  const bool hook = c.name.find("hook") != std::string::npos, uppercut = c.name.find("uppercut") != std::string::npos;
  // The striking hand's side of the attacker (its left for glove_l), horizontal.
  const Eigen::Matrix3d& Ra = w.data.x[b.bodies.body[0]].R;
  const Eigen::Vector3d fwd = Eigen::Vector3d(Ra(0, 0), Ra(1, 0), 0.0).normalized();
  const Eigen::Vector3d left = Eigen::Vector3d::UnitZ().cross(fwd);
  const bool left_hand = skel.name[c.glove].back() == 'l';
  // The opponent's guard: gloves, forearms and upper arms (two spheres along each). The upper arms count: without
  // them the body looks open behind the elbows, and punches sent there meet them (docs/decisions/match-fight.md).
  Eigen::Vector3d guard[12];
  double radius[12];
  int ng = 0;
  for (const int gb : {mb.glove[0], mb.glove[1], mb.forearm[0], mb.forearm[1], mb.upper_arm[0], mb.upper_arm[1]}) {
    if (gb < 0) continue;
    const auto& x = w.data.x[o.bodies.body[gb]];
    if (gb == mb.glove[0] || gb == mb.glove[1]) {
      guard[ng] = x.p + x.R * w.boxer_desc.bones[gb].com, radius[ng++] = ot.glove_radius;
    } else if (gb == mb.upper_arm[0] || gb == mb.upper_arm[1]) {
      guard[ng] = x.p + x.R * w.boxer_desc.bones[gb].com, radius[ng++] = ot.upper_arm_radius;  // mid upper arm
      guard[ng] = x.p + x.R * (ot.elbow_along * w.boxer_desc.bones[gb].com), radius[ng++] = ot.upper_arm_radius;  // elbow
    } else {
      guard[ng] = x.p + x.R * (ot.forearm_near * w.boxer_desc.bones[gb].com), radius[ng++] = ot.forearm_radius;
      guard[ng] = x.p + x.R * (ot.forearm_far * w.boxer_desc.bones[gb].com), radius[ng++] = ot.forearm_radius;
    }
  }
  const auto& xt = w.data.x[o.bodies.body[bone]];
  const Eigen::Vector3d centre = w.boxer_desc.bones[bone].com;
  Opening best;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = xt.p + xt.R * (centre + cand[i]);
    Eigen::Vector3d from = shoulder;
    if (hook) from = p + ot.hook_side * (left_hand ? left : Eigen::Vector3d(-left)) - ot.hook_back * fwd;
    if (uppercut) from = p - Eigen::Vector3d(0, 0, ot.uppercut_below) - ot.uppercut_back * fwd;
    const Eigen::Vector3d d = p - from;
    double clear = 1e9;
    for (int g = 0; g < ng; ++g) {
      const double s = std::clamp((guard[g] - from).dot(d) / d.squaredNorm(), 0.0, 1.0);
      clear = std::min(clear, (from + s * d - guard[g]).norm() - radius[g]);
    }
    if (jitter) clear += ot.jitter * jitter->uniform();
    if (clear > best.clear) {
      best.clear = clear, best.bone = bone, best.local = centre + cand[i];
      best.dir_local = xt.R.transpose() * d.normalized();  // the approach, kept in the target's frame
    }
  }
  return best;
}

}  // namespace

void track_punches(World& w, const char* started[2]) {
  Match& mt = *w.match;
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
    e.stamina = f.stamina.level;
    e.target = f.ai.aim_body ? "torso" : "head";
    f.open_punch = static_cast<int>(mt.events.size());
    mt.events.push_back(std::move(e));
    started[k] = c.name.c_str();
  }
}

void read_hits(World& w) {
  Match& mt = *w.match;
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
        e.landed_at = t;
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

void track_peak_speed(World& w) {
  Match& mt = *w.match;
  for (int k = 0; k < 2; ++k) {
    const MatchFighter& f = mt.fighter[k];
    const Clip* c = clip_of(w, w.boxers[k]);
    if (f.open_punch < 0 || !is_punch(c)) continue;
    const int body = w.boxers[k].bodies.body[c->glove];
    PunchEvent& e = mt.events[f.open_punch];
    e.peak_speed = std::max(e.peak_speed, body_velocity_at(w, body, w.data.x[body].p).norm());
  }
}

void count_balance_steps_after_hit(World& w) {
  Match& mt = *w.match;
  for (int k = 0; k < 2; ++k) {
    MatchFighter& f = mt.fighter[k];
    const int started_steps = w.boxers[k].metrics.balance_steps - f.balance_steps_seen;
    if (w.data.time - f.last_hit_at <= mt.tuning.fall_after_hit_window) f.balance_steps_after_hit += started_steps;
    f.balance_steps_seen += started_steps;
  }
}

}  // namespace boxing
