// deepest_overlap against closed-form capsule depths: two capsules of radius r whose axes cross at right angles a
// distance s apart overlap by 2r - s (none once s >= 2r); collision filters do not hide an overlap; the deepest
// pair wins.
#include <gtest/gtest.h>

#include "engine/physics/dynamics.h"
#include "engine/physics/overlap.h"
#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {

constexpr double kR = 0.06, kHalf = 0.2;

struct Crossed {
  Model m;
  Data d;
  std::vector<int> a, b;
};

// Body a: capsules along z, at each of a_offsets (body frame). Body b: one capsule along x, its axis `gap` from
// body a's origin along y. Both geoms filtered as a boxer's own geoms are (the step would not collide them).
Crossed crossed(double gap, const std::vector<Vec3>& a_offsets = {Vec3::Zero()}) {
  Crossed s;
  const int a = s.m.add_body(make_body("a", 0, JointType::Free, at({0, 0, 1}), 1.0, Vec3::Zero(), Mat3::Identity() * 0.01));
  const int b = s.m.add_body(make_body("b", 0, JointType::Free, at({0, gap, 1}), 1.0, Vec3::Zero(), Mat3::Identity() * 0.01));
  auto add = [&](int body, const Pose& local) {
    Geom g;
    g.body = body;
    g.shape = capsule_shape(kR, kHalf);
    g.local = local;
    g.self_collide = false;
    g.group = 1, g.mask = 0;
    return s.m.add_geom(g);
  };
  for (const Vec3& o : a_offsets) s.a.push_back(add(a, at(o)));
  s.b.push_back(add(b, Pose{Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix(), Vec3::Zero()}));
  s.m.finalize();
  s.d = make_data(s.m);
  forward_kinematics(s.m, s.d);
  return s;
}

}  // namespace

TEST(Overlap, CrossedCapsulesOverlapByTwiceTheRadiusLessTheAxesDistance) {
  for (double gap : {0.0, 0.03, 0.06, 0.1}) {
    const Crossed s = crossed(gap);
    EXPECT_NEAR(deepest_overlap(s.m, s.d, s.a, s.b), 2 * kR - gap, 1e-9) << "gap " << gap;
    EXPECT_NEAR(deepest_overlap(s.m, s.d, s.b, s.a), 2 * kR - gap, 1e-9) << "gap " << gap;
  }
}

TEST(Overlap, CapsulesApartOrAnEmptySetGiveZero) {
  const Crossed s = crossed(2 * kR + 0.01);
  EXPECT_EQ(deepest_overlap(s.m, s.d, s.a, s.b), 0.0);
  const Crossed t = crossed(0.0);
  EXPECT_EQ(deepest_overlap(t.m, t.d, t.a, {}), 0.0);
}

TEST(Overlap, TheDeepestPairWins) {
  // b's axis 0.05 from a's first capsule, 0.02 from its second (moved 0.03 toward b): 0.10 deep, not 0.07.
  const Crossed s = crossed(0.05, {Vec3::Zero(), Vec3(0, 0.03, 0)});
  EXPECT_NEAR(deepest_overlap(s.m, s.d, s.a, s.b), 2 * kR - 0.02, 1e-9);
  EXPECT_NEAR(deepest_overlap(s.m, s.d, {s.a[0]}, s.b), 2 * kR - 0.05, 1e-9);
}
