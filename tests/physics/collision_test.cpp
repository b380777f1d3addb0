// Narrowphase and broadphase against closed-form answers: depths, normals (a -> b), manifold sizes, symmetry
// under swapping the pair, stable feature ids, no NaN on random poses, broadphase == brute force.
#include <gtest/gtest.h>

#include <random>

#include "engine/physics/broadphase.h"
#include "engine/physics/narrowphase.h"
#include "physics/physics_test_util.h"

using namespace eng::physics;
using eng::physics::test::box_shape;
using eng::physics::test::capsule_shape;
using eng::physics::test::plane_shape;
using eng::physics::test::sphere_shape;

namespace {

Shape box(double x, double y, double z) { return box_shape(Vec3(x, y, z)); }
Pose at(const Vec3& p, const Mat3& R = Mat3::Identity()) { return Pose{R, p}; }
Mat3 rot(double angle, const Vec3& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

int collide(const Shape& a, const Pose& xa, const Shape& b, const Pose& xb, ContactPoint* out, double margin = 0.0) {
  return collide_shapes(a, xa, b, xb, margin, out, 4);
}

}  // namespace

TEST(Narrowphase, SphereSphereDepthNormalAndMidpoint) {
  ContactPoint c[4];
  ASSERT_EQ(collide(sphere_shape(0.5), at({0, 0, 0}), sphere_shape(0.3), at({0.7, 0, 0}), c), 1);
  EXPECT_NEAR(c[0].depth, 0.1, 1e-12);
  EXPECT_TRUE(c[0].normal.isApprox(Vec3::UnitX()));
  EXPECT_NEAR(c[0].position.x(), 0.45, 1e-12);  // midway between the surfaces at 0.5 and 0.4
}

TEST(Narrowphase, SeparatedBeyondMarginGivesNothingAndWithinMarginIsSpeculative) {
  ContactPoint c[4];
  EXPECT_EQ(collide(sphere_shape(0.5), at({0, 0, 0}), sphere_shape(0.5), at({1.1, 0, 0}), c, 0.05), 0);
  ASSERT_EQ(collide(sphere_shape(0.5), at({0, 0, 0}), sphere_shape(0.5), at({1.03, 0, 0}), c, 0.05), 1);
  EXPECT_NEAR(c[0].depth, -0.03, 1e-12);
}

TEST(Narrowphase, SphereOnPlaneAndOnBoxFace) {
  ContactPoint c[4];
  ASSERT_EQ(collide(sphere_shape(0.2), at({1, 2, 0.15}), plane_shape(), at({0, 0, 0}), c), 1);
  EXPECT_NEAR(c[0].depth, 0.05, 1e-12);
  EXPECT_TRUE(c[0].normal.isApprox(-Vec3::UnitZ()));  // from the sphere down to the plane
  ASSERT_EQ(collide(box(1, 1, 0.5), at({0, 0, 0}), sphere_shape(0.2), at({0.3, 0.1, 0.68}), c), 1);
  EXPECT_NEAR(c[0].depth, 0.02, 1e-12);
  EXPECT_TRUE(c[0].normal.isApprox(Vec3::UnitZ()));  // from the box up to the sphere
}

TEST(Narrowphase, SphereCentreInsideBoxPushesOutThroughNearestFace) {
  ContactPoint c[4];
  ASSERT_EQ(collide(sphere_shape(0.1), at({0.45, 0, 0}), box(0.5, 0.5, 0.5), at({0, 0, 0}), c), 1);
  EXPECT_NEAR(c[0].depth, 0.15, 1e-12);
  EXPECT_TRUE(c[0].normal.isApprox(-Vec3::UnitX()));  // the box lies on the sphere's -x side
}

TEST(Narrowphase, CapsuleLyingOnABoxGivesTwoPoints) {
  ContactPoint c[4];
  const int n = collide(capsule_shape(0.05, 0.2), at({0, 0, 0.54}, rot(M_PI / 2, Vec3::UnitY())), box(0.5, 0.5, 0.5),
                        at({0, 0, 0}), c);
  ASSERT_EQ(n, 2);
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(c[i].depth, 0.01, 1e-9);
    EXPECT_TRUE(c[i].normal.isApprox(-Vec3::UnitZ()));
  }
}

