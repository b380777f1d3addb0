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

// Profiled, the stages are non-negative, each side's stages lie inside the interval that contains them (physics in
// step1 + step2, the boxers' control in control), and together they account for nearly the whole tick (what is left:
// input events, clear_applied, the scenario's forces; a missed stage would leave far more).
TEST(TickProfile, StagesAreNonNegativeAndAddUpToTheTick) {
  auto w = make("stand", Scenario::Stand, true);
  ASSERT_TRUE(w);
  for (int i = 0; i < 480; ++i) step_world(*w);
  const World::TickProfile& p = w->profile;
  for (const double t : {p.physics.collision, p.physics.dynamics, p.physics.solver, p.physics.integration, p.control.graph,
                         p.control.pose, p.control.stepping, p.control.servo, p.control.qp})
    EXPECT_GE(t, 0.0);
  EXPECT_GT(p.physics.collision, 0.0);
  EXPECT_GT(p.physics.solver, 0.0);
  EXPECT_GT(p.control.qp, 0.0);
  EXPECT_LE(p.physics.total(), (p.step1_ms + p.step2_ms) * (1.0 + 1e-9));
  EXPECT_LE(p.control.total(), p.control_ms * (1.0 + 1e-9));
  const double coarse = p.step1_ms + p.control_ms + p.step2_ms;
  const double fine = p.physics.total() + p.control.total();
  EXPECT_GT(fine, 0.95 * coarse) << "fine stages " << fine << " ms of " << coarse << " ms";

  // The report: the old keys kept, the stages and the remainders add up to the tick.
  const nlohmann::json r = world_report(*w)["tick_profile_ms"];
  double sum = 0.0;
  for (const char* k : {"collision", "dynamics", "solver", "integration", "physics_other", "graph", "pose", "stepping",
                        "servo", "qp", "control_other", "sense"}) {
    ASSERT_TRUE(r.contains(k)) << k;
    EXPECT_GE(r[k].get<double>(), -1e-9) << k;
    sum += r[k].get<double>();
  }
  const double total = r["step1"].get<double>() + r["control"].get<double>() + r["step2"].get<double>() +
                       r["sense"].get<double>();
  EXPECT_NEAR(sum, total, 1e-9 * total);
  EXPECT_GT(r["qp_solve"].get<double>(), 0.0);
  EXPECT_LE(r["qp_solve"].get<double>(), r["qp"].get<double>());
}

}  // namespace
}  // namespace boxing
