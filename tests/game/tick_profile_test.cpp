// The tick's per-stage profile (World::TickProfile, the report's tick_profile_ms; docs/decisions/tick-stages.md):
// the stages are real times that account for the tick, and profiling changes nothing in the simulation.
#include <gtest/gtest.h>

#include <cstring>

#include "game/world.h"

namespace boxing {
namespace {

std::unique_ptr<World> make(const char* scenario, Scenario id, bool profile) {
  Options o;
  o.headless = true;
  o.scenario_id = id;
  o.scenario = scenario;
  o.seed = 2;
  auto w = make_world(o);
  EXPECT_TRUE(w) << w.error();
  if (!w) return nullptr;
  (*w)->profile_stages = profile;
  return std::move(*w);
}

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

// Two boxers standing for 1 s, one world profiled and one not: the same state bit for bit (the clocks are read,
// never fed back), and the report's boxers identical.
TEST(TickProfile, ProfilingChangesNothingBitForBit) {
  auto on = make("stand", Scenario::Stand, true), off = make("stand", Scenario::Stand, false);
  ASSERT_TRUE(on && off);
  for (int i = 0; i < 240; ++i) {
    step_world(*on);
    step_world(*off);
    ASSERT_TRUE(same_bits(on->data.q, off->data.q)) << "tick " << i;
    ASSERT_TRUE(same_bits(on->data.v, off->data.v)) << "tick " << i;
  }
  // (less each boxer's "qp": the solve's wall-clock latency, measured either way)
  auto boxers = [](const World& w) {
    nlohmann::json r = world_report(w)["boxers"];
    for (auto& b : r) b.erase("qp");
    return r.dump();
  };
  EXPECT_TRUE(boxers(*on) == boxers(*off)) << "the report's boxers differ with the stages profiled";
  // Off: no stage was timed, and the report keeps only the coarse split.
  EXPECT_EQ(off->profile.physics.total(), 0.0);
  EXPECT_EQ(off->profile.control.total(), 0.0);
  const nlohmann::json r = world_report(*off)["tick_profile_ms"];
  EXPECT_TRUE(r.contains("step1") && r.contains("control") && r.contains("step2") && r.contains("sense"));
  EXPECT_FALSE(r.contains("collision"));
}

// Profiled, every stage was entered and each side's stages lie inside the interval that contains them (physics in
// step1 + step2, the boxers' control in control). Nothing here depends on how fast the machine is or how loaded
// (ctest -j): no ratio of one timing to another, no time bound.
//  * Entered: a stage's field is only ever written by its lap, so a stage the pipeline stopped timing (a lap removed
//    or moved onto another field) stays exactly 0 however long the run; timed, it holds 480 ticks of real work
//    (at least a microsecond a tick) read by CLOCK_MONOTONIC (nanoseconds), which a slower machine only makes larger.
//  * Nested: the fine laps run inside the coarse stopwatch's interval on the same monotonic clock, so their sum cannot
//    exceed it; it does if a profiled physics or control call runs outside step_world's stopwatch, or a stage is
//    added into twice (a field summed from two laps, a profile not reset with the coarse times).
// (Not asserted: that the fine stages cover nearly all of the coarse time. That is a ratio of wall-clock times, which
// load on the other cores moves; docs/decisions/tick-stages.md measures it.)
TEST(TickProfile, EveryStageIsEnteredAndLiesInsideItsInterval) {
  auto w = make("stand", Scenario::Stand, true);
  ASSERT_TRUE(w);
  for (int i = 0; i < 480; ++i) step_world(*w);
  const World::TickProfile& p = w->profile;
  const struct {
    const char* name;
    double ms;
  } stages[] = {{"collision", p.physics.collision}, {"dynamics", p.physics.dynamics}, {"solver", p.physics.solver},
                {"integration", p.physics.integration}, {"graph", p.control.graph},   {"pose", p.control.pose},
                {"stepping", p.control.stepping},       {"servo", p.control.servo},   {"qp", p.control.qp}};
  for (const auto& s : stages) EXPECT_GT(s.ms, 0.0) << s.name << " was never timed";
  for (const double coarse : {p.step1_ms, p.control_ms, p.step2_ms, p.sense_ms}) EXPECT_GT(coarse, 0.0);
  EXPECT_LE(p.physics.total(), (p.step1_ms + p.step2_ms) * (1.0 + 1e-9));
  EXPECT_LE(p.control.total(), p.control_ms * (1.0 + 1e-9));

  // The report: the old keys kept, every stage's key, and the remainders (physics_other, control_other: the coarse
  // time less its stages) non-negative by the nesting above; the keys add up to the tick, which holds by construction
  // (the remainders are differences) and fails only if the report drops, renames or double-counts a key.
  const nlohmann::json r = world_report(*w)["tick_profile_ms"];
  double sum = 0.0;
  for (const char* k : {"collision", "dynamics", "solver", "integration", "physics_other", "graph", "pose", "stepping",
                        "servo", "qp", "control_other", "sense"}) {
    ASSERT_TRUE(r.contains(k)) << k;
    sum += r[k].get<double>();
  }
  EXPECT_GE(r["physics_other"].get<double>(), -1e-9);
  EXPECT_GE(r["control_other"].get<double>(), -1e-9);
  const double total = r["step1"].get<double>() + r["control"].get<double>() + r["step2"].get<double>() +
                       r["sense"].get<double>();
  EXPECT_NEAR(sum, total, 1e-9 * total);
  // The QP's solve (its latency histogram's sum) is timed inside the qp stage's lap: nested again.
  EXPECT_GT(r["qp_solve"].get<double>(), 0.0);
  EXPECT_LE(r["qp_solve"].get<double>(), r["qp"].get<double>());
}

}  // namespace
}  // namespace boxing