TEST(Narrowphase, CapsuleAcrossACrateEdgeFindsTheDeepInteriorPoint) {
  ContactPoint c[4];
  // A shin lying across the edge x = 0.5 of a crate top, tilted so both caps are clear but the middle is in.
  const Mat3 R = rot(M_PI / 2, Vec3::UnitY()) * rot(0.0, Vec3::UnitZ());
  const int n = collide(capsule_shape(0.05, 0.4), at({0.5, 0, 0.54}, R * rot(0.2, Vec3::UnitX())), box(0.5, 0.5, 0.5),
                        at({0, 0, 0}), c);
  ASSERT_GE(n, 1);
  double deepest = -1;
  for (int i = 0; i < n; ++i) deepest = std::max(deepest, c[i].depth);
  EXPECT_NEAR(deepest, 0.01, 2e-3);
}

TEST(Narrowphase, ParallelCapsulesGiveTwoPointsAndCrossedOne) {
  ContactPoint c[4];
  EXPECT_EQ(collide(capsule_shape(0.05, 0.3), at({0, 0, 0}), capsule_shape(0.05, 0.3), at({0.08, 0, 0.1}), c), 2);
  EXPECT_NEAR(c[0].depth, 0.02, 1e-9);
  ASSERT_EQ(collide(capsule_shape(0.05, 0.3), at({0, 0, 0}), capsule_shape(0.05, 0.3),
                    at({0.09, 0, 0}, rot(M_PI / 2, Vec3::UnitX())), c),
            1);
  EXPECT_NEAR(c[0].depth, 0.01, 1e-9);
  EXPECT_TRUE(c[0].normal.isApprox(Vec3::UnitX()));
}

TEST(Narrowphase, BoxRestingFlatOnBoxOrPlaneGivesFourPointsOfTheRightDepth) {
  ContactPoint c[4];
  for (double yaw : {0.0, 0.3, 1.2}) {
    ASSERT_EQ(collide(box(0.5, 0.5, 0.25), at({0, 0, 0}), box(0.1, 0.15, 0.1),
                      at({0.05, -0.1, 0.349}, rot(yaw, Vec3::UnitZ())), c),
              4)
        << yaw;
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(c[i].depth, 0.001, 1e-9);
      EXPECT_TRUE(c[i].normal.isApprox(Vec3::UnitZ(), 1e-9));
    }
  }
  ASSERT_EQ(collide(box(0.1, 0.2, 0.3), at({0, 0, 0.29}, rot(0.7, Vec3::UnitZ())), plane_shape(), at({0, 0, 0}), c), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(c[i].depth, 0.01, 1e-12);
}

TEST(Narrowphase, BoxEdgeOnEdgeGivesOnePointAlongTheCrossAxis) {
  ContactPoint c[4];
  // Two unit cubes rotated 45 degrees about perpendicular axes, touching edge to edge along Z.
  const double s = std::sqrt(2.0) * 0.5;
  const int n = collide(box(0.5, 0.5, 0.5), at({0, 0, 0}, rot(M_PI / 4, Vec3::UnitX())), box(0.5, 0.5, 0.5),
                        at({0, 0, 2 * s - 0.01}, rot(M_PI / 4, Vec3::UnitY())), c);
  ASSERT_EQ(n, 1);
  EXPECT_NEAR(c[0].depth, 0.01, 1e-8);
  EXPECT_NEAR(std::abs(c[0].normal.z()), 1.0, 1e-9);
  EXPECT_GT(c[0].normal.z(), 0.0);
}

TEST(Narrowphase, SwappingThePairFlipsTheNormalAndKeepsTheDepth) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const Shape shapes[] = {sphere_shape(0.2), capsule_shape(0.1, 0.3), box(0.2, 0.3, 0.1)};
  for (int trial = 0; trial < 300; ++trial) {
    for (const Shape& a : shapes) {
      for (const Shape& b : shapes) {
        const Pose xa = at(Vec3(u(rng), u(rng), u(rng)) * 0.3, rot(3 * u(rng), Vec3(u(rng), u(rng), u(rng) + 2)));
        const Pose xb = at(Vec3(u(rng), u(rng), u(rng)) * 0.3, rot(3 * u(rng), Vec3(u(rng), u(rng) + 2, u(rng))));
        ContactPoint c1[4], c2[4];
        const int n1 = collide(a, xa, b, xb, c1), n2 = collide(b, xb, a, xa, c2);
        if (a.type == b.type) continue;  // same-type order is the caller's; checked by the closed forms above
        ASSERT_EQ(n1, n2);
        for (int i = 0; i < n1; ++i) {
          EXPECT_NEAR(c1[i].depth, c2[i].depth, 1e-12);
          EXPECT_TRUE(c1[i].normal.isApprox(-c2[i].normal));
        }
      }
    }
  }
}

