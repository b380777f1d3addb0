#include "game/audio/sound_events.h"

#include "game/match/body_parts.h"
#include "game/match/match.h"
#include "game/world.h"

namespace boxing {

namespace {

void push(SoundEventLog& log, SoundKind kind, double t, const Eigen::Vector3d& at, double impulse) {
  log.ring[log.written % SoundEventLog::kCapacity] = {kind, t, at, impulse};
  ++log.written;
}

const SoundBody& tag(const SoundEventLog& log, int body) {
  static const SoundBody kLoose{};  // a body made after setup: not a boxer's
  return body >= 0 && body < static_cast<int>(log.bodies.size()) ? log.bodies[body] : kLoose;
}

bool is(const SoundBody& b, BodyPart p) { return b.part == static_cast<uint8_t>(p); }

// One sound per body per SoundEventTuning::repeat_s (a bounce touches with several geoms in a tick or two).
bool quiet_since(SoundEventLog& log, int body, double t) {
  if (body < 0 || body >= static_cast<int>(log.last_sound.size())) return true;
  if (t - log.last_sound[body] < log.tuning.repeat_s) return false;
  log.last_sound[body] = t;
  return true;
}

// The solver's hit events of this step: slaps (a glove on the other boxer's glove or arm) and thuds (a boxer's body
// part, not a foot, on the arena or an object). Gloves on a head or torso are the match's to judge (landed punches).
void collect_contacts(const World& w, SoundEventLog& log) {
  const double t = w.data.time;
  const SoundEventTuning& tu = log.tuning;
  for (const eng::physics::HitEvent& h : w.data.hit_events) {
    const SoundBody& a = tag(log, h.body_a);
    const SoundBody& b = tag(log, h.body_b);
    if (a.boxer >= 0 && b.boxer >= 0) {
      if (a.boxer == b.boxer || h.approach_speed < tu.slap_min_speed) continue;
      const bool a_glove = is(a, BodyPart::Glove), b_glove = is(b, BodyPart::Glove);
      const bool slap = (a_glove && (b_glove || is(b, BodyPart::Arm))) || (b_glove && is(a, BodyPart::Arm));
      if (slap && quiet_since(log, a_glove ? h.body_a : h.body_b, t))
        push(log, SoundKind::GloveOnGlove, t, h.point, h.impulse);
      continue;
    }
    const int body = a.boxer >= 0 ? h.body_a : b.boxer >= 0 ? h.body_b : -1;
    if (body < 0 || tag(log, body).foot || h.impulse < tu.thud_min_impulse) continue;
    if (quiet_since(log, body, t)) push(log, SoundKind::BodyOnCrate, t, h.point, h.impulse);
  }
}

// A foot setting down (on the ground within the load gap, FootContacts::on_ground: touching, not only near) after
// footstep_air_s or more off it: a footstep at the foot, its impulse the normal impulse of the foot's contacts in
// this step (a landing's first step: 9 N s median over a match).
void collect_footsteps(const World& w, SoundEventLog& log) {
  const double t = w.data.time;
  for (size_t k = 0; k < w.boxers.size() && k < log.airborne_from.size(); ++k) {
    const Boxer& b = w.boxers[k];
    if (b.limp) continue;
    for (int f = 0; f < 2; ++f) {
      double& from = log.airborne_from[k][f];
      if (!b.ctl.contacts.on_ground[f]) {
        if (from < 0.0) from = t;
        continue;
      }
      if (from >= 0.0 && t - from >= log.tuning.footstep_air_s && b.bones.foot[f] >= 0) {
        const int body = b.bodies.body[b.bones.foot[f]];
        double impulse = 0.0;
        for (const eng::physics::Contact& c : w.data.contacts)
          if (c.body_a == body || c.body_b == body) impulse += c.normal_impulse;
        push(log, SoundKind::Footstep, t, w.data.com_world[body], impulse);
      }
      from = -1.0;
    }
  }
}

// Landed punches from the match's record: the tick a fighter's punch lands (MatchFighter::landing set) its contact
// point and time are kept; once the match has summed its impulse over the impact window (landing cleared or moved
// on to the next punch), the sound is pushed with the landing's time and that impulse.
void collect_landed_punches(const World& w, SoundEventLog& log) {
  const Match& mt = *w.match;
  for (int k = 0; k < 2; ++k) {
    const int now = mt.fighter[k].landing;
    int& kept = log.landing[k];
    if (kept >= 0 && now != kept && kept < static_cast<int>(mt.events.size())) {
      const PunchEvent& e = mt.events[kept];
      push(log, e.hit_part == "head" ? SoundKind::GloveOnHead : SoundKind::GloveOnBody, log.landing_t[k],
           log.landing_at[k], e.impulse);
      kept = -1;
    }
    if (now < 0 || now == kept) continue;
    kept = now;
    log.landing_t[k] = w.data.time;
    // The contact: the fastest hit of boxer k's glove on the other's head or torso in this step (the one that landed).
    double fastest = -1.0;
    for (const eng::physics::HitEvent& h : w.data.hit_events) {
      const SoundBody& a = tag(log, h.body_a);
      const SoundBody& b = tag(log, h.body_b);
      const bool ab = a.boxer == k && is(a, BodyPart::Glove) && b.boxer == 1 - k;
      const bool ba = b.boxer == k && is(b, BodyPart::Glove) && a.boxer == 1 - k;
      if ((ab || ba) && h.approach_speed > fastest) fastest = h.approach_speed, log.landing_at[k] = h.point;
    }
    if (fastest < 0.0 && mt.bones.head >= 0)  // (a landing is decided by such a hit: a fallback, the opponent's head)
      log.landing_at[k] = w.data.com_world[w.boxers[1 - k].bodies.body[mt.bones.head]];
  }
}

// The bell: the opening bell on the match's first tick, one strike at each round's end and start, three at the end.
void collect_bell(const World& w, SoundEventLog& log) {
  const Bout& bt = w.match->bout;
  const int phase = static_cast<int>(bt.phase);
  const Ring& r = w.arena.ring;
  const Eigen::Vector3d post = r.present ? Eigen::Vector3d(r.corners[0].x(), r.corners[0].y(), r.top_mean + r.post_height)
                                         : Eigen::Vector3d(0.0, 0.0, 1.5);
  const double t = w.data.time;
  if (log.bout_phase < 0 || (phase != log.bout_phase && bt.phase != BoutPhase::Over)) {
    push(log, SoundKind::Bell, t, post, 1.0);
  } else if (phase != log.bout_phase) {
    for (int s = 0; s < 3; ++s) push(log, SoundKind::Bell, t + s * log.tuning.bell_gap_s, post, 1.0);
  }
  log.bout_phase = phase;
}

}  // namespace

const char* sound_kind_name(SoundKind k) {
  switch (k) {
    case SoundKind::GloveOnHead: return "glove_on_head";
    case SoundKind::GloveOnBody: return "glove_on_body";
    case SoundKind::GloveOnGlove: return "glove_on_glove";
    case SoundKind::BodyOnCrate: return "body_on_crate";
    case SoundKind::Footstep: return "footstep";
    case SoundKind::Bell: return "bell";
  }
  return "?";
}

void sound_events_setup(const World& w, SoundEventLog& log) {
  const int n = static_cast<int>(w.model.bodies.size());
  const std::vector<BodyOwner> owners = body_owners(n, w.boxers, w.boxer_desc.skeleton);
  log.bodies.assign(n, SoundBody{});
  for (int i = 0; i < n; ++i)
    log.bodies[i] = {static_cast<int8_t>(owners[i].boxer), static_cast<uint8_t>(owners[i].part), false};
  for (const Boxer& b : w.boxers)
    for (int f = 0; f < 2; ++f)
      if (b.bones.foot[f] >= 0 && b.bodies.body[b.bones.foot[f]] >= 0) log.bodies[b.bodies.body[b.bones.foot[f]]].foot = true;
  log.last_sound.assign(n, -1e9);
  log.airborne_from.assign(w.boxers.size(), {-1.0, -1.0});
}

void collect_sound_events(const World& w, SoundEventLog& log) {
  collect_contacts(w, log);
  collect_footsteps(w, log);
  if (w.match && w.match->active && w.boxers.size() >= 2) {
    collect_landed_punches(w, log);
    collect_bell(w, log);
  }
}

}  // namespace boxing
