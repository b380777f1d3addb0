// push: the push-recovery lab (Yin & van de Panne's protocol, Kudoh's experiments): boxer 0 alone on its stance,
// pushed at the chest (--push-force N for --push-duration s from --push-at s, direction --push-dir in its heading
// frame, 0 = where it faces: a push from behind). Alone: a recovery's steps have the platform to themselves (with
// the second boxer on its stance a push from behind stepped boxer 0 into it).
#include <algorithm>
#include <cmath>
#include <string>

#include "engine/physics/step.h"
#include "engine/physics/dynamics.h"
#include "game/scenarios/scenario_hooks.h"
#include "game/world.h"

namespace boxing {

namespace {
// The trace keeps the first minute (a window left open does not grow it without bound), reserved at setup.
constexpr size_t kTraceSamples = 120 * 60;

// Without --push-force the lab pushes on its own, so it shows a recovery without flags: every kTimerEvery seconds a
// kTimerForce N chest push for kTimerDuration s, its direction turning 45 degrees each time (the push lab grid's
// eight). The force is one the boxer steps out of from every direction, the diagonals included; the measurements
// behind it are in docs/decisions/scenario-captions.md.
constexpr double kTimerEvery = 4.0, kTimerForce = 180.0, kTimerDuration = 0.2;

// The timer's push under way at time t: its number (0, 1, ...), or -1 between pushes.
int timer_push(double t) {
  const int k = int(std::floor(t / kTimerEvery)) - 1;  // the first at kTimerEvery
  return k >= 0 && t - (k + 1) * kTimerEvery < kTimerDuration ? k : -1;
}

void push_before_step(World& w) {
  const Options& o = w.options;
  if (!w.boxers.empty() && o.push_force <= 0 && timer_push(w.data.time) >= 0) {
    const Boxer& b = w.boxers[0];
    const double a = b.stance.heading + 45.0 * timer_push(w.data.time) * M_PI / 180.0;
    const int chest = b.bodies.body[w.boxer_desc.skeleton.find("chest")];
    eng::physics::apply_force_at_point(w.model, w.data, chest, kTimerForce * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0),
                                       w.data.com_world[chest]);
    w.push_active = true;
    return;
  }
  if (!w.boxers.empty() && o.push_force > 0 && w.data.time >= o.push_at && w.data.time < o.push_at + o.push_duration) {
    const Boxer& b = w.boxers[0];
    const double a = b.stance.heading + o.push_dir_deg * M_PI / 180.0;
    // Kudoh's sinusoidal push (thesis Fig. 3.3: 100 sin(2 pi t) N from the front) or a constant pulse.
    const double mag = o.push_sine ? o.push_force * std::sin(2.0 * M_PI * (w.data.time - o.push_at)) : o.push_force;
    const Eigen::Vector3d f(mag * std::cos(a), mag * std::sin(a), 0.0);
    const int chest = b.bodies.body[w.boxer_desc.skeleton.find("chest")];
    eng::physics::apply_force_at_point(w.model, w.data, chest, f, w.data.com_world[chest]);
    w.push_active = true;
  }
}

// Every second step (120 Hz): com, centre of pressure (the ground contacts' forces) and the arms' swing, in the
// stance's frame (scripts/push-lab --kudoh plots them).
void push_after_step(World& w) {
  if (w.boxers.empty() || w.steps % 2 != 0 || w.push_trace.size() >= kTraceSamples) return;
  const Boxer& b = w.boxers[0];
  const auto& m = w.model;
  const auto& d = w.data;
  const int pelvis = b.bodies.body[0];
  const Eigen::Rotation2Dd to_stance(-b.stance.heading);
  const Eigen::Vector2d origin = b.stance.position;
  const Eigen::Vector2d com = to_stance * (eng::physics::subtree_com(m, d, pelvis).head<2>() - origin);
  Eigen::Vector3d cop = Eigen::Vector3d::Zero();
  double fz = 0.0;
  for (const auto& c : d.contacts) {
    if ((c.body_a == 0) == (c.body_b == 0)) continue;  // ground contacts only
    const int body = c.body_a == 0 ? c.body_b : c.body_a;
    if (m.bodies[body].root != pelvis) continue;
    const double f = c.body_b == body ? c.force.z() : -c.force.z();
    cop += f * c.point.position, fz += f;
  }
  const Eigen::Vector2d p = fz > 1e-6 ? Eigen::Vector2d(to_stance * ((cop / fz).head<2>() - origin)) : com;
  const auto& skel = w.boxer_desc.skeleton;
  const Eigen::Vector2d fwd(std::cos(b.stance.heading), std::sin(b.stance.heading));
  double swing[2];
  for (int k = 0; k < 2; ++k) {
    const int ua = b.bodies.body[skel.find(k == 0 ? "upper_arm_l" : "upper_arm_r")];
    const int fa = b.bodies.body[skel.find(k == 0 ? "forearm_l" : "forearm_r")];
    const Eigen::Vector3d along = d.x[fa].p - d.x[ua].p;  // shoulder to elbow (the bodies' joint origins)
    swing[k] = std::atan2(along.head<2>().dot(fwd), -along.z());
  }
  w.push_trace.push_back({d.time, com.x(), com.y(), p.x(), p.y(), swing[0], swing[1]});
}

void push_report(const World& w, nlohmann::json& r) {
  const double momentum = w.options.push_force * w.options.push_duration;
  r["push"] = {{"dir_deg", w.options.push_dir_deg},
               {"force_n", w.options.push_force},
               {"duration_s", w.options.push_duration},
               {"at_s", w.options.push_at},
               {"shape", w.options.push_sine ? "sine" : "pulse"},
               {"momentum_kg_m_s", w.options.push_sine ? 0.0 : momentum},
               {"trace_columns", {"t", "com_x", "com_y", "cop_x", "cop_y", "arm_swing_l", "arm_swing_r"}},
               {"trace", w.push_trace}};
}
}  // namespace

const ScenarioHooks kPushScenario = {
    .walks_graph = false,
    .setup =
        [](World& w, Rng&) {
          setup_boxers_on_stances(w, 1);
          w.push_trace.reserve(kTraceSamples);  // no allocation while it records
        },
    .place = place_boxers_on_stances,
    .before_step = push_before_step,
    .after_step = push_after_step,
    .report = push_report,
    .caption = [](const World& w) -> std::string {
      if (w.options.push_force > 0) return "PUSH LAB: one chest push, as --push-force, --push-dir and --push-at set it";
      // 0 degrees pushes along the heading (from behind), +45 turns the force to the left: from behind-right.
      static const char* const kDir[] = {"from behind", "from behind-right", "from the right", "from front-right",
                                         "from the front", "from front-left", "from the left", "from behind-left"};
      const int next = std::max(0, int(std::floor(w.data.time / kTimerEvery)));
      return "PUSH LAB: a 180 N push every 4 s, 45 degrees on each time. Next: " + std::string(kDir[next % 8]);
    },
};

}  // namespace boxing
