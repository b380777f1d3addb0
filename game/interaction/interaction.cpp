#include "game/interaction/interaction.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "engine/physics/raycast.h"
#include "engine/physics/step.h"
#include "game/match/match.h"
#include "game/world.h"
#include "game/world_build.h"

namespace boxing {

namespace {

using eng::physics::Vec3;
constexpr uint32_t kObjectGroup = 1u << 12;
constexpr double kDueSlack = 1e-9;  // s: an event at t applies at the first step whose time is >= t (1e-9 for sums)

// Where a parked object waits (held there every step, colliding with nothing).
Vec3 park_position(int k) { return Vec3(40.0 + 2.0 * k, 40.0, 5.0); }

void set_free_state(World& w, int body, const Vec3& p, const Eigen::Quaterniond& r, const Vec3& v,
                    const Vec3& omega_body) {
  const auto& b = w.model.bodies[body];
  double* q = w.data.q.data() + b.q_index;
  q[0] = p.x(), q[1] = p.y(), q[2] = p.z(), q[3] = r.w(), q[4] = r.x(), q[5] = r.y(), q[6] = r.z();
  double* v6 = w.data.v.data() + b.v_index;
  for (int i = 0; i < 3; ++i) v6[i] = v[i], v6[3 + i] = omega_body[i];
}

void park(World& w, int k) {
  ThrownObject& o = w.interaction->objects[k];
  o.live = false;
  w.model.geoms[o.geom].group = 0;
  w.model.geoms[o.geom].mask = 0;
  set_free_state(w, o.body, park_position(k), Eigen::Quaterniond::Identity(), Vec3::Zero(), Vec3::Zero());
}

int bone_body(const World& w, int boxer, const std::string& bone) {
  if (boxer < 0 || boxer >= int(w.boxers.size())) return -1;
  const int i = w.boxer_desc.skeleton.find(bone);
  return i < 0 ? -1 : w.boxers[boxer].bodies.body[i];
}

Vec3 world_point(const World& w, int body, const Vec3& local) { return w.data.x[body].apply(local); }

// The body an event means (a boxer's bone or an object), or -1.
int event_body(const World& w, const InputEvent& e) {
  if (e.object >= 0) {
    if (e.object >= int(w.interaction->objects.size()) || !w.interaction->objects[e.object].live) return -1;
    return w.interaction->objects[e.object].body;
  }
  return bone_body(w, e.boxer, e.bone);
}

void start_drag(World& w, int slot, const InputEvent& e, int body) {
  Interaction& in = *w.interaction;
  HeldDrag& h = in.drags[slot];
  h.active = true;
  h.body = body;
  h.local = e.point ? *e.point : w.model.bodies[body].com;
  h.start = world_point(w, body, h.local);
  h.release_at = e.kind == InputKind::Drag ? e.t + e.duration : -1.0;
  Interaction::DragLog log;
  log.boxer = e.object >= 0 ? -1 : e.boxer;
  log.bone = e.object >= 0 ? -1 : w.boxer_desc.skeleton.find(e.bone);
  log.object = e.object;
  log.strong = e.strong;
  log.scripted = e.kind == InputKind::Drag;
  log.t = w.data.time;
  h.log = int(in.drag_log.size());
  in.drag_log.push_back(log);
  eng::physics::PointSpring& s = w.data.point_springs[slot];
  const DragStrength& k = e.strong ? kDragStrong : kDragNormal;
  s.body = body;
  s.local_point = h.local;
  s.target = h.start;
  h.goal = e.kind == InputKind::Drag ? h.start + e.vec : h.start;
  s.hertz = k.hertz;
  s.damping_ratio = k.damping_ratio;
  s.max_force = k.max_force;
  s.active = true;
}

void end_drag(World& w, int slot) {
  HeldDrag& h = w.interaction->drags[slot];
  if (!h.active) return;
  h.active = false;
  w.data.point_springs[slot].active = false;
  w.data.point_springs[slot].impulse.setZero();
  if (h.log >= 0) w.interaction->drag_log[h.log].released_at = w.data.time;
}

void throw_object(World& w, const InputEvent& e) {
  Interaction& in = *w.interaction;
  // The next parked object of the kind, else the one of that kind thrown longest ago.
  int pick = -1;
  for (int k = 0; k < int(in.objects.size()); ++k) {
    const ThrownObject& o = in.objects[k];
    if (o.kind != e.object_kind || o.group == 0) continue;  // group 0: not from the pool (a scenario's crate)
    if (!o.live) {
      pick = k;
      break;
    }
    if (pick < 0 || o.thrown_at < in.objects[pick].thrown_at) pick = k;
  }
  if (pick < 0) return;
  for (int s = 0; s < int(in.drags.size()); ++s)
    if (in.drags[s].active && in.drags[s].body == in.objects[pick].body) end_drag(w, s);
  Vec3 from = e.from, vel = e.velocity;
  if (e.at_boxer >= 0) {
    // From 3 m on the -y side (where the default camera looks from), 0.2 m above the chest, aimed so the ballistic
    // path meets the chest: horizontal speed `speed`, vertical speed that cancels the drop over the flight time.
    const int chest = bone_body(w, e.at_boxer, "chest");
    if (chest < 0) return;
    const Vec3 target = w.data.com_world[chest];
    from = target + Vec3(0.0, -3.0, 0.2);
    const double T = 3.0 / e.speed;
    vel = Vec3(0.0, e.speed, (-0.2 + 0.5 * 9.81 * T * T) / T);
  }
  // A free place to appear: above the crates or floor under it and above any object in play there (a throw at a
  // boxer lying low started inside the crates; one started inside a resting crate: contacts 0.38 m deep), and above
  // any boxer's geom there (boxer 0 thrown at while boxer 1 lay 3 m in front of it, on the throw's line: a ball and
  // a crate started in its pelvis, contacts 10-17 cm deep). A geom's box from the last step's broadphase.
  auto extent = [](ObjectKind k) { return k == ObjectKind::Ball ? kBall.radius : kCrate.half * std::sqrt(3.0); };
  const double ext = extent(e.object_kind);
  double ground = 0.0;  // the highest top under the object's footprint
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) ground = std::max(ground, w.arena.top_at(from.x() + i * ext, from.y() + j * ext));
  from.z() = std::max(from.z(), ground + ext + 0.02);
  for (int pass = 0; pass < 4; ++pass) {
    for (int k = 0; k < int(in.objects.size()); ++k) {
      const ThrownObject& other = in.objects[k];
      if (k == pick || !other.live) continue;
      const Vec3 c = w.data.x[other.body].p;
      const double reach = ext + (other.group == 0 ? 0.3 : extent(other.kind));
      if ((from - c).norm() < reach) from.z() = c.z() + reach + 0.02;
    }
    for (const Boxer& b : w.boxers)
      for (size_t i = 0; i < b.bodies.first_geom.size(); ++i)
        for (int g = b.bodies.first_geom[i]; g < b.bodies.first_geom[i] + b.bodies.geom_count[i]; ++g) {
          if (g >= int(w.data.aabbs.size())) continue;  // before the first step
          const eng::physics::Aabb& box = w.data.aabbs[g];
          if (((from.array() > box.lo.array() - ext) && (from.array() < box.hi.array() + ext)).all())
            from.z() = box.hi.z() + ext + 0.02;
        }
  }
  ThrownObject& o = in.objects[pick];
  o.live = true;
  o.thrown_at = w.data.time;
  w.model.geoms[o.geom].group = o.group;
  w.model.geoms[o.geom].mask = 0xffffffffu;
  set_free_state(w, o.body, from, Eigen::Quaterniond::Identity(), vel, Vec3::Zero());
  ++in.objects_thrown;
}

void apply_settings(World& w, const InputEvent& e) {
  if (e.boxer >= int(w.boxers.size())) return;
  Boxer& b = w.boxers[e.boxer];
  if (b.limp) return;
  bool rebuild = false;
  if (e.servo) b.settings.space = servo_space_from_name(*e.servo), rebuild = true;
  if (e.balance) b.settings.balance_qp = *e.balance == "qp", rebuild = true;
  if (e.omega_n) b.settings.gains.omega_n = *e.omega_n, rebuild = true;
  if (e.root_spring) b.settings.root_params.enabled = *e.root_spring == "on", rebuild = true;
  if (e.root_limit) b.settings.root_params.max_torque = *e.root_limit, rebuild = true;
  if (e.consciousness) b.ctl.root_spring.set_consciousness(*e.consciousness);
  if (e.control && w.match->active && e.boxer < 2) w.match->fighter[e.boxer].player = *e.control == "player";
  if (rebuild) configure_boxer_control(w, b);
}

void apply_event(World& w, const InputEvent& e) {
  Interaction& in = *w.interaction;
  switch (e.kind) {
    case InputKind::Drag: {
      const int body = event_body(w, e);
      if (body < 0) return;
      for (int s = 1; s < int(in.drags.size()); ++s)
        if (!in.drags[s].active) {
          start_drag(w, s, e, body);
          break;
        }
      break;
    }
    case InputKind::Grab: {
      const int body = event_body(w, e);
      end_drag(w, 0);
      if (body >= 0) start_drag(w, 0, e, body);
      break;
    }
    case InputKind::Move:
      if (in.drags[0].active) in.drags[0].goal = e.vec;
      break;
    case InputKind::Release: end_drag(w, 0); break;
    case InputKind::Throw: throw_object(w, e); break;
    case InputKind::Clear:
      for (int s = 0; s < int(in.drags.size()); ++s)
        if (in.drags[s].active) {
          for (const ThrownObject& o : in.objects)
            if (o.group != 0 && o.body == in.drags[s].body) end_drag(w, s);
        }
      for (int k = 0; k < int(in.objects.size()); ++k)
        if (in.objects[k].group != 0) park(w, k);
      break;
    case InputKind::Push: {
      const int body = bone_body(w, e.boxer, e.bone.empty() ? "chest" : e.bone);
      if (body >= 0) in.pushes.push_back({body, e.vec, w.data.time + e.duration});
      break;
    }
    case InputKind::Key:
      for (int i = 0; i < kKeyActionCount; ++i)
        if (e.action == kKeyActions[i]) match_command(w, e.boxer, static_cast<FightCommand>(i + 1));
      break;
    case InputKind::Pad: {
      PadSlot& slot = in.pads[e.pad];
      slot.state = e.pad_state;
      slot.boxer = e.pad_boxer;
      slot.seen = true;
      break;
    }
    case InputKind::Set: apply_settings(w, e); break;
  }
  ++in.events_applied;
  if (in.recording) {
    InputEvent r = e;
    r.t = w.data.time;
    in.recorded.push_back(std::move(r));
  }
}

}  // namespace