TEST(Narrowphase, RandomPosesNeverGiveNanAndNormalsAreUnit) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const Shape shapes[] = {sphere_shape(0.2), capsule_shape(0.1, 0.3), box(0.2, 0.3, 0.1), plane_shape()};
  long points = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    const Shape& a = shapes[trial % 3];
    const Shape& b = shapes[(trial / 3) % 4];
    // Include exactly coincident centres and axis-aligned poses (degenerate cases).
    const bool degenerate = trial % 17 == 0;
    const Pose xa = at(degenerate ? Vec3(Vec3::Zero()) : Vec3(Vec3(u(rng), u(rng), u(rng)) * 0.4),
                       degenerate ? Mat3(Mat3::Identity()) : rot(3 * u(rng), Vec3(u(rng), u(rng), 1.5)));
    const Pose xb = at(degenerate ? Vec3(Vec3::Zero()) : Vec3(Vec3(u(rng), u(rng), u(rng)) * 0.4),
                       degenerate ? Mat3(Mat3::Identity()) : rot(3 * u(rng), Vec3(1.5, u(rng), u(rng))));
    ContactPoint c[4];
    const int n = collide(a, xa, b, xb, c, 0.02);
    for (int i = 0; i < n; ++i, ++points) {
      ASSERT_TRUE(c[i].position.allFinite() && c[i].normal.allFinite() && std::isfinite(c[i].depth));
      EXPECT_NEAR(c[i].normal.norm(), 1.0, 1e-9);
    }
  }
  EXPECT_GT(points, 1000);
}

TEST(Narrowphase, FeatureIdsSurviveATinyPerturbation) {
  ContactPoint c1[4], c2[4];
  const Pose ground = at({0, 0, 0});
  const int n1 = collide(box(1, 1, 0.5), ground, box(0.1, 0.1, 0.1), at({0.2, 0.1, 0.599}, rot(0.3, Vec3::UnitZ())), c1);
  const int n2 = collide(box(1, 1, 0.5), ground, box(0.1, 0.1, 0.1),
                         at({0.2001, 0.1, 0.5991}, rot(0.3001, Vec3(0.001, 0, 1))), c2);
  ASSERT_EQ(n1, n2);
  for (int i = 0; i < n1; ++i) EXPECT_EQ(c1[i].feature, c2[i].feature);
}

TEST(Broadphase, FindsExactlyTheBruteForceOverlaps) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 200; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng));
    const Vec3 h = Vec3(std::abs(u(rng)), std::abs(u(rng)), std::abs(u(rng))) * 0.15;
    boxes.push_back(Aabb{c - h, c + h});
  }
  std::vector<std::pair<int, int>> pairs, brute;
  broadphase_pairs(boxes.data(), int(boxes.size()), pairs);
  for (int i = 0; i < 200; ++i)
    for (int j = i + 1; j < 200; ++j)
      if (boxes[i].overlaps(boxes[j])) brute.emplace_back(i, j);
  EXPECT_EQ(pairs, brute);
  EXPECT_GT(brute.size(), 10u);
}

