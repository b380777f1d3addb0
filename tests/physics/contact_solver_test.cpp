// Contact SOLVER tests that do not depend on the colleague's narrowphase: a private, test-only
// generator of sphere/box/capsule-vs-plane and sphere-sphere contacts feeds the real pipeline stages
// (begin_contacts/add_contact -> compute_constraints -> passive_forces -> forward_dynamics ->
// solve_constraints -> integrate). The full-pipeline versions live in contact_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {

void test_collide(const Model& m, Data& d) {
  begin_contacts(d);
  const double margin = m.solver.contact_margin;
  const int ng = static_cast<int>(m.geoms.size());
  for (int a = 0; a < ng; ++a) {
    for (int b = a + 1; b < ng; ++b) {
      const Geom& ga = m.geoms[a];
      const Geom& gb = m.geoms[b];
      const Pose xa = d.x[ga.body] * ga.local, xb = d.x[gb.body] * gb.local;
      if (ga.shape.type == ShapeType::Plane && gb.body != 0) {
        const Vec3 n = xa.R.col(2);
        auto point = [&](const Vec3& pw, double r, uint32_t f) {
          const double dist = n.dot(pw - xa.p) - r;
          if (dist > margin) return;
          ContactPoint cp;
          cp.geom_a = a;
          cp.geom_b = b;
          cp.normal = n;
          cp.depth = -dist;
          cp.position = pw - n * (r + 0.5 * dist);
          cp.feature = f;
          add_contact(m, d, cp);
        };
        if (gb.shape.type == ShapeType::Sphere) point(xb.p, gb.shape.radius, 0);
        if (gb.shape.type == ShapeType::Capsule) {
          point(xb.apply(Vec3(0, 0, -gb.shape.half_length)), gb.shape.radius, 0);
          point(xb.apply(Vec3(0, 0, gb.shape.half_length)), gb.shape.radius, 1);
        }
        if (gb.shape.type == ShapeType::Box)
          for (uint32_t c = 0; c < 8; ++c) {
            const Vec3& h = gb.shape.half_extents;
            point(xb.apply(Vec3(c & 1 ? h.x() : -h.x(), c & 2 ? h.y() : -h.y(), c & 4 ? h.z() : -h.z())), 0, c);
          }
      } else if (ga.shape.type == ShapeType::Sphere && gb.shape.type == ShapeType::Sphere) {
        const Vec3 dv = xb.p - xa.p;
        const double dist = dv.norm() - ga.shape.radius - gb.shape.radius;
        if (dist > margin) continue;
        ContactPoint cp;
        cp.geom_a = a;
        cp.geom_b = b;
        cp.normal = dv.normalized();
        cp.depth = -dist;
        cp.position = xa.p + cp.normal * (ga.shape.radius + 0.5 * dist);
        add_contact(m, d, cp);
      }
    }
  }
}

void test_step(const Model& m, Data& d) {
  forward_kinematics(m, d);
  test_collide(m, d);
  compute_constraints(m, d);
  passive_forces(m, d);
  forward_dynamics(m, d);
  solve_constraints(m, d);
  integrate(m, d);
}

Geom plane(const Mat3& R, const Vec3& p, double mu) {
  Geom g;
  g.body = 0;
  g.shape.type = ShapeType::Plane;
  g.local = Pose{R, p};
  g.friction = mu;
  return g;
}
int add_free_box(Model& m, const Pose& X, const Vec3& he, double mass, double mu) {
  int b = m.add_body(make_body("box", 0, JointType::Free, X, mass, Vec3::Zero(), box_inertia(mass, he)));
  Geom g;
  g.body = b;
  g.shape.type = ShapeType::Box;
  g.shape.half_extents = he;
  g.friction = mu;
  m.add_geom(g);
  return b;
}

