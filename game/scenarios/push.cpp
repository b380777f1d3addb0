// push: the push-recovery lab (Yin & van de Panne's protocol, Kudoh's experiments): boxer 0 alone on its stance,
// pushed at the chest (--push-force N for --push-duration s from --push-at s, direction --push-dir in its heading
// frame, 0 = where it faces: a push from behind). Alone: a recovery's steps have the platform to themselves (with
// the second boxer on its stance a push from behind stepped boxer 0 into it).
#include <cmath>

#include "engine/physics/step.h"
#include "game/scenarios/scenario_hooks.h"
#include "game/world.h"

namespace boxing {

namespace {
void push_before_step(World& w) {
  const Options& o = w.options;
  if (!w.boxers.empty() && o.push_force > 0 && w.data.time >= o.push_at && w.data.time < o.push_at + o.push_duration) {
    const Boxer& b = w.boxers[0];
    const double a = b.stance.heading + o.push_dir_deg * M_PI / 180.0;
    const Eigen::Vector3d f(o.push_force * std::cos(a), o.push_force * std::sin(a), 0.0);
    const int chest = b.bodies.body[w.boxer_desc.skeleton.find("chest")];
    eng::physics::apply_force_at_point(w.model, w.data, chest, f, w.data.com_world[chest]);
    w.push_active = true;
  }
}

void push_report(const World& w, nlohmann::json& r) {
  const double momentum = w.options.push_force * w.options.push_duration;
  r["push"] = {{"dir_deg", w.options.push_dir_deg},
               {"force_n", w.options.push_force},
               {"duration_s", w.options.push_duration},
               {"at_s", w.options.push_at},
               {"momentum_kg_m_s", momentum}};
}
}  // namespace

const ScenarioHooks kPushScenario = {
    .walks_graph = false,
    .setup = [](World& w, Rng&) { setup_boxers_on_stances(w, 1); },
    .place = place_boxers_on_stances,
    .before_step = push_before_step,
    .report = push_report,
};

}  // namespace boxing
