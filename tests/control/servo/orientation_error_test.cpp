// Delta(D, A) of the paper (section IV): axis*angle of D * A^-1, world frame.
#include "engine/control/servo/orientation_error.h"

#include <gtest/gtest.h>

#include <cmath>

#include "control/control_test_util.h"

using namespace eng::control;
using eng::control::test::aa;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {
const Vector3d kAxes[] = {Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ(), Vector3d(1, 2, 3).normalized(),
                          Vector3d(-0.3, 0.9, -0.2).normalized()};
const Quaterniond kA = aa(0.7, Vector3d(0.2, -1, 0.5));  // a non-trivial actual orientation
}  // namespace

TEST(OrientationError, IdentityIsZero) {
  EXPECT_EQ(orientation_error(Quaterniond::Identity(), Quaterniond::Identity()), Vector3d::Zero());
  EXPECT_LT(orientation_error(kA, kA).norm(), 1e-15);
}

TEST(OrientationError, KnownAxisAngles) {
  for (const Vector3d& a : kAxes)
    for (double th = 0.1; th < 3.15; th += 0.25) {
      const double t = std::min(th, 3.1);
      const Vector3d e = orientation_error(aa(t, a) * kA, kA);
      EXPECT_LT((e - t * a).norm(), 1e-12) << "angle " << t << " axis " << a.transpose();
    }
}

TEST(OrientationError, SmallAnglesAreAccurate) {
  for (double t : {1e-15, 1e-12, 1e-9, 1e-7, 1e-6, 2e-6, 1e-4}) {
    const Vector3d a = kAxes[3];
    const Vector3d e = quaternion_log_vector(aa(t, a));
    EXPECT_LT((e - t * a).norm(), 1e-13 * t + 1e-30) << t;
  }
}

TEST(OrientationError, NearPiIsFiniteWithConsistentAxis) {
  for (const Vector3d& a : kAxes) {
    const Vector3d e1 = orientation_error(aa(M_PI - 1e-9, a) * kA, kA);
    ASSERT_TRUE(e1.allFinite());
    EXPECT_NEAR(e1.norm(), M_PI - 1e-9, 1e-7);
    EXPECT_GT(e1.normalized().dot(a), 1.0 - 1e-9);  // the short way round: along +a
    // pi exactly, built with w == 0: finite, |e| = pi, and q / -q agree.
    const Quaterniond qpi(0.0, a.x(), a.y(), a.z());
    const Vector3d ep = quaternion_log_vector(qpi);
    const Vector3d em = quaternion_log_vector(Quaterniond(-0.0, -a.x(), -a.y(), -a.z()));
    ASSERT_TRUE(ep.allFinite());
    EXPECT_NEAR(ep.norm(), M_PI, 1e-12);
    EXPECT_LT((ep - em).norm(), 1e-15);
    EXPECT_NEAR(std::abs(ep.normalized().dot(a)), 1.0, 1e-12);
    // pi via AngleAxis (w ~ 6e-17) composed with A: finite, magnitude pi.
    const Vector3d e3 = orientation_error(aa(M_PI, a) * kA, kA);
    ASSERT_TRUE(e3.allFinite());
    EXPECT_NEAR(e3.norm(), M_PI, 1e-9);
  }
}

TEST(OrientationError, SignFlippedQuaternionGivesSameResult) {
  const Quaterniond D = aa(2.0, kAxes[4]) * kA;
  const Quaterniond Dm(-D.w(), -D.x(), -D.y(), -D.z());
  const Quaterniond Am(-kA.w(), -kA.x(), -kA.y(), -kA.z());
  const Vector3d e = orientation_error(D, kA);
  EXPECT_LT((orientation_error(Dm, kA) - e).norm(), 1e-14);
  EXPECT_LT((orientation_error(D, Am) - e).norm(), 1e-14);
  EXPECT_LT((orientation_error(Dm, Am) - e).norm(), 1e-14);
  // Shortest path: a 3.5 rad rotation reads as 2pi - 3.5 the other way.
  const Vector3d l = orientation_error(aa(3.5, kAxes[0]) * kA, kA);
  EXPECT_LT((l - (3.5 - 2 * M_PI) * kAxes[0]).norm(), 1e-12);
}

TEST(OrientationError, OrderingIsDTimesAInverseInWorldFrame) {
  // D = R * A  =>  Delta(D, A) = log(R) (world frame), NOT log(A^-1 D) (the body-frame error).
  const Quaterniond R = aa(0.9, Vector3d::UnitZ());
  const Quaterniond A = aa(1.2, Vector3d::UnitX());
  const Vector3d e = orientation_error(R * A, A);
  EXPECT_LT((e - 0.9 * Vector3d::UnitZ()).norm(), 1e-12);
  const Vector3d body = quaternion_log_vector(A.conjugate() * (R * A));
  EXPECT_GT((body - e).norm(), 0.1);  // the two conventions differ for non-commuting A
  // Antisymmetry: Delta(A, D) = -Delta(D, A).
  EXPECT_LT((orientation_error(A, R * A) + e).norm(), 1e-12);
}

TEST(OrientationError, ExpMapRoundTrip) {
  for (const Vector3d& a : kAxes)
    for (double t : {0.0, 1e-8, 0.5, 3.0}) {
      const Vector3d r = t * a;
      EXPECT_LT((quaternion_log_vector(rotation_from_vector(r)) - r).norm(), 1e-12);
    }
}
