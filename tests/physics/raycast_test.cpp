// Ray casts against closed-form answers: the sphere's quadratic root, the box's slab distances (faces from
// every side, oblique, edge-on, rotated), the capsule's side and caps, the plane, the cutoff, the origin-inside
// convention, outward normals, the closest of several bodies, the filter, and a link posed by its joint.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/physics/data.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/model.h"
#include "engine/physics/raycast.h"
#include "physics/physics_test_util.h"

using namespace eng::physics;
using eng::physics::test::at;
using eng::physics::test::box_shape;
using eng::physics::test::capsule_shape;
using eng::physics::test::plane_shape;
using eng::physics::test::sphere_shape;
using eng::physics::test::box_inertia;
using eng::physics::test::make_body;

namespace {

Mat3 rot(double angle, const Vec3& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

Geom geom(const Shape& s, const Pose& local, int body = 0, uint32_t group = 1) {
  Geom g;
  g.shape = s;
  g.local = local;
  g.body = body;
  g.group = group;
  return g;
}

// A model of static world geoms only, ready to cast against.
struct Scene {
  Model m;
  Data d;
  void ready() {
    m.finalize();
    d = make_data(m);
    forward_kinematics(m, d);
  }
};

// Closed form for a ray (unit d) entering a sphere from outside: t = (c - o).d - sqrt(r^2 - |c - o|^2 + ((c - o).d)^2).
double sphere_distance(const Vec3& o, const Vec3& d, const Vec3& c, double r) {
  const double b = (c - o).dot(d);
  return b - std::sqrt(r * r - (c - o).squaredNorm() + b * b);
}

}  // namespace

TEST(Raycast, SphereHitIsTheNearRootOfTheQuadraticWithTheOutwardNormal) {
  Scene s;
  const Vec3 c(1.0, 2.0, 0.5);
  s.m.add_geom(geom(sphere_shape(0.4), at(c)));
  s.ready();
  const Vec3 o(-2.0, 1.8, 0.6);
  const Vec3 dir = (c + Vec3(0.0, 0.1, -0.05) - o);  // not unit: the cast normalises it
  const Vec3 u = dir.normalized();
  const RayHit h = raycast(s.m, s.d, o, dir, 100.0);
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.geom, 0);
  EXPECT_EQ(h.body, 0);
  EXPECT_NEAR(h.distance, sphere_distance(o, u, c, 0.4), 1e-12);
  EXPECT_TRUE(h.point.isApprox(o + h.distance * u, 1e-12));
  EXPECT_NEAR((h.point - c).norm(), 0.4, 1e-12);  // on the surface
  EXPECT_TRUE(h.normal.isApprox((h.point - c) / 0.4, 1e-12));
  EXPECT_NEAR(h.normal.norm(), 1.0, 1e-12);
  EXPECT_LT(h.normal.dot(u), 0.0);  // outward: faces the incoming ray
}

TEST(Raycast, BoxFacesFromAllSixSidesAreTheSlabDistancesWithTheFaceNormal) {
  const Vec3 c(0.3, -0.2, 1.0), he(0.5, 0.3, 0.2);
  for (const Mat3& R : {Mat3(Mat3::Identity()), rot(0.7, Vec3(1, 2, 3))}) {
    Scene s;
    s.m.add_geom(geom(box_shape(he), Pose{R, c}));
    s.ready();
    for (int axis = 0; axis < 3; ++axis) {
      for (double side : {-1.0, 1.0}) {
        Vec3 n_local = Vec3::Zero();
        n_local[axis] = side;
        // start 2 m out along the face normal, offset within the face, and cast straight back in
        Vec3 offset_local(0.1 * he.x(), -0.3 * he.y(), 0.2 * he.z());
        offset_local[axis] = 0.0;
        const Vec3 o = c + R * (offset_local + (he[axis] + 2.0) * n_local);
        const RayHit h = raycast(s.m, s.d, o, -(R * n_local), 10.0);
        ASSERT_TRUE(h.hit) << axis << " " << side;
        EXPECT_NEAR(h.distance, 2.0, 1e-12);
        EXPECT_TRUE(h.normal.isApprox(R * n_local, 1e-12));
      }
    }
  }
}

