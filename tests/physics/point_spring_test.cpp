// Point springs (Box2D v3 mouse joint): soft 3-row constraint with the point's effective mass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {
// free body, no gravity; inertia diag(Ixx, Iyy, Izz) * scale, mass * scale
Model free_body(double mass, const Vec3& inertia) {
  Model m;
  m.gravity.setZero();
  m.add_body(make_body("b", 0, JointType::Free, at({0, 0, 1}), mass, Vec3::Zero(), inertia.asDiagonal()));
  m.finalize();
  return m;
}
Vec3 world_point(const Data& d, int body, const Vec3& local) { return d.x[body].R * local + d.x[body].p; }
}  // namespace

// Box2D v3's soft step with the exact effective mass is implicit Euler of the spring-damper
// x'' = -w^2 (x - target) - 2 zeta w x' (w = 2 pi hertz):
//   v+ = a3 v - a3 h w^2 (x - target),  x+ = x + h v+,  a3 = 1 / (1 + h w (2 zeta + h w))
// (bias_rate * mass_scale = h w^2 a3, 1 - mass_scale = a3). A point at the com of a free body moves
// exactly so: the simulation must follow this recursion to round-off, and the continuous critically
// damped x(t) = target + (x0 - target)(1 + w t) e^{-w t} within implicit Euler's first-order error:
// O(h w) of the amplitude (h w = 0.052 here; the recursion itself is 0.8 % of the amplitude off x(t),
// bound used: h w / 4).
TEST(PointSpring, FreeBodySettlesAsTheImplicitEulerDampedOscillator) {
  const Model m = free_body(3.0, Vec3(0.1, 0.2, 0.3));
  Data d = make_data(m);
  PointSpring& ps = d.point_springs[0];
  ps.active = true;
  ps.body = 1;
  ps.local_point = Vec3::Zero();
  const Vec3 x0(0, 0, 1), target(0.3, -0.1, 1.2);
  ps.target = target;
  ps.hertz = 2.0;
  ps.damping_ratio = 1.0;
  const double h = m.dt, w = 2 * M_PI * ps.hertz;
  const double a3 = 1.0 / (1.0 + h * w * (2 * ps.damping_ratio + h * w));
  Vec3 x = x0, v = Vec3::Zero();
  double max_rec = 0.0, max_cont = 0.0;
  for (int n = 1; n <= 480; ++n) {
    step(m, d);
    v = a3 * v - a3 * h * w * w * (x - target);
    x += h * v;
    const Vec3 p = d.q.head<3>();
    max_rec = std::max(max_rec, (p - x).norm());
    const double t = n * h;
    const Vec3 xc = target + (x0 - target) * (1 + w * t) * std::exp(-w * t);
    max_cont = std::max(max_cont, (p - xc).norm());
    // reported force = mass * the point's acceleration over the step
    EXPECT_NEAR((ps.force - 3.0 * (d.v.head<3>() - d.vtmp.head<3>()) / h).norm(), 0.0, 1e-9);
  }
  const double amp = (target - x0).norm();
  EXPECT_LT(max_rec, 1e-12 * 100);
  EXPECT_LT(max_cont, h * w / 4 * amp);
  EXPECT_NEAR((d.q.head<3>() - target).norm(), 0.0, 1e-4);  // settled (2 s = 25 / w)
  EXPECT_NEAR((d.q.segment<4>(3) - Eigen::Vector4d(1, 0, 0, 0)).norm(), 0.0, 1e-12);  // at the com: no turn
}

TEST(PointSpring, AppliedForceNeverExceedsMaxForce) {
  const Model m = free_body(2.0, Vec3(0.05, 0.05, 0.05));
  Data d = make_data(m);
  PointSpring& ps = d.point_springs[3];
  ps.active = true;
  ps.body = 1;
  ps.local_point = Vec3::Zero();  // at the com: the com acceleration is the force / m
  ps.target = Vec3(1.0, 0.5, 1.0);
  ps.hertz = 5.0;
  ps.damping_ratio = 0.7;
  ps.max_force = 4.0;  // the uncapped pull would be ~ m w^2 |C| ~ 2000 N
  int saturated = 0;
  double vmax = 0.0;
  for (int i = 0; i < 1200; ++i) {
    const Vec3 v0 = d.v.head<3>();
    step(m, d);
    const double f = ps.force.norm();
    EXPECT_LE(f, ps.max_force * (1 + 1e-12)) << i;
    if (f > ps.max_force * (1 - 1e-9)) ++saturated;
    // the com's acceleration is bounded by max_force / m (no other force acts)
    vmax = std::max(vmax, (d.v.head<3>() - v0).norm() / m.dt);
  }
  EXPECT_GT(saturated, 50);  // the cap really was active
  EXPECT_LE(vmax, ps.max_force / 2.0 * (1 + 1e-9));
  // (capped, the spring becomes bang-bang around the target: it overshoots and decays slowly, like
  // Box2D's mouse joint with a small max force; not checked here)
}

