// The two balance controllers behind one interface: the CLI's --balance and servo space choose the implementation,
// and each places the clip on the crates its own way (PD: part of the rear crate's step, capped; QP: no rise, a
// deeper stance).
#include <gtest/gtest.h>

#include <variant>

#include "game/boxer.h"
#include "game/cli.h"
#include "game/world.h"

using namespace boxing;

TEST(BalanceController, ThePdRiseIsThreeQuartersOfTheRearStepCappedAtNineCentimetres) {
  Boxer b;
  b.ctl.balance = PdBalance{};
  const PdBalance pd;
  b.stance.lead_top = 0.30, b.stance.rear_top = 0.38;  // rear 8 cm higher: 0.75 x 0.08
  EXPECT_NEAR(stance_rise(pd, b), 0.06, 1e-12);
  b.stance.rear_top = 0.46;  // 16 cm: 0.12, capped
  EXPECT_DOUBLE_EQ(stance_rise(pd, b), 0.09);
  b.stance.rear_top = 0.20;  // lead higher: no rise
  EXPECT_DOUBLE_EQ(stance_rise(pd, b), 0.0);
  EXPECT_DOUBLE_EQ(stance_drop(pd, b), 0.0);
  EXPECT_FALSE(plans_steps(pd));
  EXPECT_TRUE(model_springs(pd));
}

TEST(BalanceController, TheQpNeverRisesStandsDeeperAndPlansSteps) {
  Boxer b;
  const QpBalance qp;
  b.stance.lead_top = 0.30, b.stance.rear_top = 0.46;
  b.settings.tuning.qp.stance_drop = 0.05;  // read from the settings (live-editable)
  EXPECT_DOUBLE_EQ(stance_rise(qp, b), 0.0);
  EXPECT_DOUBLE_EQ(stance_drop(qp, b), 0.05);
  EXPECT_TRUE(plans_steps(qp));
  EXPECT_FALSE(model_springs(qp));
}

TEST(BalanceController, BalanceAndServoSpaceChooseTheImplementation) {
  const auto boxer0 = [](std::vector<std::string> args) {
    auto o = parse_cli(args);
    EXPECT_TRUE(o.ok());
    auto w = make_world(*o);
    EXPECT_TRUE(w.ok()) << w.error();
    return (*w)->boxers[0].ctl.balance.index();
  };
  EXPECT_EQ(boxer0({"--scenario", "stand"}), 1u) << "qp by default";
  EXPECT_EQ(boxer0({"--scenario", "stand", "--balance", "pd"}), 0u);
  EXPECT_EQ(boxer0({"--scenario", "stand", "--servo", "parent"}), 0u) << "parent space has no QP";
  EXPECT_EQ(boxer0({"--scenario", "ragdolls"}), 0u) << "a limp ragdoll";
}
