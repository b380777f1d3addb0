// Person (egocentric) space helpers: heading extraction and person_space_root.
#include "engine/control/servo/person_space.h"

#include <gtest/gtest.h>

#include "control/control_test_util.h"

using namespace eng::control;
using eng::control::test::aa;
using Eigen::Quaterniond;
using Eigen::Vector3d;

TEST(PersonSpace, HeadingOfYawedPitchedRolled) {
  for (double yaw : {-3.0, -1.2, 0.0, 0.4, 2.5, 3.1})
    for (double pitch : {-1.2, -0.3, 0.0, 0.5, 1.4})
      for (double roll : {0.0, 0.7}) {
        const Quaterniond q = aa(yaw, Vector3d::UnitZ()) * aa(pitch, Vector3d::UnitY()) * aa(roll, Vector3d::UnitX());
        EXPECT_NEAR(heading_of(q), yaw, 1e-12) << yaw << " " << pitch << " " << roll;
      }
}

TEST(PersonSpace, HeadingWhenForwardIsVerticalIsFinite) {
  const Quaterniond q = aa(0.8, Vector3d::UnitZ()) * aa(M_PI / 2, Vector3d::UnitY());  // +X points down
  const double h = heading_of(q);
  EXPECT_TRUE(std::isfinite(h));
}

TEST(PersonSpace, PersonRootHasGameHeadingAndClipTilt) {
  const Quaterniond clip = aa(1.3, Vector3d::UnitZ()) * aa(0.3, Vector3d::UnitY()) * aa(-0.2, Vector3d::UnitX());
  for (double game : {-2.9, -0.5, 0.0, 1.0, 3.0}) {
    const Quaterniond p = person_space_root(clip, game);
    EXPECT_NEAR(heading_of(p), game, 1e-12);
    // Same tilt: the body's up axis makes the same angle with world up, and tilt-without-heading agrees.
    EXPECT_NEAR((p * Vector3d::UnitZ()).z(), (clip * Vector3d::UnitZ()).z(), 1e-12);
    EXPECT_LT(orientation_error(remove_heading(p), remove_heading(clip)).norm(), 1e-12);
  }
  // With the clip's own heading, person space reproduces the clip root.
  EXPECT_LT(orientation_error(person_space_root(clip, heading_of(clip)), clip).norm(), 1e-12);
}
