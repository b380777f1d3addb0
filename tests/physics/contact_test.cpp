// Contact behaviour of the whole pipeline with the real broadphase + narrowphase.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {
Geom static_box(const Vec3& center, const Vec3& he, const Mat3& R = Mat3::Identity()) {
  Geom g;
  g.body = 0;
  g.shape.type = ShapeType::Box;
  g.shape.half_extents = he;
  g.local = Pose{R, center};
  return g;
}
Geom plane(const Mat3& R = Mat3::Identity(), double mu = 0.8) {
  Geom g;
  g.body = 0;
  g.shape.type = ShapeType::Plane;
  g.local = Pose{R, Vec3::Zero()};
  g.friction = mu;
  return g;
}
int add_free_box(Model& m, const Pose& X, const Vec3& he, double mass, double mu = 0.8) {
  int b = m.add_body(make_body("box", 0, JointType::Free, X, mass, Vec3::Zero(), box_inertia(mass, he)));
  Geom g;
  g.body = b;
  g.shape.type = ShapeType::Box;
  g.shape.half_extents = he;
  g.friction = mu;
  m.add_geom(g);
  return b;
}
}  // namespace

TEST(Contact, BoxRestingOnCrateTopCreepsLessThan1mmIn10s) {
  Model m;
  m.add_geom(plane());
  m.add_geom(static_box({0, 0, 0.3}, {0.3, 0.3, 0.3}));  // crate, top at z = 0.6
  add_free_box(m, at({0.05, 0.02, 0.6 + 0.1}), {0.1, 0.1, 0.1}, 2.0);
  m.finalize();
  Data d = make_data(m);
  while (d.time < 1.0) step(m, d);  // settle
  const Vec3 p1 = d.q.head<3>();
  double vmax = 0;
  while (d.time < 10.0) {
    step(m, d);
    vmax = std::max(vmax, d.v.norm());
  }
  const Vec3 p10 = d.q.head<3>();
  EXPECT_LT((p10 - p1).norm(), 1e-3);
  EXPECT_LT(vmax, 1e-3);                 // no jitter
  EXPECT_NEAR(p10.z(), 0.7, 0.01);        // on the crate top (small soft-contact penetration)
  // contact forces carry the weight
  Vec3 F = Vec3::Zero();
  for (const Contact& c : d.contacts) F += c.body_b == 1 ? c.force : Vec3(-c.force);
  EXPECT_NEAR(F.z(), 2.0 * 9.81, 0.05 * 2.0 * 9.81);
}

namespace {
// box on a plane tilted by `slope` about Y, mu = 0.5 on both: returns distance slid in 2 s
double slide_distance(double slope) {
  Model m;
  const Mat3 R = Eigen::AngleAxisd(slope, Vec3::UnitY()).toRotationMatrix();
  m.add_geom(plane(R, 0.5));
  const Vec3 he(0.1, 0.1, 0.1);
  const int b = add_free_box(m, Pose{R, R * Vec3(0, 0, he.z())}, he, 1.0, 0.5);
  m.finalize();
  Data d = make_data(m);
  while (d.time < 0.25) step(m, d);  // settle the soft contact
  const Vec3 p0 = d.q.segment<3>(m.bodies[b].q_index);
  while (d.time < 2.25) step(m, d);
  return (d.q.segment<3>(m.bodies[b].q_index) - p0).norm();
}
}  // namespace

TEST(Contact, BoxOnSlopeSlidesExactlyWhenTanAboveMu) {
  const double crit = std::atan(0.5);
  const double below = slide_distance(crit - 0.01);
  const double above = slide_distance(crit + 0.01);
  const double th = crit + 0.01;
  const double expect = 0.5 * 9.81 * (std::sin(th) - 0.5 * std::cos(th)) * (2.25 * 2.25 - 0.25 * 0.25);  // from t=0.25 to 2.25
  EXPECT_LT(below, 2e-3);
  EXPECT_NEAR(above, expect, 0.1 * expect);
}