TEST(Raycast, BoxObliqueAndEdgeOnHitsMatchTheHandWorkedSlabs) {
  Scene s;
  s.m.add_geom(geom(box_shape(Vec3(0.5, 0.5, 0.5)), at(Vec3::Zero())));
  s.ready();
  // oblique onto the -x face: x reaches -0.5 after 1.5 along x, where y = -1 + 0.75 = -0.25 (inside the face)
  RayHit h = raycast(s.m, s.d, Vec3(-2.0, -1.0, 0.1), Vec3(1.0, 0.5, 0.0), 10.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 1.5 * std::sqrt(1.25), 1e-12);
  EXPECT_TRUE(h.point.isApprox(Vec3(-0.5, -0.25, 0.1), 1e-12));
  EXPECT_TRUE(h.normal.isApprox(Vec3(-1, 0, 0)));
  // edge-on at 45 degrees onto the edge x = y = -0.5: both slabs are entered together; the tie goes to x
  h = raycast(s.m, s.d, Vec3(-2.0, -2.0, 0.0), Vec3(1.0, 1.0, 0.0), 10.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 1.5 * std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(h.point.isApprox(Vec3(-0.5, -0.5, 0.0), 1e-12));
  EXPECT_TRUE(h.normal.isApprox(Vec3(-1, 0, 0)));
  // just past the edge the y slab is entered last: the -y face
  h = raycast(s.m, s.d, Vec3(-2.0, -2.1, 0.0), Vec3(1.0, 1.0, 0.0), 10.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 1.6 * std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Vec3(0, -1, 0)));
  // just beyond the far edge (x = 0.5, y = -0.5): the y slab is entered (2.51) after the x slab is left (2.5)
  EXPECT_FALSE(raycast(s.m, s.d, Vec3(-2.0, -3.01, 0.0), Vec3(1.0, 1.0, 0.0), 10.0).hit);
  EXPECT_FALSE(raycast(s.m, s.d, Vec3(-2.0, -0.9, 0.0), Vec3(1.0, -1.0, 0.0), 10.0).hit);
}

TEST(Raycast, CapsuleSideAndCapHitsMatchTheCylinderAndSphereRoots) {
  Scene s;
  const Vec3 c(0.0, 0.0, 1.0);
  const Mat3 R = rot(M_PI / 2, Vec3::UnitY());  // local Z (the capsule's axis) along world +X
  s.m.add_geom(geom(capsule_shape(0.1, 0.3), Pose{R, c}));
  s.ready();
  // side: across the axis at x = 0.2 (within the straight part |x| <= 0.3)
  RayHit h = raycast(s.m, s.d, Vec3(0.2, -2.0, 1.0), Vec3::UnitY(), 10.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 1.9, 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Vec3(0, -1, 0), 1e-12));
  // side, 0.05 off the axis: the ray meets the circle y^2 + 0.05^2 = 0.1^2 of the cylinder's cross-section
  h = raycast(s.m, s.d, Vec3(0.1, -2.0, 1.05), Vec3::UnitY(), 10.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 2.0 - std::sqrt(0.01 - 0.0025), 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Vec3(0, -std::sqrt(0.0075), 0.05) / 0.1, 1e-12));
  // cap: along the axis from -X, off-centre by 0.05: the cap sphere at x = -0.3
  const Vec3 o(-2.0, 0.05, 1.0);
  h = raycast(s.m, s.d, o, Vec3::UnitX(), 10.0);
  ASSERT_TRUE(h.hit);
  const Vec3 cap(-0.3, 0.0, 1.0);
  EXPECT_NEAR(h.distance, sphere_distance(o, Vec3::UnitX(), cap, 0.1), 1e-12);
  EXPECT_TRUE(h.normal.isApprox((h.point - cap) / 0.1, 1e-12));
  // and from +X the other cap
  h = raycast(s.m, s.d, Vec3(2.0, 0.0, 1.0), -Vec3::UnitX(), 10.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 2.0 - 0.4, 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Vec3::UnitX(), 1e-12));
  // beside the cap's rim: misses
  EXPECT_FALSE(raycast(s.m, s.d, Vec3(-2.0, 0.11, 1.0), Vec3::UnitX(), 10.0).hit);
}