void interaction_add_objects(World& w) {
  Interaction& in = *w.interaction;
  auto add = [&](const ObjectSpec& spec, int n) {
    for (int k = 0; k < n; ++k) {
      eng::physics::Body body;
      body.name = std::string(object_kind_name(spec.kind)) + std::to_string(k);
      body.joint = eng::physics::JointType::Free;
      body.mass = spec.mass;
      // A beach ball is a thin shell (2/3 m r^2); a crate a solid cube (m s^2 / 6).
      const double I = spec.kind == ObjectKind::Ball ? 2.0 / 3.0 * spec.mass * spec.radius * spec.radius
                                                     : spec.mass * 4.0 * spec.half * spec.half / 6.0;
      body.inertia = I * eng::physics::Mat3::Identity();
      // A beach ball feels the air and rolls to rest: per-DoF damping (N s/m linear; rolling, the angular part acts
      // as about damping / r^2 = 0.3 N s/m), a time constant of about 2 s. Crates stop by friction.
      body.damping = spec.kind == ObjectKind::Ball ? 0.02 : 0.0;
      ThrownObject o;
      o.kind = spec.kind;
      o.body = w.model.add_body(body);
      eng::physics::Geom g;
      if (spec.kind == ObjectKind::Ball) {
        g.shape.type = eng::physics::ShapeType::Sphere;
        g.shape.radius = spec.radius;
      } else {
        g.shape.type = eng::physics::ShapeType::Box;
        g.shape.half_extents = Vec3::Constant(spec.half);
      }
      g.body = o.body;
      g.friction = spec.friction;
      g.restitution = spec.restitution;
      g.group = 0, g.mask = 0;  // parked
      o.geom = w.model.add_geom(g);
      o.group = kObjectGroup;
      in.objects.push_back(o);
    }
  };
  add(kBall, kPoolBalls);
  add(kCrate, kPoolCrates);
}