// The effective mass (J M^-1 J^T)^+ scales the spring with the body: a body 100 times heavier (mass and
// inertia) follows the very same trajectory, so its settling time is the same.
TEST(PointSpring, SettlingTimeIsTheSameForALightAndAHeavyBody) {
  const Vec3 I(0.02, 0.03, 0.05), lp(0.05, -0.08, 0.1), target(0.4, 0.2, 1.3);
  auto run = [&](double scale, std::vector<Vec3>& path) {
    const Model m = free_body(0.5 * scale, I * scale);
    Data d = make_data(m);
    PointSpring& ps = d.point_springs[0];
    ps.active = true;
    ps.body = 1;
    ps.local_point = lp;
    ps.target = target;
    ps.hertz = 3.0;
    ps.damping_ratio = 0.5;
    int settled = -1;
    for (int i = 0; i < 720; ++i) {
      step(m, d);
      forward_kinematics(m, d);
      const Vec3 p = world_point(d, 1, lp);
      path.push_back(p);
      // 5 %: a point off the com leaves the body spinning about it (nothing damps that spin), which
      // keeps a few mm of error (Box2D's mouse joint has the same); 5 % of 0.49 m is well above that
      if ((p - target).norm() > 0.05 * (target - Vec3(0, 0, 1) - lp).norm()) settled = -1;
      else if (settled < 0) settled = i;
    }
    return settled;
  };
  std::vector<Vec3> light, heavy;
  const int t_light = run(1.0, light), t_heavy = run(100.0, heavy);
  EXPECT_GT(t_light, 0);
  EXPECT_EQ(t_light, t_heavy);
  double dev = 0.0;
  for (size_t i = 0; i < light.size(); ++i) dev = std::max(dev, (light[i] - heavy[i]).norm());
  EXPECT_LT(dev, 1e-9);
}

// A hinged rod (length L, pivot at the top) grabbed at its tip and pulled to a point on its circle.
// The hinge lets the tip move only tangentially (K has rank 1; the spring acts through K^+). At rest the
// soft step balances gravity with an offset C = a_g / w^2, a_g = the tip's tangential acceleration due to
// gravity (m g L/2 sin(theta) L / I_pivot): the fixed point of the step, independent of dt.
TEST(PointSpring, PendulumTipIsPulledToAReachableTarget) {
  Model m;
  const double L = 1.0, mass = 1.2, rr = 0.02;
  Mat3 Ic = rod_inertia_z(mass, L, rr);
  m.add_body(make_body("rod", 0, JointType::Hinge, at({0, 0, 2}), mass, {0, 0, -L / 2}, Ic, Vec3::UnitY()));
  m.finalize();
  Data d = make_data(m);
  const double theta = 1.0;  // rad from hanging, about +Y: tip at (-L sin, 0, -L cos) from the pivot
  PointSpring& ps = d.point_springs[0];
  ps.active = true;
  ps.body = 1;
  ps.local_point = Vec3(0, 0, -L);
  ps.target = Vec3(0, 0, 2) + Vec3(-L * std::sin(theta), 0, -L * std::cos(theta));
  ps.hertz = 5.0;
  ps.damping_ratio = 1.0;
  for (int i = 0; i < 720; ++i) step(m, d);
  forward_kinematics(m, d);
  const Vec3 tip = world_point(d, 1, ps.local_point);
  const double w = 2 * M_PI * ps.hertz;
  const double I_pivot = Ic(1, 1) + mass * L * L / 4;
  const double a_g = mass * 9.81 * L / 2 * std::sin(d.q[0]) * L / I_pivot;
  EXPECT_NEAR((tip - ps.target).norm(), a_g / (w * w), 0.02 * a_g / (w * w));
  EXPECT_LT(d.q[0], theta);  // gravity holds it slightly below the target
  EXPECT_LT(std::abs(d.v[0]), 1e-6);
  // the reported force is only tangential (K^+): no pull into the hinge
  const Vec3 radial = (tip - Vec3(0, 0, 2)).normalized();
  EXPECT_LT(std::abs(ps.force.dot(radial)), 1e-9 * ps.force.norm() + 1e-12);
  EXPECT_GT(ps.force.norm(), 1.0);
}

TEST(PointSpring, InactiveSpringsChangeNothing) {
  const Model m = humanoid_on_floor();
  Data a = make_data(m), b = make_data(m);
  a.q[2] = b.q[2] = 1.0;
  b.point_springs[2].body = 3;  // configured but not active
  b.point_springs[2].target = Vec3(1, 1, 1);
  for (int i = 0; i < 200; ++i) {
    step(m, a);
    step(m, b);
  }
  EXPECT_EQ(0, std::memcmp(a.q.data(), b.q.data(), sizeof(double) * a.q.size()));
  EXPECT_EQ(b.point_springs[2].force, Vec3::Zero());
}
