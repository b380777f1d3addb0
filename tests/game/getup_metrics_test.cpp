// The report's `getups` (game/getup_metrics.h), measured against the match's own bookkeeping of the same get-up and
// against what the scene does: a boxer put down in an idle match (both boxers the idle player's, as in
// match/match_rules_test.cpp) and one floored in `stand`, where no stand-up (and so no root assist) acts.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "game/interaction/interaction.h"
#include "game/match/match.h"
#include "game/person_strength.h"
#include "game/world.h"

namespace boxing {
namespace {

constexpr int kTicksPerSecond = 240;
constexpr double kTick = 1.0 / kTicksPerSecond;

std::unique_ptr<World> world_of(Scenario id, const char* name) {
  Options o;
  o.headless = true;
  o.scenario_id = id;
  o.scenario = name;
  o.seed = 1;
  auto w = make_world(o);
  EXPECT_TRUE(w) << w.error();
  return w ? std::move(*w) : nullptr;
}

void submit_push(World& w, int k, const Eigen::Vector3d& force, double duration) {
  InputEvent push;
  push.kind = InputKind::Push;
  push.boxer = k;
  push.bone = "chest";
  push.vec = force;
  push.duration = duration;
  interaction_submit(w, push);
}

// Red put down in an idle match (no consciousness, 1500 N on the chest away from blue: match_rules_test's put_down)
// and left to get up. The record opens and closes on the ticks the match's own GetUp does, its lift force and root
// torque integrate to what the match summed over the stand-up (the same quantities, kept twice: they agree to
// round-off), its phases run down -> the get-up clip for how it lies -> up in time order, and the body parts that bore
// weight include more than the feet (it lay on the crates).
TEST(GetUpMetrics, AMatchGetUpIsRecordedAsTheMatchCountsIt) {
  auto w = world_of(Scenario::Match, "match");
  ASSERT_TRUE(w);
  World& world = *w;
  for (int k = 0; k < 2; ++k) {
    InputEvent e;
    e.kind = InputKind::Set;
    e.boxer = k;
    e.control = "player";
    interaction_submit(world, e);
  }
  for (int i = 0; i < kTicksPerSecond; ++i) step_world(world);
  InputEvent out;
  out.kind = InputKind::Set;
  out.boxer = 0;
  out.consciousness = 0.0;
  interaction_submit(world, out);
  Eigen::Vector3d away = world.data.x[world.boxers[0].bodies.body[0]].p - world.data.x[world.boxers[1].bodies.body[0]].p;
  away.z() = 0.0;
  submit_push(world, 0, 1500.0 * away.normalized(), 0.2);
  const Match& mt = *world.match;
  for (int i = 0; i < 20 * kTicksPerSecond && (mt.getups.empty() || mt.getups[0].up_at < 0.0); ++i) step_world(world);
  ASSERT_EQ(mt.getups.size(), 1u);
  const GetUp& g = mt.getups[0];
  ASSERT_GE(g.up_at, 0.0) << "red not up in 20 s";
  ASSERT_EQ(world.getups.records.size(), 1u);
  const GetUpRecord& r = world.getups.records[0];
  EXPECT_EQ(r.boxer, 0);
  EXPECT_NEAR(r.down_at, g.down_at, kTick + 1e-9);
  EXPECT_NEAR(r.up_at, g.up_at, kTick + 1e-9);
  EXPECT_EQ(r.lying, g.lying);
  EXPECT_NEAR(r.lift_force_sq_dt, g.assist_force_sq_dt, 1e-9 * (1.0 + g.assist_force_sq_dt));
  EXPECT_GT(r.lift_force_peak, 0.0);  // today's stand-up is carried (issue 63)
  EXPECT_GE(r.root_torque_sq_dt, g.assist_sq_dt * (1.0 - 1e-9));
  ASSERT_GE(r.phases.size(), 3u);
  EXPECT_EQ(r.phases.front().first, "down");
  EXPECT_EQ(r.phases.back().first, "up");
  EXPECT_NE(std::find_if(r.phases.begin(), r.phases.end(),
                         [&](const auto& p) { return p.first == "getup_" + g.lying; }),
            r.phases.end());
  for (size_t i = 1; i < r.phases.size(); ++i) EXPECT_GE(r.phases[i].second, r.phases[i - 1].second);
  const auto& names = world.boxer_desc.skeleton.name;
  double off_feet = 0.0;
  for (size_t bone = 0; bone < names.size(); ++bone) {
    EXPECT_LE(r.support_s[bone], r.time + 1e-9) << names[bone];
    if (names[bone] != "foot_l" && names[bone] != "foot_r") off_feet += r.support_s[bone];
  }
  EXPECT_GT(off_feet, 0.5);
  const nlohmann::json report = getups_report(world);
  ASSERT_EQ(report.size(), 1u);
  EXPECT_NEAR(report[0]["lift_force_rms_n"].get<double>(), std::sqrt(r.lift_force_sq_dt / r.time), 1e-9);
  // Each joint's peak against a person's strength (person_strength.h): the fraction is the one over the other.
  ASSERT_EQ(report[0]["joint_torque_peak_fraction"].size(), std::size(kPersonStrength));
  for (size_t bone = 1; bone < names.size(); ++bone) {
    if (person_strength(names[bone]) <= 0.0) continue;  // welded (the gloves)
    const double limit = report[0]["joint_torque_limit_nm"][names[bone]].get<double>();
    EXPECT_EQ(limit, person_strength(names[bone]));
    EXPECT_NEAR(report[0]["joint_torque_peak_fraction"][names[bone]].get<double>(), r.torque_peak[bone] / limit, 1e-12);
  }
  EXPECT_GT(r.torque_peak[world.boxer_desc.skeleton.find("thigh_r")], 0.0);
}

// Floored in `stand` by a push (2500 N for 0.3 s), the boxer lies: nothing lifts it, so the record's lift force is 0
// to the bit and it stays open (not up), its one phase "down".
TEST(GetUpMetrics, AFallWithNoStandUpMeasuresNoLiftForce) {
  auto w = world_of(Scenario::Stand, "stand");
  ASSERT_TRUE(w);
  World& world = *w;
  for (int i = 0; i < kTicksPerSecond; ++i) step_world(world);
  submit_push(world, 0, Eigen::Vector3d(2500.0, 0.0, 0.0), 0.3);
  for (int i = 0; i < 6 * kTicksPerSecond; ++i) step_world(world);
  ASSERT_FALSE(world.getups.records.empty()) << "the push did not floor the boxer";
  const GetUpRecord& r = world.getups.records[0];
  EXPECT_LT(r.up_at, 0.0);
  EXPECT_EQ(r.lift_force_peak, 0.0);
  EXPECT_EQ(r.lift_force_sq_dt, 0.0);
  ASSERT_EQ(r.phases.size(), 1u);
  EXPECT_EQ(r.phases[0].first, "down");
  EXPECT_GT(r.time, 4.0);
}

}  // namespace
}  // namespace boxing
