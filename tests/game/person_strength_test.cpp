// The person's joint strengths (game/person_strength.h) against the boxer they are for: every joint of the boxer's
// skeleton that moves (not the free root, not the gloves welded to the forearms) has a strength, a welded one none, and
// every entry names a bone the boxer has (a renamed bone would silently read 0 otherwise). The figures are where the table says they are.
#include <gtest/gtest.h>

#include "game/person_strength.h"
#include "game/world.h"

namespace boxing {
namespace {

TEST(PersonStrength, EveryJointOfTheBoxerHasAStrengthAndEveryEntryNamesOneOfItsBones) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Stand;
  o.scenario = "stand";
  auto w = make_world(o);
  ASSERT_TRUE(w) << w.error();
  const World& world = **w;
  const auto& skeleton = world.boxer_desc.skeleton;
  EXPECT_EQ(person_strength(skeleton.name[0]), 0.0) << "the root is free: no joint";
  size_t moving = 0;
  for (int bone = 1; bone < skeleton.size(); ++bone) {
    const bool moves = world.model.bodies[world.boxers[0].bodies.body[bone]].nv > 0;
    moving += moves;
    if (moves) EXPECT_GT(person_strength(skeleton.name[bone]), 0.0) << skeleton.name[bone];
    else EXPECT_EQ(person_strength(skeleton.name[bone]), 0.0) << skeleton.name[bone] << " is welded";
  }
  for (const JointStrength& j : kPersonStrength) EXPECT_GE(skeleton.find(std::string(j.bone)), 1) << j.bone;
  EXPECT_EQ(std::size(kPersonStrength), moving);
  // Issue 63's figures for an adult man.
  EXPECT_EQ(person_strength("thigh_l"), 250.0);
  EXPECT_EQ(person_strength("shank_r"), 250.0);
  EXPECT_EQ(person_strength("foot_l"), 150.0);
  EXPECT_EQ(person_strength("upper_arm_r"), 100.0);
  EXPECT_EQ(person_strength("forearm_l"), 70.0);
}

}  // namespace
}  // namespace boxing
