// Chaos (game/interaction/chaos.h): seeded random drags, pushes and throws through the hands' path; the health the
// report measures stays within bounds, and the same seed gives the same chaos.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "game/cli.h"
#include "game/interaction/interaction.h"
#include "game/match/match.h"
#include "game/seed_rate.h"
#include "game/world.h"

namespace {
nlohmann::json run(const std::vector<std::string>& args, double seconds) {
  auto o = boxing::parse_cli(args);
  EXPECT_TRUE(o.ok()) << o.error();
  auto w = boxing::make_world(*o);
  EXPECT_TRUE(w.ok());
  while ((*w)->data.time < seconds) boxing::step_world(**w);
  return boxing::world_report(**w);
}
}  // namespace

// 40 s of the stand scenario at 2 events a second (about 80 drags, pushes and throws), seeds 1-2, every seed required
// (health is not a rate): every step finite, no boxer body over 30 m/s, no body centre in a crate or under the floor,
// contacts no deeper than 6 cm, and the events happen.
// Where the bounds come from. Events: 2 a second for 40 s is 80 expected, Poisson's sd 9; 50 is 3.3 sd under.
// Penetration: a contact is seen only in the step after it began, as deep as that step's approach: the fastest throw
// (12 m/s, chaos.cpp) travels 5 cm in a 1/240 s step, and the limb it meets adds its own speed (2.4 m/s allowed: 1 cm;
// the 5.6 cm seen on an older build, a ball into a forearm, is 13.4 m/s of approach): bound 6 cm. measured (this build,
// seeds 1-10, 40 s, `boxing --headless --scenario stand --chaos 2 --seconds 40 --report`): p50 2.0 cm, max 4.4 cm
// (seed 4); 59-103 events (docs/decisions/test-bounds.md).
TEST(Chaos, TwoEventsASecondKeepTheSimulationHealthy) {
  const seed_rate::Rate r = seed_rate::over_seeds("stand 40 s, chaos 2 a second", 1, 2, [](int seed) {
    const nlohmann::json rep = run({"--scenario", "stand", "--seed", std::to_string(seed), "--chaos", "2"}, 40.0);
    const auto& h = rep["health"];
    seed_rate::Why why;
    why.check(h["chaos_events"].get<int>() >= 50, "too few events");
    why.check(h["non_finite_steps"] == 0, "non-finite steps");
    why.check(h["max_body_speed_mps"].get<double>() < 30.0, "a body too fast");
    why.check(h["bodies_below_floor"] == 0, "a body in a crate or under the floor");
    why.check(h["max_penetration_m"].get<double>() < 0.06, "a contact too deep");
    why.check(rep["interaction"]["drags"].size() > 10u, "too few drags");
    why.check(rep["interaction"]["objects_thrown"].get<int>() > 5, "too few throws");
    return why.str().empty() ? std::string() : why.str() + ": " + h.dump();
  });
  EXPECT_TRUE(r.all());
}

TEST(Chaos, TheSameSeedGivesTheSameChaosAndAnotherSeedOther) {
  // Any seeds (determinism): the third and the fourth.
  const nlohmann::json a = run({"--scenario", "stand", "--seed", "3", "--chaos", "3"}, 8.0);
  const nlohmann::json b = run({"--scenario", "stand", "--seed", "3", "--chaos", "3"}, 8.0);
  const nlohmann::json c = run({"--scenario", "stand", "--seed", "4", "--chaos", "3"}, 8.0);
  EXPECT_EQ(a["interaction"].dump(), b["interaction"].dump());
  EXPECT_EQ(a["boxers"][0]["max_com_speed"], b["boxers"][0]["max_com_speed"]);
  EXPECT_NE(a["interaction"].dump(), c["interaction"].dump());
}

// The referee's reset after a get-up once set a boxer's feet 7-15 cm inside the crates at its mark (the pose was
// placed on the crates where it got up): match seed 37 under --chaos 0.5, boxer 0 up at 10.57 s, 113 body-steps with
// a centre in a crate over 60 s. The reset now lifts the pose clear of the crates under it. The get-up is brought
// about directly: boxer 0 shoved down at 2 s (1500 N x 0.25 s at the chest, away from blue) under --chaos 0.5, seeds
// 1-3, every seed required (health is not a rate); run until 1 s after the get-up (nobody is set anywhere after it).
TEST(Chaos, AGetUpUnderChaosLeavesNoBodyInACrate) {
  const seed_rate::Rate r = seed_rate::over_seeds("match under chaos 0.5, boxer 0 shoved down", 1, 3, [](int seed) {
    auto o = boxing::parse_cli({"--scenario", "match", "--seed", std::to_string(seed), "--chaos", "0.5", "--start-apart", "1.0"});
    if (!o.ok()) return o.error();
    auto made = boxing::make_world(*o);
    if (!made.ok()) return made.error();
    boxing::World& w = **made;
    while (w.data.time < 2.0) boxing::step_world(w);
    Eigen::Vector3d d = w.data.x[w.boxers[1].bodies.body[0]].p - w.data.x[w.boxers[0].bodies.body[0]].p;
    d.z() = 0.0;
    boxing::InputEvent push;
    push.kind = boxing::InputKind::Push;
    push.boxer = 0;
    push.bone = "chest";
    push.vec = -1500.0 * d.normalized();
    push.duration = 0.25;
    boxing::interaction_submit(w, push);
    const auto& g = w.match->getups;
    double until = 2.0 + 1.0 + w.match->tuning.count_seconds;
    while (w.data.time < until) {
      boxing::step_world(w);
      if (!g.empty() && g.front().up_at >= 0.0) until = std::min(until, g.front().up_at + 1.0);
    }
    const nlohmann::json rep = boxing::world_report(w);
    seed_rate::Why why;
    why.check(!g.empty() && g.front().up_at >= 0.0, "not down, or not up: " + rep["match"]["getups"].dump());
    why.check(rep["match"]["teleports"].get<int>() == 0, "a boxer set on a mark");
    why.check(rep["health"]["bodies_below_floor"] == 0, "a body in a crate: " + rep["health"].dump());
    why.check(rep["health"]["max_body_speed_mps"].get<double>() < 30.0, "a body too fast: " + rep["health"].dump());
    return why.str();
  });
  EXPECT_TRUE(r.all());
}