TEST(Raycast, PlaneHitIsHeightOverDescentRateAndUpwardRaysMiss) {
  Scene s;
  s.m.add_geom(geom(plane_shape(), at(Vec3(0, 0, 0.25))));
  s.ready();
  RayHit h = raycast(s.m, s.d, Vec3(1.0, 2.0, 3.25), Vec3(0.6, 0.0, -0.8), 100.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 3.0 / 0.8, 1e-12);
  EXPECT_NEAR(h.point.z(), 0.25, 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Vec3::UnitZ()));
  EXPECT_FALSE(raycast(s.m, s.d, Vec3(1.0, 2.0, 3.0), Vec3(0.6, 0.0, 0.8), 100.0).hit);
  EXPECT_FALSE(raycast(s.m, s.d, Vec3(1.0, 2.0, 3.0), Vec3(1.0, 0.0, 0.0), 100.0).hit);  // parallel
}

TEST(Raycast, ARayPassingBesideEveryShapeMisses) {
  Scene s;
  s.m.add_geom(geom(sphere_shape(0.5), at(Vec3(0, 0, 0))));
  s.m.add_geom(geom(box_shape(Vec3(0.2, 0.2, 0.2)), at(Vec3(3, 0, 0))));
  s.m.add_geom(geom(capsule_shape(0.1, 0.5), at(Vec3(6, 0, 0))));
  s.ready();
  EXPECT_FALSE(raycast(s.m, s.d, Vec3(-5, 0.6, 0), Vec3::UnitX(), 100.0).hit);
  EXPECT_TRUE(raycast(s.m, s.d, Vec3(-5, 0.49, 0), Vec3::UnitX(), 100.0).hit);
  EXPECT_FALSE(raycast(s.m, s.d, Vec3(-5, 0, 0), -Vec3::UnitX(), 100.0).hit);  // everything is behind
}

TEST(Raycast, MaxDistanceCutsOffHitsBeyondIt) {
  Scene s;
  s.m.add_geom(geom(sphere_shape(0.5), at(Vec3(3, 0, 0))));
  s.ready();
  EXPECT_FALSE(raycast(s.m, s.d, Vec3::Zero(), Vec3::UnitX(), 2.49).hit);
  const RayHit h = raycast(s.m, s.d, Vec3::Zero(), Vec3::UnitX(), 2.51);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 2.5, 1e-12);
}

TEST(Raycast, OriginInsideAShapeHitsItAtDistanceZeroFacingBackAlongTheRay) {
  Scene s;
  s.m.add_geom(geom(sphere_shape(0.5), at(Vec3(0, 0, 0))));
  s.m.add_geom(geom(box_shape(Vec3(0.5, 0.5, 0.5)), at(Vec3(3, 0, 0))));
  s.m.add_geom(geom(capsule_shape(0.2, 0.5), at(Vec3(6, 0, 0))));
  s.m.add_geom(geom(plane_shape(), at(Vec3(0, 0, -10))));
  s.ready();
  const Vec3 dir = Vec3(1, 1, 0).normalized();
  for (const auto& [o, g] : {std::pair{Vec3(0.1, 0, 0), 0}, std::pair{Vec3(3.4, 0, 0.4), 1},
                            std::pair{Vec3(6.0, 0.1, 0.6), 2}, std::pair{Vec3(20, 0, -11), 3}}) {
    const RayHit h = raycast(s.m, s.d, o, dir, 100.0);
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.geom, g);
    EXPECT_EQ(h.distance, 0.0);
    EXPECT_TRUE(h.point.isApprox(o));
    EXPECT_TRUE(h.normal.isApprox(-dir));
  }
}

TEST(Raycast, TheClosestOfTwoBodiesWinsWhateverTheirOrder) {
  Model m;
  const Mat3 I = box_inertia(1.0, Vec3(0.1, 0.1, 0.1));
  const int far = m.add_body(make_body("far", 0, JointType::Free, at({4, 0, 1}), 1.0, Vec3::Zero(), I));
  const int near = m.add_body(make_body("near", 0, JointType::Free, at({2, 0, 1}), 1.0, Vec3::Zero(), I));
  m.add_geom(geom(sphere_shape(0.3), Pose{}, far));
  m.add_geom(geom(box_shape(Vec3(0.2, 0.2, 0.2)), Pose{}, near));
  m.finalize();
  Data d = make_data(m);
  forward_kinematics(m, d);
  RayHit h = raycast(m, d, Vec3(0, 0, 1), Vec3::UnitX(), 100.0);
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.body, near);
  EXPECT_EQ(h.geom, 1);
  EXPECT_NEAR(h.distance, 1.8, 1e-12);
  h = raycast(m, d, Vec3(6, 0, 1), -Vec3::UnitX(), 100.0);  // from the other side the sphere is nearer
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.body, far);
  EXPECT_NEAR(h.distance, 1.7, 1e-12);
}