void interaction_setup(World& w, std::vector<InputEvent> script) {
  Interaction& in = *w.interaction;
  in.owners = body_owners(int(w.model.bodies.size()), w.boxers, w.boxer_desc.skeleton);
  for (int k = 0; k < int(in.objects.size()); ++k) park(w, k);
  // The scenario's own loose bodies (the ragdolls' crates) can be grabbed too: objects outside the pool.
  for (const LooseBody& l : w.loose) {
    ThrownObject o;
    o.kind = ObjectKind::Crate;
    o.body = l.body;
    o.live = true;
    o.group = 0;
    in.objects.push_back(o);
  }
  // The scenario's own schedule (impacts' volley) and the --input file's, merged in time order.
  in.script.insert(in.script.end(), std::make_move_iterator(script.begin()), std::make_move_iterator(script.end()));
  std::stable_sort(in.script.begin(), in.script.end(), [](const InputEvent& a, const InputEvent& b) { return a.t < b.t; });
  in.next_script = 0;
}

int pads_connected(const Interaction& in) {
  int n = 0;
  for (const PadSlot& p : in.pads) n += p.state.connected ? 1 : 0;
  return n;
}

namespace {

// Every pad read each step (gamepad.h): a held stick's step repeats on the simulation's clock, so a pad's fight
// replays from its recorded events alone. Each action goes to the pad's boxer by the assignment rule.
void read_pads(World& w) {
  Interaction& in = *w.interaction;
  const bool versus = w.options.mode == "versus";
  const int connected = pads_connected(in);
  int rank = 0;
  for (PadSlot& slot : in.pads) {
    if (!slot.state.connected && !slot.reader.last.connected) continue;
    const PadActions acts = pad_update(slot.reader, slot.state, w.data.time);
    const int boxer = slot.boxer >= 0 ? slot.boxer : pad_boxer(rank, connected, versus, w.options.player);
    if (slot.state.connected) ++rank;
    for (int a = 0; a < acts.count && boxer >= 0 && w.match->active; ++a)
      for (int i = 0; i < kKeyActionCount; ++i)
        if (std::strcmp(acts.action[a], kKeyActions[i]) == 0) {
          match_command(w, boxer, static_cast<FightCommand>(i + 1));
          ++slot.actions;
          slot.last_boxer = boxer;
        }
  }
}

}  // namespace