double slide(double slope) {
  Model m;
  const Mat3 R = Eigen::AngleAxisd(slope, Vec3::UnitY()).toRotationMatrix();
  m.add_geom(plane(R, Vec3::Zero(), 0.5));
  const Vec3 he(0.1, 0.1, 0.1);
  add_free_box(m, Pose{R, R * Vec3(0, 0, he.z())}, he, 1.0, 0.5);
  m.finalize();
  Data d = make_data(m);
  while (d.time < 0.25) test_step(m, d);
  const Vec3 p0 = d.q.head<3>();
  while (d.time < 2.25) test_step(m, d);
  return (d.q.head<3>() - p0).norm();
}

}  // namespace

TEST(ContactSolver, BoxRestingOnCrateTopPlaneCreepsLessThan1mmIn10s) {
  Model m;
  m.add_geom(plane(Mat3::Identity(), Vec3(0, 0, 0.6), 0.8));  // the crate top
  add_free_box(m, at({0.05, 0.02, 0.6 + 0.1 + 0.01}), {0.1, 0.1, 0.1}, 2.0, 0.8);
  m.finalize();
  Data d = make_data(m);
  while (d.time < 1.0) test_step(m, d);
  const Vec3 p1 = d.q.head<3>();
  double vmax = 0;
  while (d.time < 10.0) {
    test_step(m, d);
    vmax = std::max(vmax, d.v.norm());
  }
  EXPECT_LT((d.q.head<3>() - p1).norm(), 1e-3);
  EXPECT_LT(vmax, 1e-3);
  EXPECT_NEAR(d.q[2], 0.7, 0.005);
  Vec3 F = Vec3::Zero();
  for (const Contact& c : d.contacts) F += c.force;
  EXPECT_NEAR(F.z(), 2.0 * 9.81, 0.02 * 2.0 * 9.81);
}

TEST(ContactSolver, BoxOnSlopeSlidesExactlyWhenTanAboveMu) {
  const double crit = std::atan(0.5);
  const double below = slide(crit - 0.01);
  const double above = slide(crit + 0.01);
  const double th = crit + 0.01;
  const double expect = 0.5 * 9.81 * (std::sin(th) - 0.5 * std::cos(th)) * (2.25 * 2.25 - 0.25 * 0.25);  // from t=0.25 to 2.25
  EXPECT_LT(below, 2e-3);
  EXPECT_NEAR(above, expect, 0.1 * expect);
}

TEST(ContactSolver, OverlappingSpheresSeparateWithPeakSpeedBelow1mps) {
  Model m;
  m.gravity.setZero();
  for (int i = 0; i < 2; ++i) {
    int b = m.add_body(make_body("ball", 0, JointType::Free, at({i * 0.15, 0, 1}), 1.0, Vec3::Zero(),
                                 Mat3::Identity() * 0.004));
    Geom g;
    g.body = b;
    g.shape.type = ShapeType::Sphere;
    g.shape.radius = 0.1;
    m.add_geom(g);
  }
  m.finalize();
  Data d = make_data(m);
  double vmax = 0;
  while (d.time < 1.0) {
    test_step(m, d);
    vmax = std::max({vmax, d.v.segment<3>(0).norm(), d.v.segment<3>(6).norm()});
  }
  EXPECT_LT(vmax, 1.0);
  EXPECT_GT((d.q.segment<3>(7) - d.q.segment<3>(0)).norm(), 0.2 - 2e-3);
}

TEST(ContactSolver, FastSphereDoesNotTunnelThroughFloor) {
  Model m;
  m.add_geom(plane(Mat3::Identity(), Vec3::Zero(), 0.8));
  int b = m.add_body(make_body("ball", 0, JointType::Free, at({0, 0, 0.5}), 1.0, Vec3::Zero(),
                               Mat3::Identity() * 0.001));
  Geom g;
  g.body = b;
  g.shape.type = ShapeType::Sphere;
  g.shape.radius = 0.05;
  m.add_geom(g);
  m.finalize();
  Data d = make_data(m);
  d.v[2] = -8.0;  // 3.3 cm per step at 240 Hz, below the speculative margin
  double zmin = 1;
  while (d.time < 1.0) {
    test_step(m, d);
    zmin = std::min(zmin, d.q[2]);
  }
  EXPECT_GT(zmin, 0.05 - 0.01);
  EXPECT_LT(std::abs(d.v[2]), 1e-2);  // no restitution
}