TEST(Contact, CapsuleDroppedOnCrateEdgeDoesNotTunnel) {
  Model m;
  m.add_geom(plane());
  m.add_geom(static_box({0, 0, 0.3}, {0.3, 0.3, 0.3}));
  const double r = 0.05;
  // slightly tilted, its centre 3 cm inside the crate's edge: it lands on the edge region (v ~ 7.7 m/s,
  // 3.2 cm per step at 240 Hz)
  const Mat3 R = Eigen::AngleAxisd(0.3, Vec3::UnitX()).toRotationMatrix();
  int b = m.add_body(make_body("capsule", 0, JointType::Free, Pose{R, Vec3(0.27, 0, 3.0)}, 1.0, Vec3::Zero(),
                               rod_inertia_z(1.0, 0.4, r)));
  Geom g;
  g.body = b;
  g.shape.type = ShapeType::Capsule;
  g.shape.radius = r;
  g.shape.half_length = 0.15;
  m.add_geom(g);
  m.finalize();
  Data d = make_data(m);
  bool inside = false;
  while (d.time < 4.0) {
    step(m, d);
    forward_kinematics(m, d);
    for (double s : {-0.15, 0.0, 0.15}) {  // points on the capsule axis
      const Vec3 p = d.x[b].apply(Vec3(0, 0, s));
      if (std::abs(p.x()) < 0.3 - 0.01 && std::abs(p.y()) < 0.3 - 0.01 && p.z() < 0.6 - 0.02) inside = true;
    }
  }
  EXPECT_FALSE(inside);
  const double z = d.q[2];
  EXPECT_TRUE(z > 0.6 || z < 0.2) << "z = " << z;
  EXPECT_GT(z, 0.0);
}

TEST(Contact, OverlappingSpheresSeparateCalmly) {
  Model m;
  m.gravity.setZero();
  const double r = 0.1;
  add_free_sphere(m, {0, 0, 1}, r, 1.0);
  add_free_sphere(m, {2 * r - 0.05, 0, 1}, r, 1.0);  // 5 cm overlap
  m.finalize();
  Data d = make_data(m);
  double vmax = 0;
  while (d.time < 1.0) {
    step(m, d);
    vmax = std::max({vmax, d.v.segment<3>(0).norm(), d.v.segment<3>(6).norm()});
  }
  EXPECT_LT(vmax, 1.0);
  EXPECT_GT(vmax, 0.05);
  EXPECT_GT((d.q.segment<3>(7) - d.q.segment<3>(0)).norm(), 2 * r - 2e-3);
}

TEST(Contact, OverlappingLimbsOfOneArticulationSeparateCalmly) {
  // two capsule "forearms" on hinges from one root, spawned 5 cm interpenetrating
  Model m;
  m.gravity.setZero();
  int root = m.add_body(make_body("root", 0, JointType::Free, at({0, 0, 1}), 5.0, Vec3::Zero(),
                                  box_inertia(5.0, {0.1, 0.1, 0.1})));
  for (int s = -1; s <= 1; s += 2) {
    int l = m.add_body(make_body("limb", root, JointType::Hinge, at({0, 0.04 * s, 0}), 1.0, {0.2, 0, 0},
                                 rod_inertia_z(1.0, 0.4), Vec3::UnitZ()));
    Geom g;
    g.body = l;
    g.shape.type = ShapeType::Capsule;
    g.shape.radius = 0.045;
    g.shape.half_length = 0.12;
    g.local = Pose{Eigen::AngleAxisd(M_PI / 2, Vec3::UnitY()).toRotationMatrix(), Vec3(0.25, 0, 0)};
    m.add_geom(g);
  }
  m.finalize();
  Data d = make_data(m);
  double vmax = 0;
  while (d.time < 1.0) {
    step(m, d);
    forward_kinematics(m, d);
    for (int b = 2; b <= 3; ++b) vmax = std::max(vmax, lin(d.v_body[b]).norm() + ang(d.v_body[b]).norm() * 0.4);
  }
  EXPECT_LT(vmax, 1.0);
  EXPECT_GT(std::abs(d.q[7] - d.q[8]), 0.05);  // they moved apart
}

