#include "game/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "engine/control/biped/foothold.h"
#include "engine/control/servo/composite_inertia.h"
#include "engine/control/servo/implicit_servo.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"
#include "game/audio/sound_events.h"
#include "game/boxer_stepping.h"
#include "game/boxing_motion.h"
#include "game/interaction/chaos.h"
#include "game/interaction/interaction.h"
#include "game/match/match.h"
#include "game/rng.h"
#include "game/scenarios/scenario_hooks.h"
#include "game/world_build.h"

namespace boxing {

namespace fs = std::filesystem;
using eng::physics::Geom;
using eng::physics::Shape;
using eng::physics::ShapeType;

std::string content_dir(const Options& o) {
  if (!o.content_dir.empty()) return o.content_dir;
  if (fs::exists("content/boxer/boxer.gltf")) return "content";
  return BOXING_CONTENT_DIR;
}

namespace {

void add_static_arena(World& w) {
  Geom floor;
  floor.shape.type = ShapeType::Plane;
  floor.body = 0;
  floor.friction = w.tuning.floor_friction;
  floor.group = kStaticGroup;
  w.model.add_geom(floor);
  for (const Crate& c : w.arena.crates) {
    Geom g;
    g.shape.type = ShapeType::Box;
    g.shape.half_extents = c.half_extents;
    g.body = 0;
    g.local.p = c.center;
    g.friction = w.tuning.crate_friction;
    g.group = kStaticGroup;
    w.model.add_geom(g);
  }
  // The ring's corner posts (the ropes between them are forces, ring_ropes.h): static boxes from the floor.
  const Ring& r = w.arena.ring;
  for (int k = 0; k < 4 && r.present; ++k) {
    Geom g;
    g.shape.type = ShapeType::Box;
    const double h = 0.5 * (r.top_mean + r.post_height);
    g.shape.half_extents = Eigen::Vector3d(r.post_half, r.post_half, h);
    g.body = 0;
    g.local.p = Eigen::Vector3d(r.corners[k].x(), r.corners[k].y(), h);
    g.friction = w.tuning.crate_friction;
    g.group = kStaticGroup;
    w.model.add_geom(g);
  }
}

// The bones' mass properties as the control module takes them (bone frame, inertia about the com).
struct BoneMass {
  std::vector<double> mass;
  std::vector<Eigen::Vector3d> com;
  std::vector<Eigen::Matrix3d> inertia;
};

BoneMass bone_mass_of(const eng::assets::CharacterDesc& desc) {
  BoneMass bm;
  for (const auto& b : desc.bones) {
    bm.mass.push_back(b.mass);
    bm.com.push_back(b.com);
    bm.inertia.push_back(b.inertia_diag.asDiagonal());
  }
  return bm;
}

// Per-bone scalar inertia that scales the servo gains (composite inertia of the bone's subtree about its joint).
eng::control::ControlBody control_body_of(const eng::assets::CharacterDesc& desc) {
  const BoneMass bm = bone_mass_of(desc);
  eng::control::ControlBody cb;
  cb.I_eff = eng::control::composite_inertias(desc.skeleton, bm.mass, bm.com, bm.inertia);
  cb.total_mass = desc.total_mass();
  return cb;
}

// World / Person space: eq. 3 as implicit joint springs rooted at the planted feet (implicit_servo.h).
// Gain rule (one omega_n, zeta for the body): K_i = I_i omega_n^2, D_i = 2 zeta I_i omega_n, with I_i the inertia
// joint i has to move (servo_inertias): the bone's subtree for free bones, the load side (rest of the body about
// the joint, shared by the two legs) for thigh / shank / foot. Torque limits from human strength (N m).
void setup_implicit_servo(World& w, Boxer& b) {
  const auto& desc = w.boxer_desc;
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  const BoneMass bm = bone_mass_of(desc);
  const std::vector<double>& mass = bm.mass;
  const std::vector<Eigen::Vector3d>& com = bm.com;
  const std::vector<Eigen::Matrix3d>& inertia = bm.inertia;
  const std::vector<int> feet = {skel.find("foot_l"), skel.find("foot_r")};
  const std::vector<bool> support = eng::control::support_path(skel, feet);
  const bool parent_space =
      b.settings.space == eng::control::ServoSpace::Parent || b.settings.space == eng::control::ServoSpace::ParentMeathook;
  const std::vector<double> I = eng::control::servo_inertias(
      skel, mass, com, inertia, parent_space ? std::vector<bool>(n, false) : support, 2);
  b.ctl.joints.assign(n, {});
  for (int i = 1; i < n; ++i) {
    eng::physics::Body& body = w.model.bodies[b.bodies.body[i]];
    eng::control::ImplicitServoJoint& j = b.ctl.joints[i];
    j.kind = body.joint == eng::physics::JointType::Ball    ? eng::control::JointKind::Ball
             : body.joint == eng::physics::JointType::Hinge ? eng::control::JointKind::Hinge
                                                            : eng::control::JointKind::None;
    if (j.kind == eng::control::JointKind::None) continue;
    j.axis = body.axis;
    // Parent spaces: every joint referenced to its desired parent (planted mode = joint-space PD), gains from
    // the same subtree rule.
    const bool parent_space = b.settings.space == eng::control::ServoSpace::Parent ||
                              b.settings.space == eng::control::ServoSpace::ParentMeathook;
    j.support = parent_space || support[i];
    j.planted = parent_space || (support[i] && std::find(feet.begin(), feet.end(), i) != feet.end());
    j.free_roll = !parent_space && support[i] && skel.parent[i] == 0;  // support hips (thighs)
    j.twist_scale = parent_space ? 1.0 : b.settings.tuning.servo.planted_twist_scale;
    j.K = eng::control::servo_k1(b.settings.gains, I[i]);
    j.D = eng::control::servo_k2(b.settings.gains, I[i]);
    j.limit = j.planted ? b.settings.tuning.servo.ankle_torque_limit : b.settings.tuning.servo.servo_torque_limit;
    // The QP writes joint torques (d.tau): no servo springs in the model.
    if (!std::visit([](const auto& c) { return model_springs(c); }, b.ctl.balance)) continue;
    body.stiffness = j.K;
    body.damping += j.D;  // on top of the content's passive joint damping
  }
  b.scratch.q_joint.assign(n, Eigen::Vector3d::Zero());
  b.scratch.spring_ref.assign(n, Eigen::Vector3d::Zero());
}

}  // namespace

void configure_boxer_control(World& w, Boxer& b) {
  // The content's passive joint damping back (the servo's springs are added on top by setup_implicit_servo).
  for (int i = 0; i < w.boxer_desc.skeleton.size(); ++i) {
    eng::physics::Body& body = w.model.bodies[b.bodies.body[i]];
    body.stiffness = 0.0;
    body.damping = w.boxer_desc.bones[i].damping;
  }
  // The balance controller: the QP for a servo rooted at the feet, else the PD layer. Kept when the kind is the
  // same (its warm start and statistics carry on).
  const bool qp = b.settings.balance_qp && b.settings.space != eng::control::ServoSpace::Parent &&
                  b.settings.space != eng::control::ServoSpace::ParentMeathook;
  if (qp && !b.uses_qp()) b.ctl.balance = QpBalance{};
  if (!qp && b.uses_qp()) b.ctl.balance = PdBalance{};
  // Under the balance QP the root spring is the QP's root assist (balance_qp.h): the plan chooses the torque.
  if (QpBalance* q = std::get_if<QpBalance>(&b.ctl.balance)) {
    q->params.w_root_assist = b.settings.root_params.enabled ? b.settings.tuning.root.assist_price : 0.0;
    q->params.max_root_assist = b.settings.root_params.max_torque;
    q->params.w_torque = b.settings.root_params.enabled ? b.settings.tuning.root.qp_torque_price : 0.0;
    // The per-tick contact lists at their capacity once (twice what the plan takes, kQpMaxContacts): grown past a
    // warm-up's high-water mark in a recovery, they would allocate in the step.
    constexpr int contacts = 2 * eng::control::kQpMaxContacts;
    q->in.contacts.reserve(contacts);
    q->out.contact_force.reserve(contacts);
    q->pts.reserve(contacts);
    q->hull.reserve(contacts);
    q->in.separations.reserve(kMaxLegSeparations);
    const auto& skel = w.boxer_desc.skeleton;
    q->trunk.assign(skel.size(), 0);
    q->arm.assign(skel.size(), 0);
    for (int i = 0; i < skel.size(); ++i) {
      const std::string& name = skel.name[i];
      q->trunk[i] = i == 0 || name == "abdomen" || name == "chest" || name == "neck" || name == "head";
      q->arm[i] = name.rfind("upper_arm", 0) == 0 || name.rfind("forearm", 0) == 0;
    }
  }
  setup_implicit_servo(w, b);
}

void add_boxer(World& w, int index, const Eigen::Vector3f& color, bool limp, const Stance& stance) {
  Boxer b;
  b.index = index;
  b.team_color = color;
  b.stance = stance;
  b.limp = limp;
  b.bones = eng::control::biped_bones(w.boxer_desc.skeleton, boxing::kBoxerLegs);
  if (w.options.contact_gap >= 0.0) {  // the unified-threshold experiment (docs/decisions/foot-contact-thresholds.md)
    eng::control::FootContactThresholds& t = b.settings.tuning.contact;
    t.support = t.load = t.fallen = w.options.contact_gap;
    b.settings.tuning.qp.touch_gap = w.options.contact_gap;
  }
  const uint32_t group = 2u << index;
  b.bodies = add_character(w.model, w.boxer_desc, "b" + std::to_string(index) + "_", group, 0xffffffffu, false);
  // The thighs hold each other off: passing through each other, a sideways push's cross-over stands with its thighs
  // in an X. The shanks and feet still pass: colliding too, a cross-over's next step, from behind the stance leg to
  // in front of it, catches on it and the boxer falls (docs/decisions/balance-steps.md).
  set_self_colliding(w.model, b.bodies, {b.bones.leg[0].thigh, b.bones.leg[1].thigh});
  b.settings.space = servo_space_from_name(w.options.servo);
  b.settings.balance_qp = w.options.balance == "qp";
  // Balance steps: on in the push lab and where the boxers walk the graph (the match, the walk), there past what the
  // root assist holds (BalanceStepTuning::assist_reach_share: none in the twelve 10-minute walks, a few a match); the
  // stand's drags (no root help) keep them off as they were measured (docs/decisions/balance-steps.md).
  const bool steps_by_default =
      w.options.scenario_id == Scenario::Push || scenario_hooks(w.options.scenario_id).walks_graph;
  b.settings.stepping = w.options.stepping == "on" || (w.options.stepping == "auto" && steps_by_default);
  b.settings.tuning.step.carry = w.options.footwork == "carry";
  b.settings.tuning.stand_up.unassisted = w.options.getup == "unassisted";
  if (w.options.priorities == "kudoh") {  // the fight's (MatchTuning, match_setup), in any scenario
    b.settings.tuning.qp.trunk_weight = MatchTuning{}.trunk_weight;
    b.settings.tuning.qp.com_weight = MatchTuning{}.com_weight;
  }
  if (w.options.stance_drop >= 0.0) b.settings.tuning.qp.stance_drop = w.options.stance_drop;
  b.settings.placement = w.options.step_placement == "ipc" ? eng::control::StepPlacement::InvertedPendulumLqr
                                                           : eng::control::StepPlacement::CapturePoint;
  b.settings.gains.omega_n = w.options.servo_omega_n;
  b.settings.gains.zeta = w.options.servo_zeta;
  b.settings.gains.stable_pd = true;
  b.settings.gains.dt = kPhysicsDt;
  b.control_body = control_body_of(w.boxer_desc);
  b.ctl.servo.resize(w.boxer_desc.skeleton.size());
  if (b.settings.placement == eng::control::StepPlacement::InvertedPendulumLqr) {
    // Kwon & Hodgins' pendulum: the com's standing height over the soles, the feet and shanks as the cart.
    const double m = b.control_body.total_mass, cart = b.settings.tuning.balance_step.cart_mass_fraction * m;
    b.ctl.step_lqr = eng::control::solve_cart_pole_lqr(w.tuning.standing_com_height, m - cart, cart);
  }
  // The root spring: asked for, or (auto) for the paper's boxers, the graph walk and the match.
  const bool boxers = scenario_hooks(w.options.scenario_id).walks_graph;
  b.settings.root_params.enabled = !limp && (w.options.root_spring == "on" || (w.options.root_spring == "auto" && boxers));
  const bool qp = !limp && b.settings.balance_qp && b.settings.space != eng::control::ServoSpace::Parent &&
                  b.settings.space != eng::control::ServoSpace::ParentMeathook;
  b.settings.root_params.max_torque = w.options.root_spring_max >= 0.0 ? w.options.root_spring_max
                                      : qp                            ? b.settings.tuning.root.assist_max
                                                                      : b.settings.tuning.root.spring_max;
  if (!limp) configure_boxer_control(w, b);
  else b.ctl.balance = PdBalance{};
  if (scenario_hooks(w.options.scenario_id).walks_graph) {
    // The paper's boxers: a seeded random walk of the motion graph (each boxer its own stream).
    b.source = PoseSource::graph_walk(w.graph, w.options.seed * 2654435761ull + uint64_t(index));
  } else {
    const int guard = eng::anim::find_clip(w.clips, "guard");
    const int drill = w.options.drill_clip.empty() ? -1 : eng::anim::find_clip(w.clips, w.options.drill_clip);
    b.source = drill >= 0 ? PoseSource::drill(w.clips[guard >= 0 ? guard : 0], w.clips[drill], w.options.drill_every)
                          : PoseSource::looping_clip(w.clips[guard >= 0 ? guard : 0]);
  }
  w.boxers.push_back(std::move(b));
}

void place_boxer(World& w, Boxer& b) {
  b.desired = b.source.tick(0.0);
  place_desired_pose(w.boxer_desc, w.arena, b, b.desired);
  set_character_pose(w.model, w.data, b.bodies, w.boxer_desc, b.desired.pose.root_position, b.desired.pose.rotation);
}

World::World() = default;
World::~World() = default;

eng::Result<std::unique_ptr<World>> make_world(const Options& o) {
  auto w = std::make_unique<World>();
  w->match = std::make_unique<Match>();
  w->interaction = std::make_unique<Interaction>();
  w->chaos = std::make_unique<Chaos>();
  w->options = o;
  const std::string dir = content_dir(o);
  auto scene = eng::assets::load_gltf(dir + "/boxer/boxer.gltf");
  if (!scene) return eng::make_error("boxing: " + scene.error());
  w->boxer_scene = std::move(*scene);
  auto desc = eng::assets::load_character(w->boxer_scene);
  if (!desc) return eng::make_error("boxing: " + desc.error());
  w->boxer_desc = std::move(*desc);
  auto clips = eng::anim::load_clips(dir + "/clips/boxing_clips.gltf", w->boxer_desc.skeleton);
  if (!clips) return eng::make_error("boxing: " + clips.error());
  w->clips = std::move(*clips);
  if (w->clips.empty()) return eng::make_error("boxing: no clips in " + dir + "/clips/boxing_clips.gltf");
  if (!o.drill_clip.empty() && eng::anim::find_clip(w->clips, o.drill_clip) < 0)
    return eng::make_error("boxing: --clip '" + o.drill_clip + "' is not a clip in " + dir +
                           "/clips/boxing_clips.gltf (see `build/boxing graph --report g.json` for the names)");

  // The match fights in the ring (arena.h make_ring: a 5 m square of crates inside ropes, the boxers 2.8 m apart);
  // the other scenarios on the plain platform.
  w->arena = o.scenario_id == Scenario::Match ? make_ring(o.seed, kRingMinStep, o.start_apart)
                                              : make_arena(o.seed, w->tuning.arena_min_step, kBoxerSeparation, o.flat);
  w->model.dt = kPhysicsDt;
  add_static_arena(*w);

  Rng rng(o.seed ^ 0xB0C5ull);
  const ScenarioHooks& scenario = scenario_hooks(o.scenario_id);
  if (scenario.walks_graph)
    w->graph.build(w->clips, eng::anim::GraphOptions{}, boxing_graph_options(w->boxer_desc.skeleton),
                   w->boxer_desc.skeleton);
  std::vector<InputEvent> script;
  if (!o.input.empty()) {
    auto events = load_input_file(o.input);
    if (!events) return eng::make_error(events.error());
    script = std::move(*events);
  }
  scenario.setup(*w, rng);
  interaction_add_objects(*w);  // after the scenario's bodies: their indices do not depend on the pool
  w->model.finalize();
  w->data = eng::physics::make_data(w->model);

  scenario.place(*w, rng);
  interaction_setup(*w, std::move(script));
  w->interaction->recording = !o.record.empty();
  chaos_setup(*w);
  eng::physics::forward_kinematics(w->model, w->data);
  for (Boxer& b : w->boxers) {
    boxer_sense_contacts(w->data, b);
    // The steps' foothold searches sorted now: the world's step allocates nothing (the first carried step of a
    // walk came after any warm-up).
    for (const eng::control::FootholdParams* p : {&b.settings.tuning.step.foothold, &b.settings.tuning.step.carry_foothold,
                                                  &b.settings.tuning.balance_step.foothold,
                                                  &b.settings.tuning.balance_step.replace_foothold})
      eng::control::prepare_foothold_search(*p);
  }
  w->sounds = std::make_unique<SoundEventLog>();
  sound_events_setup(*w, *w->sounds);
  return w;
}

namespace {
// Boxers the hands hold, push or hit with a thrown object now are handled for another WorldTuning::handled_hold
// seconds (BoxerControlState::handled_until).
void mark_handled_boxers(World& w) {
  const Interaction& in = *w.interaction;
  auto mark = [&w](int body) {
    if (body < 0 || body >= int(w.interaction->owners.size())) return;
    const int k = w.interaction->owners[body].boxer;
    if (k >= 0 && k < int(w.boxers.size())) w.boxers[k].ctl.handled_until = w.data.time + w.tuning.handled_hold;
  };
  for (const HeldDrag& h : in.drags)
    if (h.active) mark(h.body);
  for (const ActivePush& p : in.pushes) mark(p.body);
  // A thrown object's hit (the last step's, recorded after it) hands the boxer over to the plain priorities too.
  for (auto h = in.object_hits.rbegin(); h != in.object_hits.rend() && h->t >= w.data.time - kPhysicsDt; ++h)
    if (h->boxer >= 0 && h->boxer < int(w.boxers.size()))
      w.boxers[h->boxer].ctl.handled_until = w.data.time + w.tuning.handled_hold;
  // The player's hands act through a handled boxer on whatever it touches: a boxer struck by the other one as it is
  // dragged or thrown about is handled too (held to Kudoh's trunk priority under such a blow, a standing boxer whips
  // an arm far past any punch's speed).
  for (const auto& c : w.data.prev_contacts) {
    if (c.body_a == 0 || c.body_b == 0 || c.body_a >= int(in.owners.size()) || c.body_b >= int(in.owners.size())) continue;
    const int ka = in.owners[c.body_a].boxer, kb = in.owners[c.body_b].boxer;
    if (ka < 0 || kb < 0 || ka == kb || ka >= int(w.boxers.size()) || kb >= int(w.boxers.size())) continue;
    double& ua = w.boxers[ka].ctl.handled_until;
    double& ub = w.boxers[kb].ctl.handled_until;
    if (w.data.time < ua) ub = std::max(ub, ua);
    else if (w.data.time < ub) ua = std::max(ua, ub);
  }
}
}  // namespace

void step_world(World& w) {
  using clock = std::chrono::steady_clock;
  auto ms = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  const auto t0 = clock::now();
  chaos_begin_step(w);        // --chaos: maybe a random event, through the same path as the player's
  interaction_begin_step(w);  // input events due now: throws set coordinates, so before the step's first half
  eng::physics::clear_applied(w.data);
  for (Boxer& b : w.boxers) boxer_joint_speed_limits(w.model, b, w.data.time);  // read by step1's mass matrix
  // The step's first half (kinematics, contacts, rows, the mass matrix and c(q, v)) once, for the physics and for
  // every boxer's control: the balance QPs read their blocks of d.M_crba and d.qfrc_bias (MuJoCo's mj_step1 /
  // mj_step2 split). Control then writes torques, spring references and forces for the second half.
  eng::physics::StageTimes* physics_stages = w.profile_stages ? &w.profile.physics : nullptr;
  ControlStageTimes* control_stages = w.profile_stages ? &w.profile.control : nullptr;
  eng::physics::step1(w.model, w.data, physics_stages);
  const auto t1 = clock::now();
  const ScenarioHooks& scenario = scenario_hooks(w.options.scenario_id);
  if (scenario.before_control) scenario.before_control(w);
  mark_handled_boxers(w);
  for (Boxer& b : w.boxers) boxer_control(w.model, w.data, w.boxer_desc, w.arena, b, kPhysicsDt, control_stages);

  // The scenario's forces (the push scenario's chest push).
  w.push_active = false;
  if (scenario.before_step) scenario.before_step(w);
  interaction_apply_forces(w);
  ring_ropes_apply(w, kPhysicsDt);  // the ring's ropes push back a boxer past them (nothing without a ring)
  const auto t2 = clock::now();

  eng::physics::step2(w.model, w.data, physics_stages);
  const auto t3 = clock::now();
  for (Boxer& b : w.boxers) boxer_sense_contacts(w.data, b);
  for (Boxer& b : w.boxers) observe_push(w.model, w.data, b, kPhysicsDt);
  for (Boxer& b : w.boxers) boxer_measure(w.model, w.data, w.boxer_desc, b, kPhysicsDt);
  for (Boxer& b : w.boxers) detect_fall(w.data, b, kPhysicsDt);
  interaction_after_step(w);  // (the scenario's after_step reads this step's object hits)
  health_after_step(w);
  if (scenario.after_step) scenario.after_step(w);
  measure_getups(w);  // after the scenario's (the match's referee calls a boxer up or down there)
  if (w.sounds) collect_sound_events(w, *w.sounds);  // read-only: what this tick sounds like (game/audio/)
  ++w.steps;
  const auto t4 = clock::now();
  w.profile.step1_ms += ms(t0, t1), w.profile.control_ms += ms(t1, t2), w.profile.step2_ms += ms(t2, t3);
  w.profile.sense_ms += ms(t3, t4);
  w.physics_ms_total += ms(t0, t4);
}

namespace {
// Mean wall time per 240 Hz tick of each stage of step_world (this machine; reporting only). step1 + control + step2
// + sense is the whole tick. With the stages profiled, also their split (docs/decisions/tick-stages.md): physics
// (collision, dynamics, solver, integration; physics_other: step1's input events and clear_applied), control (graph,
// pose, stepping, servo, qp summed over the boxers, qp_solve the part of qp in the QP's solve; control_other: the
// scenario's and the player's forces). These with sense add up to the tick.
nlohmann::json tick_profile_report(const World& w) {
  const World::TickProfile& p = w.profile;
  const double n = w.steps ? static_cast<double>(w.steps) : 1.0;
  nlohmann::json r = {{"step1", p.step1_ms / n}, {"control", p.control_ms / n}, {"step2", p.step2_ms / n},
                      {"sense", p.sense_ms / n}};
  if (!w.profile_stages) return r;
  double qp_solve_ms = 0.0;  // the QP histograms' sums (they record every solve since the start, as the profile)
  for (const Boxer& b : w.boxers)
    if (b.uses_qp()) {
      const eng::core::LatencyHistogram& h = std::get<QpBalance>(b.ctl.balance).solve_us;
      qp_solve_ms += 1e-3 * h.mean_us() * static_cast<double>(h.count());
    }
  r["collision"] = p.physics.collision / n;
  r["dynamics"] = p.physics.dynamics / n;
  r["solver"] = p.physics.solver / n;
  r["integration"] = p.physics.integration / n;
  r["physics_other"] = (p.step1_ms + p.step2_ms - p.physics.total()) / n;
  r["graph"] = p.control.graph / n;
  r["pose"] = p.control.pose / n;
  r["stepping"] = p.control.stepping / n;
  r["servo"] = p.control.servo / n;
  r["qp"] = p.control.qp / n;
  r["qp_solve"] = qp_solve_ms / n;
  r["control_other"] = (p.control_ms - p.control.total()) / n;
  return r;
}

// The balance QP's solve cost (wall clock, this machine): median and 95th percentile per boxer; null with PD.
nlohmann::json qp_report(const Boxer& b) {
  if (!b.uses_qp()) return nullptr;
  const eng::core::LatencyHistogram& h = std::get<QpBalance>(b.ctl.balance).solve_us;
  return {{"solves", h.count()}, {"solve_us_median", h.percentile(50)}, {"solve_us_p95", h.percentile(95)}};
}

// How far the clip's steps carried the feet (BoxerMetrics::step_travel_*): count, mean and spread of the fraction.
nlohmann::json step_travel_report(const BoxerMetrics& m) {
  const int n = m.step_travel_count;
  const double mean = n > 0 ? m.step_travel_sum / n : 0.0;
  const double sd = n > 1 ? std::sqrt(std::max(0.0, (m.step_travel_sq - n * mean * mean) / (n - 1))) : 0.0;
  return {{"steps", n}, {"mean_fraction", mean}, {"sd_fraction", sd}};
}
}  // namespace

nlohmann::json world_report(const World& w) {
  nlohmann::json boxers = nlohmann::json::array();
  for (const Boxer& b : w.boxers) {
    const BoxerMetrics& m = b.metrics;
    nlohmann::json err = nlohmann::json::object(), err_up = nlohmann::json::object();
    double total = 0, total_up = 0;
    for (int i = 0; i < w.boxer_desc.skeleton.size() && m.samples > 0; ++i) {
      const double rms = std::sqrt(m.err_sq_sum[i] / m.samples);
      err[w.boxer_desc.skeleton.name[i]] = rms;
      total += m.err_sq_sum[i] / m.samples;
      if (m.samples_upright == 0) continue;
      err_up[w.boxer_desc.skeleton.name[i]] = std::sqrt(m.err_sq_upright[i] / m.samples_upright);
      total_up += m.err_sq_upright[i] / m.samples_upright;
    }
    boxers.push_back({{"index", b.index},
                      {"servo", b.limp ? "limp" : servo_space_name(b.settings.space)},
                      {"balance", b.limp ? "none" : b.uses_qp() ? "qp" : "pd"},
                      {"fell", m.fell},
                      {"fell_at_s", m.fell_at},
                      {"steps_taken", m.steps_taken},
                      {"steps_skipped", m.steps_skipped},
                      {"steps_in_place", m.steps_in_place},
                      {"steps_landed_in_place", m.steps_landed_in_place},
                      {"step_travel", step_travel_report(m)},
                      {"balance_steps", m.balance_steps},
                      {"return_steps", m.return_steps},
                      {"footwork", {{"moves", b.ctl.footwork.moves}, {"steps", b.ctl.footwork.steps},
                                    {"dropped", b.ctl.footwork.dropped}}},
                      {"most_steps_in_recovery", m.most_steps_in_recovery},
                      {"late_landings", m.late_landings},
                      {"replacements", m.replacements},
                      {"balance_step_miss_mean_m", m.landings[0] ? m.landing_miss_sum[0] / m.landings[0] : 0.0},
                      {"return_step_miss_mean_m", m.landings[1] ? m.landing_miss_sum[1] / m.landings[1] : 0.0},
                      {"legs_overlap_max_m", m.legs_overlap_max},
                      {"legs_overlap_s", m.legs_overlap_s},
                      {"thighs_touch_s", m.thighs_touch_s},
                      // On its feet at the end in a stance it can fight from (the return step's test: not crossed, not in
                      // line; false once fallen).
                      {"stance_can_fight_end", !b.limp && !m.fell && stance_can_fight(w.data, b)},
                      // Its feet on a poor foothold at the end (an edge under the sole, by the clips' margins; 0-2, on
                      // its feet only).
                      {"feet_on_edge_end", b.limp || m.fell ? 0 : int(on_poor_foothold(w.data, w.arena, b, 0)) +
                                                                    int(on_poor_foothold(w.data, w.arena, b, 1))},
                      {"fell_pelvis_m", {m.fell_pelvis.x(), m.fell_pelvis.y(), m.fell_pelvis.z()}},
                      {"fell_reason", m.fell_reason},
                      {"time_upright_s", m.time_upright},
                      {"max_com_speed", m.max_com_speed},
                      {"arm_off_guard_s", m.arm_off_guard_s},
                      {"arm_error_end_rad", m.arm_error_end},
                      {"root_spring",
                       {{"enabled", b.settings.root_params.enabled},
                        {"max_torque_nm", b.settings.root_params.max_torque},
                        {"rms_torque_nm", m.time_upright > 0 ? std::sqrt(m.root_torque_sq_dt / m.time_upright) : 0.0},
                        {"peak_torque_nm", m.root_torque_peak},
                        {"saturated_fraction", m.time_upright > 0 ? m.root_saturated_time / m.time_upright : 0.0}}},
                      {"qp", qp_report(b)},
                      {"rms_tracking_error_rad", err},
                      {"rms_tracking_error_all_bones_rad",
                       m.samples > 0 ? std::sqrt(total / w.boxer_desc.skeleton.size()) : 0.0},
                      {"rms_tracking_error_upright_rad", err_up},  // only before the first fall
                      {"rms_tracking_error_upright_all_bones_rad",
                       m.samples_upright > 0 ? std::sqrt(total_up / w.boxer_desc.skeleton.size()) : 0.0},
                      {"clips_visited_s", b.source.clip_time()},
                      {"clip_timeline", b.source.timeline()},
                      {"stance_lead_top_m", b.stance.lead_top},
                      {"stance_rear_top_m", b.stance.rear_top},
                      {"trace", m.trace},
                      {"feet_start", {std::vector<double>(m.foot0[0].data(), m.foot0[0].data() + 3),
                                      std::vector<double>(m.foot0[1].data(), m.foot0[1].data() + 3)}},
                      {"feet_slide_m", {m.foot_slide[0], m.foot_slide[1]}}});
  }
  nlohmann::json r = {{"scenario", scenario_name(w.options.scenario_id)},
                      {"physics_steps", w.steps},
                      {"physics_dt", kPhysicsDt},
                      {"physics_ms_per_step", w.steps ? w.physics_ms_total / w.steps : 0.0},
                      {"tick_profile_ms", tick_profile_report(w)},
                      {"boxers", boxers},
                      {"interaction", interaction_report(w)},
                      {"health", health_report(w)},
                      {"getups", getups_report(w)}};
  if (const auto report = scenario_hooks(w.options.scenario_id).report) report(w, r);
  return r;
}

}  // namespace boxing
