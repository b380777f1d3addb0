// impacts: the paper's Fig. 7 experiment. Three boxers side by side on the crates, facing the camera (-y): world-space
// servo, person-space servo, and world space with the root spring that can be knocked out (its consciousness drops
// with each blow's impulse, the servo's gains with it). A volley of beach balls, then a crate at 8 m/s at each; the
// report says who stayed up. The throws are input events (game/interaction/), the same a player's keys make.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "game/interaction/interaction.h"
#include "game/scenarios/scenario_hooks.h"
#include "game/world.h"
#include "game/world_build.h"

namespace boxing {

namespace {

// The experiment's layout, volley and knock-out rule (each function reads the defaults: ImpactsTuning{}).
struct ImpactsTuning {
  double spacing = 1.0;            // m between the three boxers (side by side, the middle one at x = 0)
  int root_boxer = 2;              // which boxer has the root spring (and is knocked out by the blows)
  double balls_from = 1.0;         // s, the first ball
  double balls_every = 0.25;       // s between balls (each at the next boxer in turn)
  int balls_per_boxer = 5;         // balls thrown at each boxer
  double ball_speed = 8.0;         // m/s
  double crate_at = 5.0;           // s, the first crate (after the volley)
  double crate_every = 0.5;        // s between crates (one at each boxer)
  double crate_speed = 8.0;        // m/s
  // The root-spring boxer's consciousness lost per N s of impulse (a crate's blow: about 1.5): more, fewer blows fell it.
  double severity_per_ns = 0.01;
  // Its servo gains' scale: gain_floor + gain_span x consciousness (the paper's lowered motor gains when knocked out).
  double gain_floor = 0.3, gain_span = 0.7;
};

void impacts_setup(World& w, Rng&) {
  const ImpactsTuning tu;
  const Eigen::Vector3f colors[3] = {{0.75f, 0.08f, 0.06f}, {0.06f, 0.18f, 0.75f}, {0.1f, 0.55f, 0.15f}};
  for (int k = 0; k < 3; ++k) {
    add_boxer(w, k, colors[k], false, stance_at(w.arena, Eigen::Vector2d(-tu.spacing + tu.spacing * k, 0.0), -M_PI / 2));
    Boxer& b = w.boxers.back();
    b.settings.space = k == 1 ? eng::control::ServoSpace::Person : eng::control::ServoSpace::World;
    b.settings.root_params.enabled = k == tu.root_boxer;
    configure_boxer_control(w, b);
  }
}

void impacts_place(World& w, Rng& rng) {
  const ImpactsTuning tu;
  place_boxers_on_stances(w, rng);
  // The volley: balls at each boxer in turn, then a crate at each.
  for (int i = 0; i < tu.balls_per_boxer * 3; ++i) {
    InputEvent e;
    e.kind = InputKind::Throw;
    e.t = tu.balls_from + tu.balls_every * i;
    e.object_kind = ObjectKind::Ball;
    e.at_boxer = i % 3;
    e.speed = tu.ball_speed;
    w.interaction->script.push_back(e);
  }
  for (int k = 0; k < 3; ++k) {
    InputEvent e;
    e.kind = InputKind::Throw;
    e.t = tu.crate_at + tu.crate_every * k;
    e.object_kind = ObjectKind::Crate;
    e.at_boxer = k;
    e.speed = tu.crate_speed;
    w.interaction->script.push_back(e);
  }
}

// The root-spring boxer: each blow takes consciousness (RootSpring::hit), its servo follows it (the paper's root
// spring "lowers its motor gains when knocked out").
void impacts_after_step(World& w) {
  const ImpactsTuning tu;
  Boxer& b = w.boxers[tu.root_boxer];
  const auto& hits = w.interaction->object_hits;
  for (auto h = hits.rbegin(); h != hits.rend() && h->t == w.data.time; ++h)  // this step's hits
    if (h->boxer == tu.root_boxer) b.ctl.root_spring.hit(b.settings.root_params, tu.severity_per_ns * h->impulse);
  b.ctl.gain_scale = tu.gain_floor + tu.gain_span * b.ctl.root_spring.consciousness();
}

void impacts_report(const World& w, nlohmann::json& r) {
  const ImpactsTuning tu;
  nlohmann::json boxers = nlohmann::json::array();
  for (const Boxer& b : w.boxers) {
    // Throws that touched this boxer (an object's several hit events on several bones count once).
    int balls = 0, crates = 0;
    std::vector<std::pair<int, double>> seen;
    for (const auto& h : w.interaction->object_hits) {
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
                      {"stayed_up_after_balls", !b.metrics.fell || fell_at >= tu.crate_at},
                      {"stayed_up", !b.metrics.fell},
                      {"fell_at_s", fell_at}});
  }
  r["impacts"] = {{"balls_per_boxer", tu.balls_per_boxer},
                  {"ball_speed_mps", tu.ball_speed},
                  {"crate_speed_mps", tu.crate_speed},
                  {"crate_at_s", tu.crate_at},
                  {"boxers", boxers}};
}

}  // namespace

const ScenarioHooks kImpactsScenario = {
    .walks_graph = false,
    .setup = impacts_setup,
    .place = impacts_place,
    .after_step = impacts_after_step,
    .report = impacts_report,
    .caption = [](const World&) -> std::string {
      return "IMPACTS (the paper's Fig. 7): world space, person space, a root spring; balls, then a crate";
    },
};

}  // namespace boxing