TEST(Contact, PairFilteringRules) {
  // chain root(free) -> a(hinge) -> b(hinge), a sphere on each, all overlapping each other
  auto build = [](bool self_collide, uint32_t mask_b) {
    Model m;
    m.gravity.setZero();
    int root = m.add_body(make_body("root", 0, JointType::Free, at({0, 0, 1}), 1, Vec3::Zero(), Mat3::Identity() * 0.01));
    int a = m.add_body(make_body("a", root, JointType::Hinge, at({0.05, 0, 0}), 1, Vec3::Zero(), Mat3::Identity() * 0.01));
    int b = m.add_body(make_body("b", a, JointType::Hinge, at({0.05, 0, 0}), 1, Vec3::Zero(), Mat3::Identity() * 0.01));
    for (int body : {root, a, b}) {
      Geom g;
      g.body = body;
      g.shape.type = ShapeType::Sphere;
      g.shape.radius = 0.1;
      g.self_collide = self_collide;
      if (body == b) g.mask = mask_b;
      m.add_geom(g);
    }
    m.finalize();
    return m;
  };
  auto pairs_in_contact = [](const Model& m) {
    Data d = make_data(m);
    forward_kinematics(m, d);
    collide(m, d);
    std::vector<std::pair<int, int>> p;
    for (const Contact& c : d.contacts) p.emplace_back(c.body_a, c.body_b);
    return p;
  };
  // parent/child pairs (root-a, a-b) never collide; root-b (grand-parent) does with self collision
  auto p = pairs_in_contact(build(true, 0xffffffffu));
  ASSERT_FALSE(p.empty());
  for (auto& [x, y] : p) EXPECT_TRUE((x == 1 && y == 3) || (x == 3 && y == 1)) << x << "," << y;
  EXPECT_TRUE(pairs_in_contact(build(false, 0xffffffffu)).empty());  // self collision off
  EXPECT_TRUE(pairs_in_contact(build(true, 0u)).empty());            // b's mask excludes everything
}
TEST(Contact, StackOfThreeCratesStaysPut) {
  Model m;
  m.add_geom(plane());
  for (int i = 0; i < 3; ++i) add_free_box(m, at({0.01 * i, 0, 0.2 + 0.4 * i}), {0.2, 0.2, 0.2}, 10.0);
  m.finalize();
  Data d = make_data(m);
  while (d.time < 1.0) step(m, d);
  const VecX q1 = d.q;
  double vmax = 0;
  while (d.time < 10.0) {
    step(m, d);
    vmax = std::max(vmax, d.v.cwiseAbs().maxCoeff());
  }
  for (int i = 0; i < 3; ++i) EXPECT_LT((d.q.segment<3>(7 * i) - q1.segment<3>(7 * i)).norm(), 1e-3) << "box " << i;
  EXPECT_LT(vmax, 1e-3);
  EXPECT_NEAR(d.q[14 + 2], 1.0, 0.01);  // top box centre
}

// Speculative contacts: a sphere moving 3.3 cm per step (below the 4 cm margin) stops on the floor instead of
// passing through it, and does not bounce (no restitution).
TEST(Contact, FastSphereDoesNotTunnelThroughTheFloorAndDoesNotBounce) {
  Model m;
  m.add_geom(plane());
  const int b = add_free_sphere(m, {0, 0, 0.5}, 0.05, 1.0);
  m.finalize();
  Data d = make_data(m);
  d.v[m.bodies[b].v_index + 2] = -8.0;
  double zmin = 1;
  while (d.time < 1.0) {
    step(m, d);
    zmin = std::min(zmin, d.q[m.bodies[b].q_index + 2]);
  }
  EXPECT_GT(zmin, 0.05 - 0.01);
  EXPECT_LT(std::abs(d.v[m.bodies[b].v_index + 2]), 1e-2);
}