TEST(Broadphase, WithFixedBoxesFindsTheBruteForceOverlapsLessFixedPairs) {
  // A grid of fixed crates (touching neighbours, as an arena's are), moving boxes over it, and two unbounded boxes
  // (planes), one fixed and one not: every overlapping pair but the fixed-fixed ones, in the same sorted order.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2, 2);
  std::vector<Aabb> boxes;
  std::vector<unsigned char> fixed;
  for (int x = 0; x < 10; ++x)
    for (int y = 0; y < 10; ++y) {
      const Vec3 c(-2.25 + 0.5 * x, -2.25 + 0.5 * y, 0.15 + 0.01 * ((x * 7 + y * 3) % 5));
      boxes.push_back(Aabb{c - Vec3(0.26, 0.26, 0.15), c + Vec3(0.26, 0.26, 0.15)});
      fixed.push_back(1);
    }
  for (int i = 0; i < 60; ++i) {
    const Vec3 c(u(rng), u(rng), 0.3 + 0.25 * std::abs(u(rng)));
    const Vec3 h = Vec3(std::abs(u(rng)), std::abs(u(rng)), std::abs(u(rng))) * 0.1;
    boxes.push_back(Aabb{c - h, c + h});
    fixed.push_back(0);
  }
  for (int k = 0; k < 2; ++k) {
    boxes.push_back(Aabb{Vec3::Constant(-1e18), Vec3::Constant(1e18)});
    fixed.push_back(k == 0);
  }
  const int n = int(boxes.size());
  std::vector<std::pair<int, int>> pairs, all, brute;
  broadphase_pairs(boxes.data(), fixed.data(), n, pairs);
  broadphase_pairs(boxes.data(), n, all);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (boxes[i].overlaps(boxes[j]) && !(fixed[i] && fixed[j])) brute.emplace_back(i, j);
  EXPECT_EQ(pairs, brute);
  EXPECT_GT(brute.size(), 150u);        // the moving boxes touch crates and the planes
  EXPECT_GT(all.size(), brute.size() + 300);  // the unmasked sweep also reports the crates' neighbour pairs
}

TEST(Broadphase, ShapeBoundsContainTheShape) {
  const Aabb b = shape_aabb(capsule_shape(0.1, 0.5), at({1, 0, 0}, rot(M_PI / 2, Vec3::UnitY())), 0.0);
  EXPECT_NEAR(b.hi.x(), 1.6, 1e-12);
  EXPECT_NEAR(b.hi.z(), 0.1, 1e-12);
  const Aabb p = shape_aabb(plane_shape(), at({0, 0, 0}), 0.0);
  EXPECT_LT(p.lo.x(), -1e10);
}

// Closed-form cases re-posed under several rigid motions of the whole scene: the depth must not change, the
// normal and point must move with the scene, the point count must stay (a frame-independent narrowphase).
TEST(Narrowphase, ClosedFormCasesAreInvariantUnderRigidMotionsOfTheScene) {
  struct Case {
    Shape a;
    Pose xa;
    Shape b;
    Pose xb;
    int n;
    double depth;
    Vec3 normal;
  };
  const Case cases[] = {
      {sphere_shape(0.5), at({0, 0, 0}), sphere_shape(0.3), at({0.7, 0, 0}), 1, 0.1, Vec3::UnitX()},
      {sphere_shape(0.2), at({0, 0, 0.5}), capsule_shape(0.1, 0.5), at({0, 0.25, 0.5}, rot(M_PI / 2, Vec3::UnitY())), 1, 0.05,
       Vec3::UnitY()},
      {capsule_shape(0.1, 0.4), at({0, 0, 0}), capsule_shape(0.1, 0.4), at({0, 0.15, 0}), 2, 0.05, Vec3::UnitY()},
      {box(1, 1, 0.5), at({0, 0, 0}), sphere_shape(0.25), at({0.2, -0.1, 0.7}), 1, 0.05, Vec3::UnitZ()},
      {box(1, 1, 0.5), at({0, 0, 0}), capsule_shape(0.1, 0.3), at({0, 0, 0.58}, rot(M_PI / 2, Vec3::UnitX())), 2, 0.02,
       Vec3::UnitZ()},
      {box(1, 1, 0.5), at({0, 0, 0}), box(0.3, 0.2, 0.1), at({0.1, 0.1, 0.59}), 4, 0.01, Vec3::UnitZ()},
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Case& k : cases) {
    for (int r = 0; r < 6; ++r) {
      const Mat3 Rw = r == 0 ? Mat3::Identity() : rot(3.0 * u(rng), Vec3(u(rng), u(rng), u(rng)) + Vec3(0, 0, 1e-3));
      const Pose W{Rw, Vec3(u(rng), u(rng), u(rng))};
      ContactPoint c[4];
      ASSERT_EQ(collide(k.a, W * k.xa, k.b, W * k.xb, c), k.n) << "case depth " << k.depth << " motion " << r;
      for (int i = 0; i < k.n; ++i) {
        EXPECT_NEAR(c[i].depth, k.depth, 1e-9);
        EXPECT_TRUE(c[i].normal.isApprox(Rw * k.normal, 1e-9)) << c[i].normal.transpose();
      }
    }
  }
}
