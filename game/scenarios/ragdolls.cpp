// ragdolls: three limp humanoids and four loose crates dropped onto the arena from a seeded layout, tumbled.
#include <cmath>
#include <string>

#include "game/rng.h"
#include "game/scenarios/scenario_hooks.h"
#include "game/world.h"
#include "game/world_build.h"

namespace boxing {

namespace {
using eng::physics::Geom;
using eng::physics::ShapeType;

// The scenario keeps showing falls (issue 64: it settled in 0.3 s and then showed nothing): every kRedropSeconds one
// ragdoll, in turn, is lifted back to its drop height with a new seeded tumble and at rest, and falls again. 10 s: all
// have come to rest by 8 s (RagdollsScenario.BodiesTumbleCollideAndComeToRestAboveTheFloor).
constexpr double kRedropSeconds = 10.0;

void ragdolls_setup(World& w, Rng& rng) {
  // Limp humanoids and loose crates dropped onto the arena from a seeded layout.
  for (int k = 0; k < 3; ++k) {
    Stance s;
    s.position = {rng.uniform(-1.0, 1.0), rng.uniform(-0.6, 0.6)};
    s.heading = rng.uniform(-M_PI, M_PI);
    s.lead_top = s.rear_top = 0.9 + 0.5 * k;
    add_boxer(w, k, Eigen::Vector3f(0.55f + 0.2f * k, 0.5f, 0.9f - 0.25f * k), true, s);
  }
  for (int k = 0; k < 4; ++k) {
    eng::physics::Body body;
    body.name = "crate" + std::to_string(k);
    body.joint = eng::physics::JointType::Free;
    const double h = rng.uniform(0.12, 0.2);
    body.mass = 6.0;
    body.inertia = (body.mass / 3.0 * h * h) * Eigen::Matrix3d::Identity();
    const int id = w.model.add_body(body);
    Geom g;
    g.shape.type = ShapeType::Box;
    g.shape.half_extents = Eigen::Vector3d(h, h, h);
    g.body = id;
    g.group = 1u << 10;
    w.model.add_geom(g);
    w.loose.push_back(LooseBody{id, g.shape, Eigen::Vector3f(0.5f, 0.33f, 0.17f)});
  }
}

// A ragdoll on its stance, tilted by a random rotation (the tumble), posed to be dropped.
void tumble(World& w, Boxer& b, Rng& rng) {
  b.desired = b.source.tick(0.0);
  place_desired_pose(w.boxer_desc, w.arena, b, b.desired);
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(rng.uniform(0.3, 1.4),
                                                  Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), 0.2)
                                                      .normalized()));
  b.desired.pose.rotation[0] = tilt * b.desired.pose.rotation[0];
  set_character_pose(w.model, w.data, b.bodies, w.boxer_desc, b.desired.pose.root_position, b.desired.pose.rotation);
}

void ragdolls_place(World& w, Rng& rng) {
  for (Boxer& b : w.boxers) tumble(w, b, rng);
  for (size_t k = 0; k < w.loose.size(); ++k) {
    const auto& body = w.model.bodies[w.loose[k].body];
    double* q = w.data.q.data() + body.q_index;
    q[0] = rng.uniform(-1.2, 1.2), q[1] = rng.uniform(-0.8, 0.8), q[2] = 1.5 + 0.4 * k;
    const Eigen::Quaterniond r(Eigen::AngleAxisd(rng.uniform(0, 3), Eigen::Vector3d(0.3, 0.5, 0.8).normalized()));
    q[3] = r.w(), q[4] = r.x(), q[5] = r.y(), q[6] = r.z();
  }
}
void ragdolls_after_step(World& w) {
  const long every = std::lround(kRedropSeconds / kPhysicsDt);
  const long step = w.steps + 1;  // this step's count (step_world counts it after the hooks)
  if (w.boxers.empty() || step % every != 0) return;
  const long drop = step / every;
  Rng rng(w.options.seed * 0x9E3779B97F4A7C15ull + uint64_t(drop));
  Boxer& b = w.boxers[size_t(drop - 1) % w.boxers.size()];
  tumble(w, b, rng);
  for (int body : b.bodies.body) {  // dropped from rest
    const auto& bd = w.model.bodies[body];
    w.data.v.segment(bd.v_index, bd.nv).setZero();
  }
}
}  // namespace

const ScenarioHooks kRagdollsScenario = {
    .walks_graph = false,
    .setup = ragdolls_setup,
    .place = ragdolls_place,
    .after_step = ragdolls_after_step,
    .caption = [](const World& w) -> std::string {
      return "RAGDOLLS: limp bodies dropped on the crates, one again every " + std::to_string(int(kRedropSeconds)) +
             " s (" + std::to_string(int(w.data.time / kRedropSeconds)) + " so far)";
    },
};

}  // namespace boxing
