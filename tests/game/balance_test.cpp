// The boxers' balance end to end (no rendering), the claims of the README's "boxer and inertial servo" and
// "balance QP" sections: world and person space recover from a 150 N x 0.1 s chest push from every direction with
// no root help, parent space without the meathook falls unpushed (the paper's baseline), and the balance QP (the
// default) keeps the boxer up through the punches that floor the PD balance layer. The behaviour is asserted over fixed
// seed ranges (seed_rate.h): seeds 1-N, each test's N and rate stated, the measurements in docs/decisions/test-bounds.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/physics/overlap.h"
#include "game/boxer_stepping.h"
#include "game/cli.h"
#include "game/world.h"
#include "game/seed_rate.h"

namespace {

// Runs a scenario for `seconds` of simulated time, boxer 0's tuning edited first by `tune` when given; returns every
// boxer's metrics (boxer 0 first).
std::vector<boxing::BoxerMetrics> run_all(const std::vector<std::string>& args, double seconds,
                                          const std::function<void(boxing::BoxerTuning&)>& tune = {}) {
  auto o = boxing::parse_cli(args);
  EXPECT_TRUE(o.ok());
  auto w = boxing::make_world(*o);
  EXPECT_TRUE(w.ok()) << w.error();
  if (!w.ok()) return {boxing::BoxerMetrics{}};
  boxing::World& world = **w;
  if (tune) tune(world.boxers[0].settings.tuning);
  const int steps = int(seconds / boxing::kPhysicsDt);
  for (int i = 0; i < steps; ++i) boxing::step_world(world);
  std::vector<boxing::BoxerMetrics> m;
  for (const boxing::Boxer& b : world.boxers) m.push_back(b.metrics);
  return m;
}

// run_all's boxer 0.
boxing::BoxerMetrics run(const std::vector<std::string>& args, double seconds,
                         const std::function<void(boxing::BoxerTuning&)>& tune = {}) {
  return run_all(args, seconds, tune)[0];
}

// "fell at 4.2 s (pelvis below half its standing height)", or "" when it stood.
std::string fell_why(const boxing::BoxerMetrics& m) {
  if (!m.fell) return "";
  char s[64];
  std::snprintf(s, sizeof s, "fell at %.1f s (", m.fell_at);
  return s + m.fell_reason + ")";
}

// The boxers of `m` that fell, and why ("" when none did).
std::string falls(const std::vector<boxing::BoxerMetrics>& m) {
  seed_rate::Why why;
  for (size_t k = 0; k < m.size(); ++k) why.check(!m[k].fell, "boxer " + std::to_string(k) + " " + fell_why(m[k]));
  return why.str();
}

// The push lab's world for a push of `force` N x 0.2 s at 2 s toward `dir` degrees, steps on, on `seed`.
std::unique_ptr<boxing::World> push_world(const char* seed, const char* dir, const char* force) {
  auto o = boxing::parse_cli({"--scenario", "push", "--seed", seed, "--push-dir", dir, "--push-force", force,
                              "--push-duration", "0.2", "--push-at", "2", "--stepping", "on"});
  EXPECT_TRUE(o.ok());
  auto w = boxing::make_world(*o);
  EXPECT_TRUE(w.ok()) << w.error();
  return w.ok() ? std::move(*w) : nullptr;
}

// push_world's push, its boxer's balance-step tuning changed by `tune`, run for `seconds`: boxer 0's metrics, and in
// *on_edge how many of its feet then stand on a poor foothold (on_poor_foothold).
boxing::BoxerMetrics push_feet_on_edge(const char* seed, const char* dir, const char* force, double seconds,
                                       const std::function<void(eng::control::BalanceStepTuning&)>& tune, int* on_edge) {
  const std::unique_ptr<boxing::World> w = push_world(seed, dir, force);
  if (!w) return boxing::BoxerMetrics{};
  boxing::Boxer& b = w->boxers[0];
  tune(b.settings.tuning.balance_step);
  for (int i = 0; i < int(seconds / boxing::kPhysicsDt); ++i) boxing::step_world(*w);
  *on_edge = int(boxing::on_poor_foothold(w->data, w->arena, b, 0)) + int(boxing::on_poor_foothold(w->data, w->arena, b, 1));
  return b.metrics;
}

// Steps `world` for `seconds` of simulated time, calling `each` after every step while boxer 0 is on its feet.
void step_while_up(boxing::World& world, double seconds, const std::function<void()>& each) {
  for (int i = 0; i < int(seconds / boxing::kPhysicsDt); ++i) {
    boxing::step_world(world);
    if (!world.boxers[0].metrics.fell) each();
  }
}

// A situation that arises on some seeds and not others (a crossed stance, a foot on an edge): over seeds lo..hi,
// `check(seed, &shown)` sets shown when the seed brings the situation about (the contrast run: the mechanism off, or
// the situation looked for) and returns why the mechanism failed there (empty: it passed; a seed that does not show
// the situation passes unless a check that holds on every seed failed). The rate's `shown` lists the seeds that
// showed it: a test requires enough of them, or it shows nothing.
struct ShownRate {
  seed_rate::Rate r;
  std::vector<int> shown;
  std::string shown_list() const {
    std::string s;
    for (int seed : shown) s += " " + std::to_string(seed);
    return s.empty() ? " none" : s;
  }
  // At least `need` seeds showed the situation, and the mechanism failed on at most `fails` seeds.
  ::testing::AssertionResult at_least(int need, int fails) const {
    if (int(shown.size()) < need)
      return ::testing::AssertionFailure() << r.what << ": the situation arose on seeds" << shown_list() << " of "
                                           << r.lo << "-" << r.hi << ", at least " << need << " required"
                                           << r.failures();
    return r.at_least(r.seeds() - fails);
  }
};

ShownRate over_seeds_shown(const std::string& what, int lo, int hi, const std::function<std::string(int, bool*)>& check) {
  ShownRate s;
  s.r = seed_rate::over_seeds(what, lo, hi, [&](int seed) {
    bool shown = false;
    std::string why = check(seed, &shown);
    if (shown) s.shown.push_back(seed);
    std::printf("[seed_rate] %s, seed %d: the situation %s\n", what.c_str(), seed, shown ? "arose" : "did not arise");
    return why;
  });
  std::printf("[seed_rate] %s: the situation arose on seeds%s\n", what.c_str(), s.shown_list().c_str());
  return s;
}

// push_world's push, by seed number.
std::unique_ptr<boxing::World> push_world(int seed, const char* dir, const char* force) {
  return push_world(std::to_string(seed).c_str(), dir, force);
}

class PushFromEveryDirection : public ::testing::TestWithParam<std::string> {};

// Seeds 1-3, every seed required (a small push, 15 kg m/s: the claim is that it is survived, whatever the stance; seed
// 3 is the stance whose 315 deg push used to floor person space, its rear crate 12 cm lower than the lead one). A seed
// passes when all 8 directions stand 5 s (the push at 2 s). measured: 3 of 3 in both spaces.
TEST_P(PushFromEveryDirection, A150NewtonChestPushIsSurvivedWithNoRootHelp) {
  const seed_rate::Rate r =
      seed_rate::over_seeds(GetParam() + " space, 150 N x 0.1 s from 8 directions", 1, 3, [](int seed) {
        seed_rate::Why why;
        for (int dir = 0; dir < 360; dir += 45) {
          const auto m = run({"--scenario", "push", "--seed", std::to_string(seed), "--servo", GetParam(), "--push-dir",
                              std::to_string(dir), "--push-force", "150", "--push-duration", "0.1", "--push-at", "2"},
                             5.0);
          why.check(!m.fell, "toward " + std::to_string(dir) + " deg " + fell_why(m));
        }
        return why.str();
      });
  EXPECT_TRUE(r.all());
}

INSTANTIATE_TEST_SUITE_P(Servo, PushFromEveryDirection, ::testing::Values("world", "person"));

// The push scenario's trace (Kudoh's plots): standing in guard the centre of pressure lies under the com on average
// (the ground's force balances the weight through the com), and Kudoh's sinusoidal push from the front moves the
// centre of pressure back and forth at the push's 1 Hz. Checks the trace's com, its centre of pressure (summed from
// the solver's contact forces) and the --push-shape sine force.
TEST(Push, TheTraceHasTheCentreOfPressureUnderTheComAndFollowsKudohsSine) {
  // Seeds 1-3, every seed required: the trace's physics, not the stance, makes it pass.
  const seed_rate::Rate r = seed_rate::over_seeds("sine push trace, 5 s", 1, 3, [](int seed) -> std::string {
    auto o = boxing::parse_cli({"--scenario", "push", "--seed", std::to_string(seed), "--stepping", "off", "--push-dir",
                                "180", "--push-force", "100", "--push-shape", "sine", "--push-duration", "5",
                                "--push-at", "2"});
    if (!o.ok()) return o.error();
    auto w = boxing::make_world(*o);
    if (!w.ok()) return w.error();
    boxing::World& world = **w;
    for (int i = 0; i < int(5.0 / boxing::kPhysicsDt); ++i) boxing::step_world(world);
    const auto& tr = world.push_trace;
    if (tr.size() <= 590u) return "a trace of " + std::to_string(tr.size()) + " rows, not 120 Hz";
    // Standing before the push, over two periods of the guard's 0.6 s bounce (the centre of pressure sways +-4 cm
    // about the com as the balance drives it; on average it is under it).
    double dx = 0, dy = 0;
    int n = 0;
    for (const auto& row : tr)
      if (row[0] >= 0.8 && row[0] < 2.0) dx += row[3] - row[1], dy += row[4] - row[2], ++n;
    // Under the sine (a push backward in the first half of each second, forward in the second) the centre of
    // pressure moves back and forth: its mean over the seconds' first halves differs from the second halves' by > 1 cm.
    double half[2] = {0, 0};
    int cnt[2] = {0, 0};
    for (const auto& row : tr) {
      if (row[0] < 2.0) continue;
      const int h = std::fmod(row[0] - 2.0, 1.0) < 0.5 ? 0 : 1;
      half[h] += row[3], ++cnt[h];
    }
    if (n <= 100 || cnt[0] <= 100 || cnt[1] <= 100) return "too few trace rows";
    seed_rate::Why why;
    why.check(std::abs(dx / n) < 0.015 && std::abs(dy / n) < 0.015,
              "centre of pressure off the com on average by " + std::to_string(dx / n) + ", " + std::to_string(dy / n) + " m");
    const double swing = std::abs(half[0] / cnt[0] - half[1] / cnt[1]);
    why.check(swing > 0.01, "the centre of pressure moved " + std::to_string(swing) + " m with the sine");
    why.check(!world.boxers[0].metrics.fell, fell_why(world.boxers[0].metrics));
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

// Kudoh's 500 N x 0.1 s from behind, in place, with Kudoh's priorities (the fight's balance) and the knees 8 cm
// deeper: the boxer stays up, the arms it swings to hold the trunk come back to the guard (without the return they
// stayed 1.6-2.0 rad off on 7 of 8 seeds), and the plain lab balance falls (docs/decisions/balance-steps.md).
TEST(Push, KudohsPushFromBehindIsSurvivedInPlaceAndTheArmsComeBack) {
  // Seeds 1-3, every seed required (in place, a push of the stance's own physics). measured: 3 of 3 (arms 0.01-0.06 rad off at the end, 0.5-0.6 s
  // off the guard; the plain balance down at 3.2-3.3 s on each).
  const seed_rate::Rate r = seed_rate::over_seeds("Kudoh's 500 N from behind, 8 s", 1, 3, [](int seed) {
    const std::vector<std::string> push = {"--scenario", "push", "--seed", std::to_string(seed), "--stepping", "off",
                                           "--push-dir", "0", "--push-force", "500", "--push-duration", "0.1",
                                           "--push-at", "2"};
    auto kudoh = push;
    for (const char* a : {"--priorities", "kudoh", "--stance-drop", "0.08"}) kudoh.push_back(a);
    const auto m = run(kudoh, 8.0);
    seed_rate::Why why;
    why.check(!m.fell, fell_why(m));
    why.check(m.arm_error_end < 0.3, "upper arms " + std::to_string(m.arm_error_end) + " rad off their pose at the end");
    why.check(m.arm_off_guard_s < 3.0, "arms off the guard " + std::to_string(m.arm_off_guard_s) + " s");  // the swing
    why.check(run(push, 8.0).fell, "the lab's own balance (no priorities) stood");  // ... goes down
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

TEST(Push, SixTimesThatImpulseFloorsTheBoxer) {
  // The same scenario is not a pass by construction: 900 N x 0.1 s (90 kg m/s) from behind knocks the boxer down in
  // place. (With the push lab's balance steps it staggers on for seconds: the BalanceSteps tests.) Seeds 1-3, every
  // seed required. And a fallen boxer goes limp and stays bounded: the QP's torques on a lying body once made the
  // limbs flail and the simulation diverge (com speed 1e129 m/s on walk seed 3); a fall is ~3.4 m/s, bound 6 m/s.
  // measured: 3 of 3, down at 2.8 s, the com
  // at most 2.3-3.0 m/s.
  const seed_rate::Rate r = seed_rate::over_seeds("900 N x 0.1 s from behind, in place, 8 s", 1, 3, [](int seed) {
    const auto m = run({"--scenario", "push", "--seed", std::to_string(seed), "--servo", "world", "--push-dir", "0",
                        "--push-force", "900", "--push-duration", "0.1", "--push-at", "2", "--stepping", "off"},
                       8.0);
    seed_rate::Why why;
    why.check(m.fell, "stood");
    why.check(!m.fell || m.fell_at > 2.0, "fell before the push, " + fell_why(m));
    why.check(m.max_com_speed < 6.0, "com at " + std::to_string(m.max_com_speed) + " m/s");
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

TEST(ParentSpace, WithoutTheMeathookTheBoxerFallsUnpushed) {
  // Seeds 1-3, every seed required. measured: 3 of 3 (parent space down at 1.2-1.3 s).
  const seed_rate::Rate r = seed_rate::over_seeds("parent space, standing 4 s", 1, 3, [](int seed) {
    seed_rate::Why why;
    const auto m = run({"--scenario", "stand", "--seed", std::to_string(seed), "--servo", "parent"}, 4.0);
    why.check(m.fell, "parent-space PD alone held the body up (the paper's baseline falls)");
    const auto h = run({"--scenario", "stand", "--seed", std::to_string(seed), "--servo", "parent-meathook"}, 4.0);
    why.check(!h.fell, "with the meathook's artificial support " + fell_why(h));
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

TEST(Drill, AnUnknownClipNameIsAClearError) {
  auto o = boxing::parse_cli({"--scenario", "stand", "--clip", "haymaker"});
  ASSERT_TRUE(o.ok());
  auto w = boxing::make_world(*o);
  ASSERT_FALSE(w.ok());
  EXPECT_NE(w.error().find("'haymaker' is not a clip"), std::string::npos) << w.error();
}

// A drill of one clip (stand, the clip played every 3 s: three plays in 10 s), both boxers of the stand scenario, seeds
// 1-4 (a seed passes when both stand). The balance QP keeps the centre of pressure in the feet through the punches'
// lunges (the jab's 5 cm with the arm thrown forward floors the PD balance layer: the next test), and block_high moves
// the arms and trunk, not the root. measured: every clip here 10 of seeds 1-10 (20 of 20 boxers), combo_jab_cross
// too (it held 12 of 16 boxers on seeds 1-8 in the deeper stance before, README "Stance and steps on the crates");
// bound 3 of 4: one seed of four may move with a last-bit difference between machines (docs/decisions/test-bounds.md).
class DrillOfOneClip : public ::testing::TestWithParam<const char*> {};

TEST_P(DrillOfOneClip, TheBalanceQpKeepsBothBoxersUpOnSeeds1To4) {
  const std::string clip = GetParam();
  const seed_rate::Rate r = seed_rate::over_seeds(clip + " drill, QP, 10 s", 1, 4, [&](int seed) {
    return falls(run_all({"--scenario", "stand", "--seed", std::to_string(seed), "--clip", clip}, 10.0));
  });
  EXPECT_TRUE(r.at_least(3));
}

INSTANTIATE_TEST_SUITE_P(Clip, DrillOfOneClip,
                         ::testing::Values("jab", "cross", "lead_uppercut", "duck", "combo_jab_cross", "block_high"));

TEST(Drill, ThePdBalanceLayerFallsInTheJabDrill) {
  // The baseline the drills above are measured against (otherwise they show nothing): the PD balance layer (--balance
  // pd) loses a boxer of the jab drill on a seed (a seed passes when a boxer falls, 4.7-8.9 s). measured: 6 of seeds
  // 1-10 (11 of 20 boxers), 3 of seeds 1-4; bound 2 of 4: one seed of four may move.
  const seed_rate::Rate r = seed_rate::over_seeds("jab drill, PD layer, 10 s: a boxer falls", 1, 4, [](int seed) {
    const auto m = run_all({"--scenario", "stand", "--seed", std::to_string(seed), "--clip", "jab", "--balance", "pd"},
                           10.0);
    return falls(m).empty() ? std::string("both boxers stood") : std::string();
  });
  EXPECT_TRUE(r.at_least(2));
}

TEST(Drill, TheClipsQuickStepsLiftOffOnlyWhenTheBodyIsCapturableOnceTheFootLands) {
  // The step_forward drill floored 13 of 16 boxers on seeds 1-8 when the clip lifted the foot on its own schedule
  // (README, "The walk"); gated on the capture point over the stance foot, every one of its steps was held down (the
  // capture point 12-26 cm from the stance foot at lift-off). Gated on the capture point at the touch-down lying in
  // the new support (lift_off_gate.h, quick steps), none is held down and the boxer stands through the three
  // plays, the feet carried forward (a shuffle: the soles drag on their tops, 22% of the clip's 15 cm on seeds 1-8).
  // Each play lifts the lead foot, then the rear: 6 steps, of which 2 are not taken since the carried steps land where
  // planned (stop 57): their landing, relative to the other foot, is within 2 cm of where the foot already stands.
  // Seeds 1-4, 10 s (a seed passes when the boxer stands, no step is skipped, and the steps taken go forward).
  // measured (seeds 1-10): all stand, none skipped, 1-4 steps taken and 1-4 not taken (their landing where the foot
  // stood; 6 plays' steps in all on 7 seeds, 3-5 on the others, a step still held at 10 s); bound 3 of 4: one seed
  // of four may move with a last-bit difference between machines.
  const seed_rate::Rate r = seed_rate::over_seeds("step_forward drill, 10 s", 1, 4, [](int seed) {
    const auto m = run({"--scenario", "stand", "--seed", std::to_string(seed), "--clip", "step_forward"}, 10.0);
    seed_rate::Why why;
    why.check(!m.fell, fell_why(m));
    why.check(m.steps_skipped == 0, std::to_string(m.steps_skipped) + " steps skipped");
    why.check(m.steps_taken + m.steps_in_place <= 6, std::to_string(m.steps_taken + m.steps_in_place) + " steps of 6");
    why.check(m.steps_taken >= 1 && m.step_travel_count == m.steps_taken, "no step taken, or travel not counted");
    why.check(m.step_travel_count == 0 || m.step_travel_sum / m.step_travel_count > 0.1,
              "steps left behind: " + std::to_string(m.step_travel_sum / std::max(1, m.step_travel_count)) + " m");
    return why.str();
  });
  EXPECT_TRUE(r.at_least(3));
}

TEST(GraphWalk, TheWalkStandsOnTheRootAssistWithinItsLimit) {
  // Walk seed 7 fell at 3.5 s before the lift-off gating and the root assist (README); now the walk stands, the assist
  // (the paper's torque-limited root spring, on by default for the walk) never above its 400 N m. The footwork clips'
  // steps lift off as quick steps (a 3 cm heel lift of a punch, too short to swing, is held down) and cost the assist
  // nothing: during a quick step's swing the plan's com falls toward the landing foot as the inverted pendulum does
  // (qp_balance.cpp); held over the stance foot instead the plan bought the com's acceleration from the assist (rms
  // 70 N m on seed 7 against 29). Seeds 1-3, 20 s. measured (seeds 1-6, the CLI's report): all stand, 4-11 steps
  // taken, 1-4 held down, more taken than held on each; here, seeds 1-3: the assist's peak 186-270 N m, its rms 14.5-29.6
  // (the bound 45 N m lies between the quick steps' 29 and the held plan's 70 on seed 7), 8-9 steps taken, 1-4 held
  // down. bound 2 of 3: one seed of three may move.
  const seed_rate::Rate r = seed_rate::over_seeds("graph walk 20 s", 1, 3, [](int seed) {
    const auto m = run({"--scenario", "graph-walk", "--seed", std::to_string(seed)}, 20.0);
    const double rms = m.time_upright > 0.0 ? std::sqrt(m.root_torque_sq_dt / m.time_upright) : 0.0;
    std::printf("  seed %d: assist peak %.0f N m, rms %.1f N m; steps %d taken, %d held down\n", seed,
                m.root_torque_peak, rms, m.steps_taken, m.steps_skipped);
    seed_rate::Why why;
    why.check(!m.fell, fell_why(m));
    why.check(m.root_torque_peak > 1.0, "the assist unused");  // it is used ...
    why.check(m.root_torque_peak <= 400.0 + 1e-6, "the assist over its limit");  // ... within its limit
    why.check(m.steps_taken >= 4 && m.steps_taken > m.steps_skipped,
              std::to_string(m.steps_taken) + " steps taken, " + std::to_string(m.steps_skipped) + " held down");
    why.check(rms < 45.0, "the assist's rms " + std::to_string(rms) + " N m");
    return why.str();
  });
  EXPECT_TRUE(r.at_least(2));
}

TEST(Drill, AClipsOwnLungeIsGivenByTheSolesNotBoughtFromTheRootAssist) {
  // The rear uppercut drill with the root spring on (as the match's boxers fight): asked for the clip's whole com
  // acceleration, its centre of pressure past the soles, the plan bought the rest from the assist (rms 34 N m);
  // asked only for what the soles give (BalanceQpTuning::com_acc_in_support), 8 N m, and the boxer stands.
  // Seeds 1-3, every seed required (measured: 3 of 3, the assist's rms 31.5-33.5 N m asked for the whole, 7.0-8.4
  // asked for the soles').
  const seed_rate::Rate r = seed_rate::over_seeds("rear_uppercut drill, root spring on, 12 s", 1, 3, [](int seed) {
    const std::vector<std::string> args = {"--scenario", "stand", "--seed", std::to_string(seed), "--clip",
                                           "rear_uppercut", "--root-spring", "on"};
    const auto rms = [](const boxing::BoxerMetrics& m) { return std::sqrt(m.root_torque_sq_dt / m.time_upright); };
    const auto whole = run(args, 12.0, [](boxing::BoxerTuning& t) { t.qp.com_acc_in_support = false; });
    const auto soles = run(args, 12.0);
    std::printf("  seed %d: the assist's rms %.1f N m (whole com acceleration), %.1f N m (the soles')\n", seed,
                rms(whole), rms(soles));
    seed_rate::Why why;
    why.check(!whole.fell && whole.time_upright > 0.0, "whole: " + fell_why(whole));
    why.check(!soles.fell, "soles: " + fell_why(soles));
    // the assist did carry the lunge before (otherwise this test shows nothing)
    why.check(rms(whole) > 20.0, "whole: the assist's rms " + std::to_string(rms(whole)) + " N m");
    why.check(rms(soles) < 0.5 * rms(whole), "soles: the assist's rms " + std::to_string(rms(soles)) + " N m");
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

TEST(GraphWalk, CarriedFootworkMovesTheFeetWhereTheShuffleDragsThem) {
  // --footwork carry (the default; step_planner.h): the clips' steps swing on their own path to where the clip puts
  // the foot relative to the stance foot; the shuffle (--footwork shuffle) drags the pressed soles. A seed passes
  // when, over kWalkSeconds of the walk, the shuffle's soles cover under 30% of the clips' travel, the carried steps
  // over 40%, and the carried walk stands on an assist rms under 45 N m (walk seed 10 before: 26%, 70%, 30 N m), both
  // walks with at least 5 steps. measured (seeds 1-6, 15 s): 3 of 6 (seeds 1, 4, 5: under 5 steps in 15 s; on 2, 3, 6
  // shuffled 0.28-0.29, carried 0.70-0.93, rms 15-33 N m); require 2 of 6: one seed may move.
  constexpr double kWalkSeconds = 15.0;
  const seed_rate::Rate r = seed_rate::over_seeds("graph walk, carried vs shuffled feet", 1, 6, [](int seed) {
    const std::string sd = std::to_string(seed);
    const auto shuffle = run({"--scenario", "graph-walk", "--seed", sd, "--footwork", "shuffle"}, kWalkSeconds);
    const auto carried = run({"--scenario", "graph-walk", "--seed", sd}, kWalkSeconds);
    seed_rate::Why why;
    why.check(!carried.fell, "carried: " + fell_why(carried));
    if (shuffle.step_travel_count < 5 || carried.step_travel_count < 5 || carried.time_upright <= 0.0)
      return why.check(false, "too few steps: " + std::to_string(shuffle.step_travel_count) + " shuffled, " +
                                  std::to_string(carried.step_travel_count) + " carried").str();
    const double shuffled = shuffle.step_travel_sum / shuffle.step_travel_count;
    const double carry = carried.step_travel_sum / carried.step_travel_count;
    const double rms = std::sqrt(carried.root_torque_sq_dt / carried.time_upright);
    std::printf("  seed %d: travel shuffled %.2f, carried %.2f; carried assist rms %.1f N m\n", seed, shuffled, carry, rms);
    why.check(shuffled < 0.3, "shuffled soles covered " + std::to_string(shuffled) + " of the travel");
    why.check(carry > 0.4, "carried steps covered " + std::to_string(carry) + " of the travel");
    why.check(rms < 45.0, "carried: assist rms " + std::to_string(rms) + " N m");
    return why.str();
  });
  EXPECT_TRUE(r.at_least(2));
}

TEST(GraphWalk, ACarriedStepWhoseLandingIsWhereTheFootStandsIsNotTaken) {
  // The carried landing is relative to the stance foot; when the feet already stand as the clip ends, it is where the
  // foot is, and the foot was lifted and put back within 2 cm (a boxer marking time). With StepTuning::carry_in_place
  // off, such steps land in place (the situation: a seed shows it when one does); with it (the default) those steps
  // are not taken (steps_in_place) and none lands in place, the boxer stands, and the steps that go somewhere are
  // still taken (2 or more). (Walk seed 21, 30 s, was the one named.) measured (seeds 1-6, 15 s, the clips of issue
  // 65's defences): steps landed in place with it off on seeds 2-4; with it none on any seed, 1-2 steps not taken
  // there, 2-5 steps travelled (the graph's 157 transitions reach the step clips less often than the 213 before: 3
  // or more then). require: the situation on at least 1 seed, at most 2 seeds failing (none measured).
  constexpr double kWalkSeconds = 15.0;
  const ShownRate s = over_seeds_shown("graph walk, steps marking time", 1, 6, [](int seed, bool* shown) {
    const std::string sd = std::to_string(seed);
    const auto marking_time = run({"--scenario", "graph-walk", "--seed", sd}, kWalkSeconds,
                                   [](boxing::BoxerTuning& t) { t.step.carry_in_place = 0.0; });
    const auto m = run({"--scenario", "graph-walk", "--seed", sd}, kWalkSeconds);
    std::printf("  seed %d: off: %d landed in place, %d not taken; on: %d landed in place, %d not taken, %d travelled\n",
                seed, marking_time.steps_landed_in_place, marking_time.steps_in_place, m.steps_landed_in_place,
                m.steps_in_place, m.step_travel_count);
    *shown = marking_time.steps_landed_in_place > 0;
    seed_rate::Why why;
    why.check(marking_time.steps_in_place == 0, "off: " + std::to_string(marking_time.steps_in_place) + " not taken");
    why.check(!m.fell, fell_why(m));
    why.check(m.steps_landed_in_place == 0, std::to_string(m.steps_landed_in_place) + " landed in place");
    why.check(m.step_travel_count >= 2, "only " + std::to_string(m.step_travel_count) + " steps travelled");
    if (*shown) why.check(m.steps_in_place > 0, "no step left untaken");
    return why.str();
  });
  EXPECT_TRUE(s.at_least(1, 2));
}

TEST(Drill, ACarriedStepHeldForItsWeightShiftIsStillTheClipsWholeStep) {
  // The gate holds a carried step down until the capture point allows it (the weight shift) while the clip plays on.
  // Judged by what was left of the clip's step when it opened, a step_forward rear step kept a few cm of its 16 and a
  // few hundredths of a second to its touch-down: not carried, too late to swing, skipped (StepTuning::carry_whole
  // off: the situation, a seed shows it when a step is skipped). Lifted as the clip's whole step (the default), it is
  // taken: no step skipped on any seed, and the boxer up. The step_forward drill, 10 s. (Seed 30 was the one named: 4
  // taken and 1 skipped off, 5 and none on.) measured (seeds 1-8): skips with it off on seeds 3, 5, 7 (2, 3, 2); none
  // with it on, on 8 of 8. require: skips off on at least 2 seeds, none on on 7 of 8 (one seed may move). (On seeds
  // 3, 5, 7 the steps taken are the same both ways, 3, 1, 3: seed 30's "one more taken" does not hold over the range,
  // so it is not asserted.)
  const ShownRate s = over_seeds_shown("step_forward drill, held steps", 1, 8, [](int seed, bool* shown) {
    const std::vector<std::string> drill = {"--scenario", "stand", "--seed", std::to_string(seed), "--clip", "step_forward"};
    const auto left = run(drill, 10.0, [](boxing::BoxerTuning& t) { t.step.carry_whole = false; });
    const auto m = run(drill, 10.0);
    std::printf("  seed %d: off: %d taken, %d skipped, %d travelled; on: %d taken, %d skipped, %d travelled\n", seed,
                left.steps_taken, left.steps_skipped, left.step_travel_count, m.steps_taken, m.steps_skipped,
                m.step_travel_count);
    *shown = left.steps_skipped >= 1;
    seed_rate::Why why;
    why.check(m.steps_skipped == 0, std::to_string(m.steps_skipped) + " skipped");
    why.check(!m.fell, fell_why(m));
    return why.str();
  });
  EXPECT_TRUE(s.at_least(2, 1));
}

}  // namespace

namespace {

TEST(BalanceSteps, APushCarryingTheCapturePointOutIsMetWithAStepWhereInPlaceFalls) {
  // 400 N x 0.2 s from behind (80 kg m/s, 1.07 m/s of com velocity), seeds 1-3: in place the boxer falls; with
  // balance steps (the push lab's default) it steps and stays up. (Across the lab's grid the steps win only some
  // pushes, not even every smaller one from behind: the README's push-domain charts; this is one they win.)
  for (const char* seed : {"1", "2", "3"}) {
    auto with = [&](const char* stepping) {
      return run({"--scenario", "push", "--seed", seed, "--push-dir", "0", "--push-force", "400", "--push-duration",
                  "0.2", "--push-at", "2", "--stepping", stepping},
                 7.0);
    };
    const auto off = with("off");
    EXPECT_TRUE(off.fell) << "seed " << seed << ": in place this push should floor the boxer";
    EXPECT_EQ(off.balance_steps, 0);
    const auto on = with("on");
    EXPECT_GE(on.balance_steps, 1) << "seed " << seed;
    EXPECT_FALSE(on.fell) << "seed " << seed << ": fell at " << on.fell_at << " s (" << on.fell_reason << ")";
  }
}

TEST(BalanceSteps, APushTheRootAssistHoldsInPlaceTakesNoStep) {
  // 413 N x 0.2 s from behind: with no root help the capture point leaves the feet and the boxer steps; with the root
  // spring's assist (400 N m: its moment moves the pivot up to 0.54 m past the feet, half of that counted,
  // BalanceStepTuning::assist_reach_share) the same push is held in place, the assist at 200-400 N m, and no step is
  // taken (the match's boxers, who fight with the assist, step only for what it cannot hold). Seeds 1-3, every seed
  // required (measured: 3 of 3; 1-4 steps bare, none assisted).
  const seed_rate::Rate r = seed_rate::over_seeds("413 N from behind, root assist off / on, 6 s", 1, 3, [](int seed) {
    auto with = [seed](const char* root_spring) {
      return run({"--scenario", "push", "--seed", std::to_string(seed), "--push-dir", "0", "--push-force", "413",
                  "--push-duration", "0.2", "--push-at", "2", "--stepping", "on", "--root-spring", root_spring},
                 6.0);
    };
    const auto bare = with("off"), assisted = with("on");
    seed_rate::Why why;
    why.check(bare.balance_steps >= 1, "bare: no step");
    why.check(!bare.fell, "bare: " + fell_why(bare));
    why.check(assisted.balance_steps == 0, "assisted: " + std::to_string(assisted.balance_steps) + " steps");
    why.check(!assisted.fell, "assisted: " + fell_why(assisted));
    why.check(assisted.root_torque_peak > 200.0, "assisted: the assist peaked at " +
                                                     std::to_string(assisted.root_torque_peak) + " N m");
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

// Yin & van de Panne's bars for a 75 kg body, 0.2 s at the chest (com velocities: forward 1.1 m/s = 413 N, to the left
// 1.05 m/s = 394 N, backward 0.8 m/s = 300 N, to the right as to the left), and Yin's sideways momentum (79 kg m/s)
// as 197 N for 0.4 s to the right, stepped out of with balance steps (the push lab's default), seeds 1-8, 6 s (the
// falls come 1.1-2.8 s after the push). A seed passes when the boxer steps (at least one balance step), stands, and
// every step comes down on a top (no late landing: the com comes down for a swing leg below its reach,
// BalanceStepTuning::reach_share; found on right 394 N seeds 11, 36, 46 and left 394 N seed 44).
// The history behind them: to the right (toward the rear foot) the lead foot crosses over, the rear follows, toward
// the platform's edge 1 m away (seeds 1-8 stood 3, 5, 8, 7 of 8 through the rounds of docs/decisions/balance-steps.md);
// to the left the rear foot crosses behind and the com can creep out of a 0.6-0.9 m diagonal stance, stepped out of
// by the foot farther from the capture point (stepping_foot); the longer push's landing is re-planned while the push
// observer still reads the push (seeds 1-48: 127 of 144 such pushes stood across forward, left and right, 109
// before; seventh round). measured and bounds: each bar's line (seeds 1-8; 1-16 in docs/decisions/test-bounds.md);
// a bound one seed under the measured rate: one seed of eight may move with a last-bit difference between machines.
struct YinPush {
  const char* name;
  const char* dir;
  const char* force;
  const char* duration;
  int min_steps;  // balance steps a seed must take (the backward bar is held in place: none on seeds 1-8)
  int need;       // of seeds 1-8
};

class YinsBars : public ::testing::TestWithParam<YinPush> {};

TEST_P(YinsBars, AreSteppedOutOfOnSeeds1To8) {
  const YinPush& p = GetParam();
  const seed_rate::Rate r = seed_rate::over_seeds(std::string(p.name) + " push, 6 s", 1, 8, [&](int seed) {
    const auto m = run({"--scenario", "push", "--seed", std::to_string(seed), "--push-dir", p.dir, "--push-force",
                        p.force, "--push-duration", p.duration, "--push-at", "2", "--stepping", "on"},
                       6.0);
    seed_rate::Why why;
    why.check(!m.fell, fell_why(m));
    why.check(m.balance_steps >= p.min_steps, std::to_string(m.balance_steps) + " balance steps");
    // Forward, the step swaps the feet into a stance the boxer can fight from: a one-step recovery stays in it
    // rather than take a long return step back (seeds 1, 3, 4, 6, 8; two steps and a return on 2, 5, 7).
    if (std::string(p.dir) == "0" && m.balance_steps == 1) why.check(m.return_steps == 0, "a return step after one");
    why.check(m.late_landings == 0, std::to_string(m.late_landings) + " late landings");
    return why.str();
  });
  EXPECT_TRUE(r.at_least(p.need));
}

INSTANTIATE_TEST_SUITE_P(
    Push, YinsBars,
    ::testing::Values(YinPush{"forward 413 N", "0", "413", "0.2", 1, 7},        // measured 8/8
                      YinPush{"left 394 N", "90", "394", "0.2", 1, 7},          // measured 8/8 (15 of 1-16)
                      YinPush{"backward 300 N", "180", "300", "0.2", 0, 7},      // measured 8/8
                      YinPush{"right 394 N", "270", "394", "0.2", 1, 7},        // measured 8/8 (15 of 1-16)
                      YinPush{"right 197 N x 0.4 s", "270", "197", "0.4", 1, 5}),  // measured 6/8 (13 of 1-16)
    [](const ::testing::TestParamInfo<YinPush>& i) {
      std::string n;
      for (const char c : std::string(i.param.name)) n += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return n;
    });

TEST(BalanceSteps, ThePushObserverReadsTheChestPushAsItsForceOverTheMass) {
  // observe_push (after each physics step): the com's horizontal acceleration less what the ground's contact forces
  // give it. A 394 N push to the right for 0.2 s on the 75 kg boxer accelerates it at 5.25 m/s^2, which the ground's
  // forces do not explain; standing before it and after it, the ground explains all of it.
  // Seeds 1-3, every seed required (the observer's arithmetic, not the stance, makes it pass). measured (seeds 1-10):
  // before it at most 0.03 m/s^2; during it 4.97-5.05 m/s^2 on average of 5.25, from 4.1 to 5.75.
  const seed_rate::Rate r = seed_rate::over_seeds("the push observer, 394 N to the right, 4 s", 1, 3, [](int seed) {
    auto o = boxing::parse_cli({"--scenario", "push", "--seed", std::to_string(seed), "--push-dir", "270",
                                "--push-force", "394", "--push-duration", "0.2", "--push-at", "2", "--stepping", "on"});
    if (!o.ok()) return o.error();
    auto w = boxing::make_world(*o);
    if (!w.ok()) return w.error();
    boxing::World& world = **w;
    const boxing::Boxer& b = world.boxers[0];
    const double expected = 394.0 / b.control_body.total_mass;
    double before = 0.0, during_min = 1e9, during_max = 0.0, after_sum = 0.0;
    Eigen::Vector2d during_sum = Eigen::Vector2d::Zero();
    int n = 0, after_n = 0, after_over = 0;
    while (world.data.time < 4.0) {
      boxing::step_world(world);
      const Eigen::Vector2d a = b.ctl.balance_steps.push_acc;
      const double t = world.data.time;
      if (t > 1.0 && t < 2.0) before = std::max(before, a.norm());
      if (t > 2.05 && t < 2.2) {  // past the filter's rise (10 ms)
        during_min = std::min(during_min, a.norm()), during_max = std::max(during_max, a.norm());
        during_sum += a, ++n;
      }
      if (t > 2.5) after_sum += a.norm(), ++after_n, after_over += a.norm() > b.settings.tuning.balance_step.push_acc;
    }
    const auto f = [](double x) { return std::to_string(x); };
    std::printf("  seed %d: before %.3f; during x %.3f, y %.3f (%.3f expected), %.3f-%.3f; after %.3f on average, %d of %d "
                "steps over the threshold\n", seed, before, during_sum.x() / n, during_sum.y() / n, -expected, during_min,
                during_max, after_sum / after_n, after_over, after_n);
    seed_rate::Why why;
    why.check(before < 0.5, "before the push " + f(before) + " m/s^2");
    why.check(std::abs(during_sum.x() / n) < 0.3, "during it, forward " + f(during_sum.x() / n) + " m/s^2");
    // heading 0: to the right is -y
    why.check(std::abs(during_sum.y() / n + expected) < 0.1 * expected, "during it " + f(during_sum.y() / n) + " m/s^2");
    why.check(during_min > 0.7 * expected && during_max < 1.3 * expected,
              "during it from " + f(during_min) + " to " + f(during_max) + " m/s^2");
    // After it, through the recovery's steps: under the re-planning's threshold (push_acc, 2 m/s^2) on average by half
    // at least, and over it in under 5% of the steps (a landing's impact reads for a few milliseconds: its contact
    // forces change within the step). measured (seeds 1-10): the average 0.06-0.53 m/s^2 (p50 0.15; 0.5 was the bound
    // until seed 2's 0.53 showed it fitted to seed 1's 0.09), over the threshold 0-15 of 361 steps.
    why.check(after_sum / after_n < 0.5 * b.settings.tuning.balance_step.push_acc, "after it " + f(after_sum / after_n) + " m/s^2 on average");
    why.check(after_over < after_n / 20, "after it over the threshold " + std::to_string(after_over) + " steps");
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

// The planted feet's slide (BoxerMetrics::foot_slide): a boxer standing in guard does not slide its feet (the metric
// does not add up the contacts' jitter), and in a drill, where no step moves a foot, the slide summed over the
// foot's plantings is at least how far the foot ended up from where it started (checked against the bodies'
// positions). The rear hook's pivot slides the rear foot (docs/decisions/foot-slide.md): not a bar, a reading.
TEST(FootSlide, AGuardStandsStillAndADrillsSlideIsAtLeastTheFootsDisplacement) {
  // Seeds 1-3, every seed required (the metric's bookkeeping, not the stance, makes it pass).
  const seed_rate::Rate r = seed_rate::over_seeds("foot slide: guard 10 s, rear_hook drill 10 s", 1, 3, [](int seed) {
    seed_rate::Why why;
    const auto still = run({"--scenario", "stand", "--seed", std::to_string(seed)}, 10.0);
    why.check(!still.fell, "guard: " + fell_why(still));
    why.check(still.foot_slide[0] < 0.005 && still.foot_slide[1] < 0.005,
              "guard: feet slid " + std::to_string(still.foot_slide[0]) + ", " + std::to_string(still.foot_slide[1]) + " m");
    auto o = boxing::parse_cli({"--scenario", "stand", "--seed", std::to_string(seed), "--clip", "rear_hook"});
    if (!o.ok()) return o.error();
    auto w = boxing::make_world(*o);
    if (!w.ok()) return w.error();
    boxing::World& world = **w;
    const boxing::Boxer& b = world.boxers[0];
    const auto sole = [&](int k) {  // the sole centre, as the metric reads it
      const eng::physics::Pose& x = world.data.x[b.bodies.body[b.bones.foot[k]]];
      return Eigen::Vector2d((x.p + x.R * b.settings.tuning.foot.centre).head<2>());
    };
    boxing::step_world(world);
    const Eigen::Vector2d start[2] = {sole(0), sole(1)};
    for (int i = 1; i < int(10.0 / boxing::kPhysicsDt); ++i) boxing::step_world(world);
    why.check(!b.metrics.fell, "drill: " + fell_why(b.metrics));
    why.check(b.metrics.balance_steps + b.metrics.steps_taken == 0, "drill: a step was taken");
    for (int k = 0; k < 2; ++k) {
      const double moved = (sole(k) - start[k]).norm();
      why.check(b.metrics.foot_slide[k] >= moved - 1e-3, "drill: foot " + std::to_string(k) + " moved " +
                                                             std::to_string(moved) + " m, slid " +
                                                             std::to_string(b.metrics.foot_slide[k]));
    }
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

// The rear foot under a cross drill: each cross turns the rear leg over the planted foot until the ankle's twist stops
// it at its limit; the step's stop, unplanned, yanked the foot past its friction and it slid a few cm a punch (the graph
// walks' rear feet 0.2-1.0 m in 10 minutes, off their crates). With the feet's limits in the plan (BalanceQpTuning::
// limit_weight) it stays put. 20 s of crosses; the same drill with the limits left out of the plan.
TEST(FootSlide, TheCrossDrillsRearFootStaysPlantedWithTheAnkleLimitsInThePlan) {
  // Seeds 1-3. measured: planned, the rear foot slid 1.2, 1.2, 2.1 cm (bound 3 cm: every seed); unplanned 16.5 cm (and
  // the boxer fell), 16.2, 1.9 cm: more than 5 times the planned slide on 2 of 3 (seed 3's rear foot holds either way);
  // bound 1 of 3, one under the measured.
  int slid = 0;
  std::string stayed;
  const seed_rate::Rate r = seed_rate::over_seeds("cross drill 20 s, the rear foot's slide", 1, 3, [&](int seed) {
    const auto rear_slide = [seed](double limit_weight) {
      auto o = boxing::parse_cli({"--scenario", "stand", "--seed", std::to_string(seed), "--clip", "cross"});
      EXPECT_TRUE(o.ok()) << o.error();
      auto w = boxing::make_world(*o);
      EXPECT_TRUE(w.ok()) << w.error();
      boxing::World& world = **w;
      for (boxing::Boxer& b : world.boxers) b.settings.tuning.qp.limit_weight = limit_weight;
      for (int i = 0; i < int(20.0 / boxing::kPhysicsDt); ++i) boxing::step_world(world);
      const boxing::Boxer& b = world.boxers[0];
      std::printf("  seed %d, limit weight %g: feet slid %.3f / %.3f m%s\n", seed, limit_weight, b.metrics.foot_slide[0],
                  b.metrics.foot_slide[1], b.metrics.fell ? ", fell" : "");
      return std::make_pair(b.metrics.foot_slide[1], b.metrics.fell);
    };
    const auto planned = rear_slide(boxing::BalanceQpTuning{}.limit_weight), unplanned = rear_slide(0.0);
    // Unplanned (the contrast: otherwise this test shows nothing).
    if (unplanned.first > 5.0 * planned.first) ++slid;
    else stayed += " " + std::to_string(seed);
    seed_rate::Why why;
    why.check(!planned.second, "planned: fell");
    why.check(planned.first < 0.03, "planned: the rear foot slid " + std::to_string(planned.first) + " m");
    return why.str();
  });
  EXPECT_TRUE(r.all());
  EXPECT_GE(slid, 1) << "unplanned, the rear foot slid no more than planned on seeds" << stayed;
}

TEST(BalanceSteps, AStanceTheRecoveryLeftCrossedReturnsToOneTheBoxerCanFightFrom) {
  // 394 N x 0.2 s to the right, 8 s: on some seeds the lead (left) foot crosses over to land right of the rear one
  // and the recovery settles with the feet crossed (the situation: the stance, stance_can_fight, crossed at some
  // tick). Yin's third phase, the return step, first shifts the weight over one foot, then swings the other back to
  // its guard place relative to it. The foot that moved last, as the return used to choose, stood under the com: its
  // weight shift went the long way and was given up after 2.5 s, and the boxer stood cross-legged to the end (seed 16:
  // 5.4 s of the legs through each other). The foot farther from the com returns now: where the feet crossed, no
  // landing is late, the boxer stands and ends in a stance it can fight from, its legs through each other under 4 s.
  // measured (seeds 1-16, 8 s): the stance crossed at some tick on all 16; 12 of 16 pass (1, 5, 8: no return step by
  // 8 s, cannot fight; 15: fell at 3.4 s, a late landing); legs through each other at most 1.67 s (seed 13). require
  // 11 of 16 (one seed may move) and the crossing on at least 15.
  const ShownRate s = over_seeds_shown("right push 394 N, a crossed stance", 1, 16, [](int seed, bool* shown) {
    const std::unique_ptr<boxing::World> w = push_world(seed, "270", "394");
    if (!w) return std::string("no world");
    boxing::World& world = *w;
    bool crossed = false;
    for (int i = 0; i < int(8.0 / boxing::kPhysicsDt); ++i) {
      boxing::step_world(world);
      crossed = crossed || !boxing::stance_can_fight(world.data, world.boxers[0]);
    }
    const boxing::BoxerMetrics& m = world.boxers[0].metrics;
    const bool can_fight = boxing::stance_can_fight(world.data, world.boxers[0]);
    std::printf("  seed %d: crossed %d, %d balance / %d return steps, late %d, legs through %.2f s, can fight at 8 s %d%s\n",
                seed, crossed, m.balance_steps, m.return_steps, m.late_landings, m.legs_overlap_s, can_fight,
                m.fell ? ", fell" : "");
    *shown = crossed;
    seed_rate::Why why;
    if (!crossed) return why.str();
    why.check(!m.fell, fell_why(m));
    why.check(m.late_landings == 0, std::to_string(m.late_landings) + " late landings");
    why.check(can_fight, "ended in a stance it cannot fight from");
    why.check(m.legs_overlap_s < 4.0, "legs through each other " + std::to_string(m.legs_overlap_s) + " s");
    return why.str();
  });
  EXPECT_TRUE(s.at_least(15, 5));
}

TEST(BalanceSteps, AReturnStepLandsWhereItWasPlanned) {
  // 394 N x 0.2 s to the right, 8 s: a recovery that ends in a return step. Its swing's path acceleration fed forward
  // (BalanceQpTuning::swing_acc_feed_forward), the sole comes down within a centimetre of where the return planned it;
  // tracked on position and velocity alone, the PD trailed the ease's stop and the foot ran on 3-4 cm past its
  // landing (seeds 6, 11 and 13, the ones named before). Seeds 1-6, the seeds whose recovery takes a return step both
  // ways. measured: seeds 2, 3, 4, 6 take one; fed forward 0.5, 7.2, 1.8, 0.4 cm off, PD alone 3.3, 2.9, 37.1, 2.0 cm:
  // within 1 cm fed forward on 2 of 4, closer than PD alone on 3 of 4 (seed 3's fed-forward return misses by 7 cm: the
  // claim holds on some recoveries, not all). bound: one of each under the measured (a seed may move), and at least 3
  // seeds with a return step, or the test shows nothing.
  struct Miss { int seed; double fed, pd; bool fell; };
  std::vector<Miss> misses;
  for (int seed = 1; seed <= 6; ++seed) {
    const auto right_push = [&](double share) {
      return run({"--scenario", "push", "--seed", std::to_string(seed), "--push-dir", "270", "--push-force", "394",
                  "--push-duration", "0.2", "--push-at", "2", "--stepping", "on"},
                 8.0, [&](boxing::BoxerTuning& t) {
                   EXPECT_EQ(t.qp.swing_acc_feed_forward, 1.0);  // as built
                   t.qp.swing_acc_feed_forward = share;
                 });
    };
    const boxing::BoxerMetrics fed = right_push(1.0), pd = right_push(0.0);
    if (fed.landings[1] < 1 || pd.landings[1] < 1) {
      std::printf("[seed_rate] seed %d: no return step (fed forward %d, PD alone %d)\n", seed, fed.landings[1],
                  pd.landings[1]);
      continue;
    }
    misses.push_back({seed, fed.landing_miss_sum[1] / fed.landings[1], pd.landing_miss_sum[1] / pd.landings[1], fed.fell});
    std::printf("[seed_rate] seed %d: a return step's landing from its plan: %.1f cm (fed forward), %.1f cm (PD alone)\n",
                seed, 100.0 * misses.back().fed, 100.0 * misses.back().pd);
  }
  int within = 0, closer = 0;
  std::string failed;
  for (const Miss& m : misses) {
    within += m.fed < 0.01, closer += m.fed < m.pd;
    if (m.fed >= 0.01 || m.fed >= m.pd || m.fell)
      failed += "\n  seed " + std::to_string(m.seed) + ": " + std::to_string(m.fed) + " m fed forward, " +
                std::to_string(m.pd) + " m PD alone" + (m.fell ? ", fell" : "");
    EXPECT_FALSE(m.fell) << "seed " << m.seed << ": fell, fed forward";
  }
  ASSERT_GE(misses.size(), 3u) << "too few return steps to show anything";
  EXPECT_GE(within, 1) << within << " of " << misses.size() << " within 1 cm:" << failed;
  EXPECT_GE(closer, 2) << closer << " of " << misses.size() << " closer fed forward:" << failed;
}

TEST(BalanceSteps, AFootTheRecoveryLeftOnAnEdgeIsRePlacedOntoAGoodFoothold) {
  // Yin's forward push (413 N x 0.2 s), 10 s: on some seeds the recovery ends in a stance the boxer can fight from (no
  // return step) with one sole over a crate's edge (by the clips' foothold margins, on_poor_foothold): the situation,
  // shown with the re-placement off (BalanceStepTuning::replace_edge_foot) when the boxer stands with no return step
  // and a foot on an edge at the end. With the re-placement that foot steps onto the nearest good foothold (the weight
  // shift, then a return step): both feet well placed at the end, one re-placement, the boxer up. (Seeds 5 and 7 of the
  // forward push and 1 of the left one were the ones named.) measured (seeds 1-8): a foot left on an edge on seeds 5
  // and 7, re-placed on both; 8 of 8 pass. require: the situation on at least 1 seed, at most 1 failing.
  const ShownRate s = over_seeds_shown("forward push 413 N, a foot left on an edge", 1, 8, [](int seed, bool* shown) {
    const auto push = [&](bool replace, int* on_edge) {
      return push_feet_on_edge(std::to_string(seed).c_str(), "0", "413", 10.0, [replace](auto& t) {
        EXPECT_TRUE(t.replace_edge_foot);  // as built
        t.replace_edge_foot = replace;
      }, on_edge);
    };
    int edge_with = -1, edge_without = -1;
    const boxing::BoxerMetrics with = push(true, &edge_with), without = push(false, &edge_without);
    std::printf("  seed %d: feet on an edge at 10 s: %d (re-placed, %d re-placements%s), %d (not, %d return steps%s)\n",
                seed, edge_with, with.replacements, with.fell ? ", fell" : "", edge_without, without.return_steps,
                without.fell ? ", fell" : "");
    *shown = !without.fell && without.return_steps == 0 && edge_without >= 1;
    seed_rate::Why why;
    if (!*shown) return why.str();
    why.check(!with.fell, fell_why(with));
    why.check(with.replacements >= 1, "no re-placement");
    why.check(edge_with == 0, std::to_string(edge_with) + " feet on an edge at the end");
    return why.str();
  });
  EXPECT_TRUE(s.at_least(1, 1));
}

TEST(BalanceSteps, AReturnThatLandsOnAnEdgeIsFollowedByARePlacement) {
  // Yin's left and right pushes (394 N x 0.2 s), 14 s: on some seeds the recovery ends in a return step that comes
  // down with a sole over a crate's edge (on_poor_foothold): the situation, shown with the follow-up off
  // (BalanceStepTuning::follow_ups 0) when the boxer stands after a return step with a foot on an edge at the end.
  // With the follow-up the feet are looked at again once the body settles after it, and that foot is re-placed: both
  // feet well placed at the end, the boxer up; on every push, no more feet on an edge than without the follow-up.
  // (Seed 4's left push and seed 6's right one were the ones named.) measured (seeds 1-7, both pushes): the situation on
  // 3 left, 4 left, 4 right, 6 right, 7 left; fixed on 4 left, 6 right, 7 left; 3 left and 4 right end with 1 and 2
  // feet on an edge either way (the follow-up re-placed and the foot landed on an edge again): seeds 3, 4 fail, 5 of 7
  // pass. require: the situation on at least 3 seeds, at most 3 failing (2 measured, one may move).
  const ShownRate s = over_seeds_shown("left and right pushes 394 N, a return onto an edge", 1, 7,
                                       [](int seed, bool* shown) {
    seed_rate::Why why;
    for (const char* dir : {"90", "270"}) {
      const auto push = [&](int follow_ups, int* on_edge) {
        return push_feet_on_edge(std::to_string(seed).c_str(), dir, "394", 14.0, [follow_ups](auto& t) {
          EXPECT_GE(t.follow_ups, 1);  // as built
          t.follow_ups = follow_ups;
        }, on_edge);
      };
      int edge_with = -1, edge_without = -1;
      const boxing::BoxerMetrics with = push(boxing::BoxerTuning{}.balance_step.follow_ups, &edge_with),
                                 without = push(0, &edge_without);
      std::printf("  seed %d, push %s deg: feet on an edge at 14 s: %d (followed up, %d re-placements%s), %d (not, %d "
                  "return steps, %d re-placements%s)\n",
                  seed, dir, edge_with, with.replacements, with.fell ? ", fell" : "", edge_without, without.return_steps,
                  without.replacements, without.fell ? ", fell" : "");
      const std::string at = std::string("toward ") + dir + " deg: ";
      why.check(with.fell || edge_with <= edge_without, at + "more feet on an edge with the follow-up");
      if (without.fell || without.return_steps < 1 || edge_without < 1) continue;
      *shown = true;
      why.check(!with.fell, at + fell_why(with));
      why.check(with.replacements >= 1, at + "no re-placement");
      why.check(edge_with == 0, at + std::to_string(edge_with) + " feet on an edge at the end");
    }
    return why.str();
  });
  EXPECT_TRUE(s.at_least(3, 3));
}

TEST(BalanceSteps, AStandingBoxerTakesNoneAndItsLegsNeverTouch) {
  // Standing in guard for 10 s: the capture point never leaves the soles, no step is taken for nothing; the guard's
  // legs stay apart (BoxerMetrics::legs_overlap_*), its thighs never touch. Seeds 1-3, every seed required (measured:
  // 3 of 3; seed 4 was the one named).
  const seed_rate::Rate r = seed_rate::over_seeds("standing 10 s, steps on", 1, 3, [](int seed) {
    const auto m = run({"--scenario", "stand", "--seed", std::to_string(seed), "--stepping", "on"}, 10.0);
    seed_rate::Why why;
    why.check(!m.fell, fell_why(m));
    why.check(m.balance_steps == 0, std::to_string(m.balance_steps) + " balance steps");
    why.check(m.legs_overlap_max == 0.0 && m.legs_overlap_s == 0.0, "legs through each other");
    why.check(m.thighs_touch_s == 0.0, "thighs touched " + std::to_string(m.thighs_touch_s) + " s");
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

TEST(BalanceSteps, ACrossOversThighsHoldEachOtherOffWhereTheyPassedThroughEachOther) {
  // 394 N x 0.2 s to the right, 8 s: on some seeds the left foot crosses over and the feet end crossed. With the
  // thighs not colliding (as every leg geom was until the fourteenth round, docs/decisions/balance-steps.md), they
  // stood in an X over 8 cm deep (the situation; seed 3, the one named: 13 cm). Colliding (add_boxer), they touch and
  // stay within the contact's own penetration (1.5 cm) and the boxer stands. Not colliding they never touch (every
  // seed). measured (seeds 1-13): crossed over 8 cm passing on seeds 3, 11, 13 (13.0, 9.6, 11.2 cm), colliding at most
  // 0.4 cm on every seed; 13 of 13 pass. require: the situation on at least 2 seeds, at most 1 failing.
  const auto deepest_thighs = [](int seed, bool collide, boxing::BoxerMetrics* out) {
    const std::unique_ptr<boxing::World> w = push_world(seed, "270", "394");
    if (!w) return 0.0;
    boxing::World& world = *w;
    const boxing::Boxer& b = world.boxers[0];
    std::vector<int> thigh[2];
    for (int k = 0; k < 2; ++k) {
      const int bone = b.bones.leg[k].thigh;
      for (int g = b.bodies.first_geom[bone]; g < b.bodies.first_geom[bone] + b.bodies.geom_count[bone]; ++g) {
        thigh[k].push_back(g);
        EXPECT_TRUE(world.model.geoms[g].self_collide);  // as built
        world.model.geoms[g].self_collide = collide;
      }
    }
    double deepest = 0.0;
    step_while_up(world, 8.0, [&] {
      deepest = std::max(deepest, eng::physics::deepest_overlap(world.model, world.data, thigh[0], thigh[1]));
    });
    *out = b.metrics;
    return deepest;
  };
  const ShownRate s = over_seeds_shown("right push 394 N, thighs crossing", 1, 13, [&](int seed, bool* shown) {
    boxing::BoxerMetrics colliding, passing;
    const double held = deepest_thighs(seed, true, &colliding), passed = deepest_thighs(seed, false, &passing);
    std::printf("  seed %d: thighs through each other at most: colliding %.3f m (touching %.2f s%s), passing %.3f m\n",
                seed, held, colliding.thighs_touch_s, colliding.fell ? ", fell" : "", passed);
    seed_rate::Why why;
    why.check(passing.thighs_touch_s == 0.0, "passing, the thighs touched");
    *shown = passed > 0.08;
    if (!*shown) return why.str();
    why.check(held < 0.015, "colliding, through each other " + std::to_string(held) + " m");
    why.check(colliding.thighs_touch_s > 0.0, "colliding, the thighs never touched");
    why.check(!colliding.fell, fell_why(colliding));
    return why.str();
  });
  EXPECT_TRUE(s.at_least(2, 1));
}

TEST(BalanceSteps, TheLegClearanceKeepsACrossedStancesLegsOutOfEachOther) {
  // 394 N x 0.2 s to the left, 14 s: on some seeds the recovery crosses the feet, and without the balance QP's leg
  // clearance (BalanceQpTuning::leg_clearance_weight 0) the legs stand through each other by over 1 cm, or the
  // thighs press together, for over a second (the situation; seed 7, the one named: 2.3 s, the thighs 6.4 s). With it
  // the plan holds them apart: under 0.1 s of overlap, the thighs touching under half as long, and the boxer stands.
  // measured (seeds 1-8): the situation on seeds 2 (thighs 2.68 s, 0.01 with it) and 7 (legs 1.50 s, thighs 4.32 s;
  // 0.00 and 0.23 with it); 8 of 8 pass. require: the situation on at least 1 seed, at most 1 failing.
  const ShownRate s = over_seeds_shown("left push 394 N, the leg clearance", 1, 8, [](int seed, bool* shown) {
    const auto left_push = [&](double weight) {
      return run({"--scenario", "push", "--seed", std::to_string(seed), "--push-dir", "90", "--push-force", "394",
                  "--push-duration", "0.2", "--push-at", "2", "--stepping", "on"},
                 14.0, [&](boxing::BoxerTuning& t) {
                   EXPECT_GT(t.qp.leg_clearance_weight, 0.0);  // as built
                   t.qp.leg_clearance_weight = weight;
                 });
    };
    const boxing::BoxerMetrics off = left_push(0.0), on = left_push(boxing::BalanceQpTuning{}.leg_clearance_weight);
    std::printf("  seed %d: legs through each other over 1 cm: %.2f s (clearance), %.2f s (none); thighs touching %.2f s, "
                "%.2f s%s\n", seed, on.legs_overlap_s, off.legs_overlap_s, on.thighs_touch_s, off.thighs_touch_s,
                on.fell ? "; fell with the clearance" : "");
    *shown = off.legs_overlap_s > 1.0 || off.thighs_touch_s > 1.0;
    seed_rate::Why why;
    if (!*shown) return why.str();
    why.check(on.legs_overlap_s < 0.1, "legs through each other " + std::to_string(on.legs_overlap_s) + " s");
    why.check(on.thighs_touch_s < 0.5 * off.thighs_touch_s, "thighs touching " + std::to_string(on.thighs_touch_s) + " s");
    why.check(!on.fell, fell_why(on));
    return why.str();
  });
  EXPECT_TRUE(s.at_least(1, 1));
}

TEST(BalanceSteps, AReturnThatWouldStepOffThePlatformIsTakenByTheOtherFoot) {
  // 394 N x 0.2 s to the right, 14 s: on some seeds a recovery leaves a foot near the platform's edge, and its return
  // (where the stance has it relative to the other foot) lands on the floor, 0.36 m below its crate; the boxer then
  // stood in a long lunge across the edge (seed 3, the one named, fell at 9.8 s). The situation: with
  // BalanceStepTuning::return_onto_platform off, a sole stands within 5 cm of the floor over 1 s. With it the other
  // foot returns instead, onto its crate: no foot on the floor, the boxer up. Counted while boxer 0 is up. (The balance
  // QP's leg clearance, which takes seed 3's recovery down another path, is off here, as it was when this was found.)
  // measured (seeds 1-16): a foot on the floor over 1 s with the rule off on seeds 3 (1.89 s, fell), 7 and 14 (8.8 and
  // 18.3 s of foot-time, the same with the rule on: the recovery left the platform, no return involved); the rule
  // brings seed 3's to 0, on no other seed does it change anything. Over seeds 1-8 here: never more floor time with
  // the rule; the situation on 3 and 7, fixed on 3. require: on every seed no more floor time with the rule, and at
  // least one seed where it takes a foot's second or more on the floor to none (measured 1: this claim still rests on
  // one recovery of the range, docs/decisions/test-bounds.md).
  const auto on_floor_s = [](int seed, bool onto_platform, boxing::BoxerMetrics* out) {
    const std::unique_ptr<boxing::World> w = push_world(seed, "270", "394");
    if (!w) return 0.0;
    boxing::World& world = *w;
    boxing::Boxer& b = world.boxers[0];
    EXPECT_TRUE(b.settings.tuning.balance_step.return_onto_platform);  // as built
    b.settings.tuning.balance_step.return_onto_platform = onto_platform;
    b.settings.tuning.qp.leg_clearance_weight = 0.0;
    double floor_s = 0.0;
    step_while_up(world, 14.0, [&] {
      for (int k = 0; k < 2; ++k) {
        const eng::physics::Pose& x = world.data.x[b.bodies.body[b.bones.foot[k]]];
        if ((x.p + x.R * b.settings.tuning.foot.sole_offset()).z() < boxing::kFloorTop) floor_s += boxing::kPhysicsDt;
      }
    });
    *out = b.metrics;
    return floor_s;
  };
  const ShownRate s = over_seeds_shown("right push 394 N, a return onto the platform keeps the feet off the floor", 1, 8, [&](int seed, bool* shown) {
    boxing::BoxerMetrics onto, off;
    const double onto_s = on_floor_s(seed, true, &onto), off_s = on_floor_s(seed, false, &off);
    std::printf("  seed %d: a foot on the floor: %.2f s (onto the platform%s), %.2f s (where the stance says%s)\n", seed,
                onto_s, onto.fell ? ", fell" : "", off_s, off.fell ? ", fell" : "");
    *shown = off_s > 1.0 && onto_s == 0.0 && !onto.fell;
    seed_rate::Why why;
    why.check(onto_s <= off_s, "more floor time with the return onto the platform");
    return why.str();
  });
  EXPECT_TRUE(s.at_least(1, 0));
}

}  // namespace
