// Foot contacts from a hand-built contact list: each purpose's flag at its own depth threshold, the feet's normal
// force with the sign of the contact's side, the stance points in contact order, and the fall detection's links.
#include "engine/control/biped/foot_contacts.h"

#include <gtest/gtest.h>

using namespace eng::control;
using eng::physics::Contact;

namespace {
// Bones: 0 pelvis, 1 thigh_l, 2 shank_l, 3 foot_l, 4 thigh_r, 5 shank_r, 6 foot_r; bodies = bone + 10 (0 is static).
BipedBones bones() {
  BipedBones b;
  b.leg[0] = {1, 2, 3};
  b.leg[1] = {4, 5, 6};
  b.foot[0] = 3, b.foot[1] = 6;
  return b;
}
const std::vector<int> kBodies = {10, 11, 12, 13, 14, 15, 16};

Contact contact(int a, int b, double depth, double x, double y, double fz = 0.0) {
  Contact c;
  c.body_a = a, c.body_b = b;
  c.point.depth = depth;
  c.point.position = Eigen::Vector3d(x, y, 0.3);
  c.force = Eigen::Vector3d(0.0, 0.0, fz);
  return c;
}
}  // namespace

TEST(FootContacts, EachPurposeCountsAContactAtItsOwnGap) {
  // Left foot 1 cm above the ground (speculative): on the servo's support (2 cm) but not loaded in the plan (2 mm).
  // Right foot touching (1 mm gap) at two points.
  const std::vector<Contact> cs = {contact(0, 13, -0.01, 0.0, 0.1), contact(0, 16, -0.001, 0.2, -0.1),
                                   contact(16, 0, 0.002, 0.3, -0.1)};
  FootContacts fc;
  find_foot_contacts(cs, kBodies, bones(), FootContactThresholds{}, fc);
  EXPECT_TRUE(fc.support[0]);
  EXPECT_FALSE(fc.on_ground[0]);
  EXPECT_TRUE(fc.ground_points[0].empty());
  EXPECT_TRUE(fc.support[1]);
  EXPECT_TRUE(fc.on_ground[1]);
  ASSERT_EQ(fc.ground_points[1].size(), 2u);
  EXPECT_EQ(fc.ground_points[1][0], Eigen::Vector2d(0.2, -0.1));
  EXPECT_EQ(fc.ground_points[1][1], Eigen::Vector2d(0.3, -0.1));
  // 3 cm away: nothing at all.
  find_foot_contacts({contact(0, 13, -0.03, 0.0, 0.1)}, kBodies, bones(), FootContactThresholds{}, fc);
  EXPECT_FALSE(fc.support[0]);
  EXPECT_TRUE(fc.ground_points[1].empty()) << "the struct is refilled, not accumulated";
}

TEST(FootContacts, NormalForceIsTheForceOnTheFootWhicheverSideItIs) {
  // force is the force on body b; a foot as body a gets its negative.
  const std::vector<Contact> cs = {contact(0, 13, 0.0, 0, 0, 300.0), contact(13, 0, 0.0, 0, 0, -200.0),
                                   contact(13, 16, 0.0, 0, 0, 50.0)};  // foot on foot: support, not ground
  FootContacts fc;
  find_foot_contacts(cs, kBodies, bones(), FootContactThresholds{}, fc);
  EXPECT_DOUBLE_EQ(fc.normal_force[0], 300.0 + 200.0 - 50.0);
  EXPECT_DOUBLE_EQ(fc.normal_force[1], 50.0);
  EXPECT_TRUE(fc.support[1]);
  EXPECT_FALSE(fc.on_ground[1]);
}

TEST(FootContacts, AContactOnACratesSideIsOnTheGroundButNotOnATop) {
  // A swing's sole brushing a crate's side: the contact's normal is level. On the ground (the plan may load it), but
  // not a landing on a top (a balance step's touch-down reads on_top).
  Contact side = contact(0, 13, 0.0, 0.0, 0.1);
  side.point.normal = Eigen::Vector3d(0.0, 1.0, 0.02).normalized();
  FootContacts fc;
  find_foot_contacts({side}, kBodies, bones(), FootContactThresholds{}, fc);
  EXPECT_TRUE(fc.on_ground[0]);
  EXPECT_FALSE(fc.on_top[0]);
  // The same foot on the top as well (normal up, whichever body the foot is): on a top.
  Contact top = contact(13, 0, 0.0, 0.1, 0.1);
  top.point.normal = Eigen::Vector3d(0.05, 0.0, -1.0).normalized();
  find_foot_contacts({side, top}, kBodies, bones(), FootContactThresholds{}, fc);
  EXPECT_TRUE(fc.on_top[0]);
  EXPECT_FALSE(fc.on_top[1]);
  // A contact 1 cm away (speculative) is not on the ground, so not on a top either, whatever its normal.
  find_foot_contacts({contact(0, 16, -0.01, 0.0, 0.0)}, kBodies, bones(), FootContactThresholds{}, fc);
  EXPECT_FALSE(fc.on_top[1]);
}

TEST(FootContacts, OnlyLinksOtherThanFeetAndShanksOnTheGroundCountAsFallen) {
  FootContacts fc;
  find_foot_contacts({contact(0, 12, 0.0, 0, 0), contact(0, 16, 0.0, 0, 0)}, kBodies, bones(), {}, fc);
  EXPECT_FALSE(fc.other_link_on_ground) << "a shank (kneeling) and a foot";
  find_foot_contacts({contact(0, 99, 0.0, 0, 0)}, kBodies, bones(), {}, fc);
  EXPECT_FALSE(fc.other_link_on_ground) << "another character's link";
  find_foot_contacts({contact(11, 14, 0.0, 0, 0)}, kBodies, bones(), {}, fc);
  EXPECT_FALSE(fc.other_link_on_ground) << "two links of the body, not the ground";
  find_foot_contacts({contact(0, 10, -0.004, 0, 0)}, kBodies, bones(), {}, fc);
  EXPECT_TRUE(fc.other_link_on_ground) << "the pelvis within 5 mm";
  find_foot_contacts({contact(10, 0, -0.006, 0, 0)}, kBodies, bones(), {}, fc);
  EXPECT_FALSE(fc.other_link_on_ground) << "the pelvis 6 mm away";
}