void interaction_submit(World& w, InputEvent e) { w.interaction->queue.push_back(std::move(e)); }

void interaction_begin_step(World& w) {
  Interaction& in = *w.interaction;
  const double now = w.data.time;
  for (int s = 1; s < int(in.drags.size()); ++s)
    if (in.drags[s].active && in.drags[s].release_at >= 0.0 && now >= in.drags[s].release_at - kDueSlack) end_drag(w, s);
  while (in.next_script < in.script.size() && in.script[in.next_script].t <= now + kDueSlack)
    apply_event(w, in.script[in.next_script++]);
  for (const InputEvent& e : in.queue) apply_event(w, e);
  in.queue.clear();
  read_pads(w);
  // Parked objects stay put; live ones that left the world (fell off the edge) are parked.
  for (int k = 0; k < int(in.objects.size()); ++k) {
    const ThrownObject& o = in.objects[k];
    if (o.group == 0) continue;
    if (!o.live) set_free_state(w, o.body, park_position(k), Eigen::Quaterniond::Identity(), Vec3::Zero(), Vec3::Zero());
    else if (w.data.q[w.model.bodies[o.body].q_index + 2] < -3.0) park(w, k);
  }
}

void interaction_apply_forces(World& w) {
  Interaction& in = *w.interaction;
  const double now = w.data.time;
  for (int s = 0; s < int(in.drags.size()); ++s) {
    if (!in.drags[s].active) continue;
    Vec3& target = w.data.point_springs[s].target;
    const Vec3 step = in.drags[s].goal - target;
    const double max_step = kDragTargetSpeed * w.model.dt;
    target += step.norm() > max_step ? Vec3(step * (max_step / step.norm())) : step;
  }
  size_t keep = 0;
  for (size_t i = 0; i < in.pushes.size(); ++i) {
    const ActivePush& p = in.pushes[i];
    if (now >= p.until - kDueSlack) continue;
    eng::physics::apply_force_at_point(w.model, w.data, p.body, p.force, w.data.com_world[p.body]);
    in.pushes[keep++] = p;
  }
  in.pushes.resize(keep);
}

