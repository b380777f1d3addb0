#include "game/interaction/chaos.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/physics/dynamics.h"
#include "game/interaction/interaction.h"
#include "game/world.h"

namespace boxing {

void chaos_setup(World& w) {
  w.chaos->rate = w.options.chaos;
  w.chaos->rng = Rng(w.options.seed * 0xC4A05ull + 0x5EEDull);
}

void chaos_begin_step(World& w) {
  Chaos& c = *w.chaos;
  if (c.rate <= 0.0 || w.boxers.empty()) return;
  if (c.rng.uniform() >= c.rate * w.model.dt) return;  // a Poisson process sampled per step
  Rng& r = c.rng;
  InputEvent e;
  e.t = w.data.time;
  e.boxer = r.below(int(w.boxers.size()));
  const double kind = r.uniform();
  if (kind < 0.45) {  // a drag of a random bone, 0.2-1.5 m, 0.2-1 s, strong one time in three
    const auto& names = w.boxer_desc.skeleton.name;
    e.kind = InputKind::Drag;
    e.bone = names[size_t(r.below(int(names.size())))];
    const double a = r.uniform(-M_PI, M_PI), up = r.uniform(-0.6, 0.9);
    e.vec = r.uniform(0.2, 1.5) * Eigen::Vector3d(std::cos(a), std::sin(a), up).normalized();
    e.duration = r.uniform(0.2, 1.0);
    e.strong = r.uniform() < 0.33;
  } else if (kind < 0.7) {  // a chest push, 100-600 N for 0.1-0.2 s, any horizontal direction
    const double a = r.uniform(-M_PI, M_PI);
    e.kind = InputKind::Push;
    e.bone = "chest";
    e.vec = r.uniform(100.0, 600.0) * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
    e.duration = r.uniform(0.1, 0.2);
  } else {  // a ball (6-12 m/s) or, one time in three, a crate (5-9 m/s)
    e.kind = InputKind::Throw;
    e.object_kind = r.uniform() < 0.67 ? ObjectKind::Ball : ObjectKind::Crate;
    e.at_boxer = e.boxer;
    e.speed = e.object_kind == ObjectKind::Ball ? r.uniform(6.0, 12.0) : r.uniform(5.0, 9.0);
  }
  ++c.events;
  interaction_submit(w, e);
}

void health_after_step(World& w) {
  Health& h = w.health;
  const auto& d = w.data;
  if (!d.q.allFinite() || !d.v.allFinite()) {
    ++h.non_finite_steps;
    return;
  }
  auto speed_of = [&](int b) { return eng::physics::point_velocity(d, b, d.com_world[b]).norm(); };
  if (h.crates_top < 0.0)
    for (const Crate& cr : w.arena.crates) h.crates_top = std::max(h.crates_top, cr.center.z() + cr.half_extents.z());
  auto inside = [&](const Eigen::Vector3d& c) {
    if (c.z() < -0.02) return true;
    if (c.z() > h.crates_top) return false;
    for (const Crate& cr : w.arena.crates) {
      const Eigen::Vector3d in = cr.half_extents - (c - cr.center).cwiseAbs();
      if ((in.array() > 0.02).all()) return true;
    }
    return false;
  };
  // d.com_world / v_body are step1's (the start of this step): one step behind q, v; enough for the bounds.
  for (const Boxer& b : w.boxers)
    for (size_t i = 0; i < b.bodies.body.size(); ++i) {
      const int body = b.bodies.body[i];
      const double s = speed_of(body);
      if (s > h.max_body_speed)
        h.max_body_speed = s, h.worst_speed_at = d.time, h.worst_speed_boxer = b.index, h.worst_speed_bone = int(i);
      h.bodies_below_floor += inside(d.com_world[body]);
    }
  for (const ThrownObject& o : w.interaction->objects) {
    if (!o.live) continue;
    if (o.group == 0 || d.time - o.thrown_at > 0.1) h.max_object_speed = std::max(h.max_object_speed, speed_of(o.body));
    h.bodies_below_floor += inside(d.com_world[o.body]);
  }
  for (const auto& c : d.contacts) h.max_penetration = std::max(h.max_penetration, c.point.depth);
}

nlohmann::json health_report(const World& w) {
  const Health& h = w.health;
  return {{"non_finite_steps", h.non_finite_steps},
          {"max_body_speed_mps", h.max_body_speed},
          {"max_body_speed_at_s", h.worst_speed_at},
          {"max_body_speed_body", h.worst_speed_bone < 0 ? std::string()
                                      : "boxer " + std::to_string(h.worst_speed_boxer) + " " +
                                            w.boxer_desc.skeleton.name[size_t(h.worst_speed_bone)]},
          {"max_object_speed_mps", h.max_object_speed},
          {"bodies_below_floor", h.bodies_below_floor},
          {"max_penetration_m", h.max_penetration},
          {"chaos_rate", w.chaos->rate},
          {"chaos_events", w.chaos->events}};
}

}  // namespace boxing