TEST(Raycast, TheFilterSkipsABodyAnArticulationOrAGroup) {
  Model m;
  const Mat3 I = box_inertia(1.0, Vec3(0.1, 0.1, 0.1));
  const int a = m.add_body(make_body("a", 0, JointType::Free, at({2, 0, 1}), 1.0, Vec3::Zero(), I));
  const int a_child = m.add_body(make_body("a_child", a, JointType::Hinge, at({1, 0, 0}), 1.0, Vec3::Zero(), I));
  const int b = m.add_body(make_body("b", 0, JointType::Free, at({5, 0, 1}), 1.0, Vec3::Zero(), I));
  m.add_geom(geom(sphere_shape(0.2), Pose{}, a, 1u));
  m.add_geom(geom(sphere_shape(0.2), Pose{}, a_child, 1u));
  m.add_geom(geom(sphere_shape(0.2), Pose{}, b, 2u));
  m.finalize();
  Data d = make_data(m);
  forward_kinematics(m, d);
  const Vec3 o(0, 0, 1), x = Vec3::UnitX();
  EXPECT_EQ(raycast(m, d, o, x, 100.0).body, a);
  RayFilter skip_a;
  skip_a.skip_body = a;
  EXPECT_EQ(raycast(m, d, o, x, 100.0, skip_a).body, a_child);
  RayFilter skip_root;
  skip_root.skip_root = a;
  EXPECT_EQ(raycast(m, d, o, x, 100.0, skip_root).body, b);
  RayFilter only_group_2;
  only_group_2.mask = 2u;
  EXPECT_EQ(raycast(m, d, o, x, 100.0, only_group_2).body, b);
  RayFilter only_group_4;
  only_group_4.mask = 4u;
  EXPECT_FALSE(raycast(m, d, o, x, 100.0, only_group_4).hit);
  // casting out of a body: from a's centre with a skipped, the child is the first thing hit
  const RayHit h = raycast(m, d, Vec3(2, 0, 1), x, 100.0, skip_a);
  EXPECT_EQ(h.body, a_child);
  EXPECT_NEAR(h.distance, 0.8, 1e-12);
}

TEST(Raycast, ALinkRotatedByItsJointIsHitWhereItIsPosedNotWhereItRests) {
  // a bar (box long along its local x, 1 m out from a hinge about world Z) swung by 90 degrees onto +Y
  Model m;
  const Mat3 I = box_inertia(1.0, Vec3(0.3, 0.1, 0.1));
  const int base = m.add_body(make_body("base", 0, JointType::Fixed, at({0, 0, 1}), 1.0, Vec3::Zero(), I));
  const int arm = m.add_body(make_body("arm", base, JointType::Hinge, Pose{}, 1.0, Vec3(1, 0, 0), I, Vec3::UnitZ()));
  m.add_geom(geom(box_shape(Vec3(0.3, 0.1, 0.1)), at({1, 0, 0}), arm));
  m.finalize();
  Data d = make_data(m);
  d.q[m.bodies[arm].q_index] = M_PI / 2;
  forward_kinematics(m, d);
  // straight down onto the bar's far half: at rest there is nothing at (0, 1.25)
  RayHit h = raycast(m, d, Vec3(0.0, 1.25, 3.0), -Vec3::UnitZ(), 10.0);
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.body, arm);
  EXPECT_NEAR(h.distance, 3.0 - 1.1, 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Vec3::UnitZ(), 1e-12));
  // where the bar rests at q = 0 (x = 1.25 on the X axis) and where the unrotated box would reach (0.2, 1):
  EXPECT_FALSE(raycast(m, d, Vec3(1.25, 0.0, 3.0), -Vec3::UnitZ(), 10.0).hit);
  EXPECT_FALSE(raycast(m, d, Vec3(0.2, 1.0, 3.0), -Vec3::UnitZ(), 10.0).hit);
  // side-on along -Y the bar's end face (its local +x face) is hit: the normal is rotated into the world
  h = raycast(m, d, Vec3(0.0, 3.0, 1.0), -Vec3::UnitY(), 10.0);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 3.0 - 1.3, 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Vec3::UnitY(), 1e-12));
}