void interaction_after_step(World& w) {
  Interaction& in = *w.interaction;
  for (int s = 0; s < int(in.drags.size()); ++s) {
    const HeldDrag& h = in.drags[s];
    if (!h.active || h.log < 0) continue;
    Interaction::DragLog& log = in.drag_log[h.log];
    log.peak_force = std::max(log.peak_force, w.data.point_springs[s].force.norm());
    // d.x is the pose at the start of this step (step1's kinematics): the displacement one step late.
    log.max_displacement = std::max(log.max_displacement, (world_point(w, h.body, h.local) - h.start).norm());
  }
  for (const eng::physics::HitEvent& hit : w.data.hit_events) {
    const bool boxer_hit = (in.owners[hit.body_a].boxer >= 0 || in.owners[hit.body_b].boxer >= 0) &&
                           hit.body_a > 0 && hit.body_b > 0 && in.owners[hit.body_a].boxer != in.owners[hit.body_b].boxer;
    if (boxer_hit && hit.approach_speed > 1.0) {
      in.flashes[in.next_flash] = {w.data.time, hit.point, hit.approach_speed, hit.normal, hit.impulse};
      in.next_flash = (in.next_flash + 1) % int(in.flashes.size());
    }
    for (int side = 0; side < 2; ++side) {
      const int ob = side ? hit.body_b : hit.body_a, other = side ? hit.body_a : hit.body_b;
      const BodyOwner& owner = in.owners[other];
      if (owner.boxer < 0) continue;
      for (int k = 0; k < int(in.objects.size()); ++k) {
        const ThrownObject& o = in.objects[k];
        if (o.body == ob && o.group != 0)
          in.object_hits.push_back(
              {w.data.time, o.kind, k, o.thrown_at, owner.boxer, owner.bone, hit.approach_speed, hit.impulse});
      }
    }
  }
}

Pick interaction_pick(const World& w, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) {
  Pick p;
  const eng::physics::RayHit hit = eng::physics::raycast(w.model, w.data, origin, dir, 100.0);
  if (!hit.hit || hit.body <= 0) return p;  // nothing, or the floor / a crate of the arena
  p.body = hit.body;
  p.point = hit.point;
  p.local = w.data.x[hit.body].inverse().apply(hit.point);
  p.distance = hit.distance;
  const BodyOwner& owner = w.interaction->owners[hit.body];
  p.boxer = owner.boxer, p.bone = owner.bone;
  for (int k = 0; k < int(w.interaction->objects.size()); ++k)
    if (w.interaction->objects[k].body == hit.body) p.object = k;
  if (p.boxer < 0 && p.object < 0) p.body = -1;
  return p;
}

InputEvent grab_event(const World& w, const Pick& p, bool strong) {
  InputEvent e;
  e.kind = InputKind::Grab;
  e.t = w.data.time;
  if (p.object >= 0) e.object = p.object;
  else e.boxer = p.boxer, e.bone = w.boxer_desc.skeleton.name[p.bone];
  e.point = p.local;
  e.strong = strong;
  return e;
}

bool drag_state(const World& w, int slot, Eigen::Vector3d& point, Eigen::Vector3d& target, double& force,
                double& max_force) {
  const HeldDrag& h = w.interaction->drags[slot];
  if (!h.active) return false;
  const eng::physics::PointSpring& s = w.data.point_springs[slot];
  point = world_point(w, h.body, h.local);
  target = h.goal;
  force = s.force.norm();
  max_force = s.max_force;
  return true;
}

nlohmann::json interaction_report(const World& w) {
  const Interaction& in = *w.interaction;
  nlohmann::json drags = nlohmann::json::array(), hits = nlohmann::json::array();
  for (const Interaction::DragLog& d : in.drag_log) {
    nlohmann::json j = {{"t", d.t},
                        {"released_at", d.released_at},
                        {"strong", d.strong},
                        {"scripted", d.scripted},
                        {"peak_force_n", d.peak_force},
                        {"max_displacement_m", d.max_displacement}};
    if (d.object >= 0) j["object"] = d.object;
    else j["boxer"] = d.boxer, j["bone"] = w.boxer_desc.skeleton.name[d.bone];
    drags.push_back(j);
  }
  for (const Interaction::ObjectHit& h : in.object_hits)
    hits.push_back({{"t", h.t},
                    {"object", object_kind_name(h.kind)},
                    {"object_index", h.object},
                    {"boxer", h.boxer},
                    {"bone", w.boxer_desc.skeleton.name[h.bone]},
                    {"speed_mps", h.speed},
                    {"impulse_ns", h.impulse}});
  nlohmann::json pads = nlohmann::json::array();
  for (int k = 0; k < kMaxPads; ++k)
    if (in.pads[k].seen)
      pads.push_back({{"pad", k},
                      {"connected", in.pads[k].state.connected},
                      {"actions", in.pads[k].actions},
                      {"boxer", in.pads[k].last_boxer}});
  return {{"events_applied", in.events_applied},
          {"pads", pads},
          {"drags", drags},
          {"objects_thrown", in.objects_thrown},
          {"object_hits", hits}};
}

}  // namespace boxing
