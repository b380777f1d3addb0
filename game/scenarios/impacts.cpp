// impacts: the paper's Fig. 7 experiment. Three boxers side by side on the crates, facing the camera (-y): world-space
// servo, person-space servo, and world space with the root spring that can be knocked out (its consciousness drops
// with each blow's impulse, the servo's gains with it). A volley of beach balls, then a crate at 8 m/s at each; the
// report says who stayed up. The throws are input events (game/interaction/), the same a player's keys make.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "game/scenarios/scenario_hooks.h"
#include "game/world.h"
#include "game/world_build.h"

namespace boxing {

namespace {

constexpr double kBallsFrom = 1.0, kBallsEvery = 0.25, kCrateAt = 5.0, kCrateEvery = 0.5;
constexpr int kBallsPerBoxer = 5;
constexpr double kCrateSpeed = 8.0, kBallSpeed = 8.0;
constexpr double kSeverityPerNs = 0.01;  // root-spring boxer: consciousness lost per N s of impulse (a crate: ~1.5)
constexpr int kRootBoxer = 2;

void impacts_setup(World& w, Rng&) {
  const Eigen::Vector3f colors[3] = {{0.75f, 0.08f, 0.06f}, {0.06f, 0.18f, 0.75f}, {0.1f, 0.55f, 0.15f}};
  for (int k = 0; k < 3; ++k) {
    add_boxer(w, k, colors[k], false, stance_at(w.arena, Eigen::Vector2d(-1.0 + 1.0 * k, 0.0), -M_PI / 2));
    Boxer& b = w.boxers.back();
    b.settings.space = k == 1 ? eng::control::ServoSpace::Person : eng::control::ServoSpace::World;
    b.settings.root_params.enabled = k == kRootBoxer;
    configure_boxer_control(w, b);
  }
}

void impacts_place(World& w, Rng& rng) {
  place_boxers_on_stances(w, rng);
  // The volley: balls at each boxer in turn, then a crate at each.
  for (int i = 0; i < kBallsPerBoxer * 3; ++i) {
    InputEvent e;
    e.kind = InputKind::Throw;
    e.t = kBallsFrom + kBallsEvery * i;
    e.object_kind = ObjectKind::Ball;
    e.at_boxer = i % 3;
    e.speed = kBallSpeed;
    w.interaction.script.push_back(e);
  }
  for (int k = 0; k < 3; ++k) {
    InputEvent e;
    e.kind = InputKind::Throw;
    e.t = kCrateAt + kCrateEvery * k;
    e.object_kind = ObjectKind::Crate;
    e.at_boxer = k;
    e.speed = kCrateSpeed;
    w.interaction.script.push_back(e);
  }
}

// The root-spring boxer: each blow takes consciousness (RootSpring::hit), its servo follows it (the paper's root
// spring "lowers its motor gains when knocked out").
void impacts_after_step(World& w) {
  Boxer& b = w.boxers[kRootBoxer];
  const auto& hits = w.interaction.object_hits;
  for (auto h = hits.rbegin(); h != hits.rend() && h->t == w.data.time; ++h)  // this step's hits
    if (h->boxer == kRootBoxer) b.ctl.root_spring.hit(b.settings.root_params, kSeverityPerNs * h->impulse);
  b.ctl.gain_scale = 0.3 + 0.7 * b.ctl.root_spring.consciousness();
}

void impacts_report(const World& w, nlohmann::json& r) {
  nlohmann::json boxers = nlohmann::json::array();
  for (const Boxer& b : w.boxers) {
    // Throws that touched this boxer (an object's several hit events on several bones count once).
    int balls = 0, crates = 0;
    std::vector<std::pair<int, double>> seen;
    for (const auto& h : w.interaction.object_hits) {
      if (h.boxer != b.index || std::find(seen.begin(), seen.end(), std::pair(h.object, h.thrown_at)) != seen.end())
        continue;
      seen.emplace_back(h.object, h.thrown_at);
      ++(h.kind == ObjectKind::Ball ? balls : crates);
    }
    const double fell_at = b.metrics.fell ? b.metrics.fell_at : -1.0;
    boxers.push_back({{"boxer", b.index},
                      {"servo", servo_space_name(b.settings.space)},
                      {"root_spring", b.settings.root_params.enabled},
                      {"consciousness", b.ctl.root_spring.consciousness()},
                      {"ball_hits", balls},
                      {"crate_hits", crates},
                      {"stayed_up_after_balls", !b.metrics.fell || fell_at >= kCrateAt},
                      {"stayed_up", !b.metrics.fell},
                      {"fell_at_s", fell_at}});
  }
  r["impacts"] = {{"balls_per_boxer", kBallsPerBoxer},
                  {"ball_speed_mps", kBallSpeed},
                  {"crate_speed_mps", kCrateSpeed},
                  {"crate_at_s", kCrateAt},
                  {"boxers", boxers}};
}

}  // namespace

const ScenarioHooks kImpactsScenario = {
    .walks_graph = false,
    .setup = impacts_setup,
    .place = impacts_place,
    .after_step = impacts_after_step,
    .report = impacts_report,
};

}  // namespace boxing
