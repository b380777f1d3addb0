// Contact events (begin / end touch, hit events) filled by the solver, per geom pair.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/physics_test_util.h"

using namespace eng::physics;
using namespace eng::physics::test;

namespace {
int add_floor(Model& m) {
  Geom g;
  g.body = 0;
  g.shape.type = ShapeType::Plane;
  return m.add_geom(g);
}
}  // namespace

// Semi-implicit Euler from rest covers g dt^2 n(n+1)/2 in n steps. Dropping the ball from that height
// (+ 0.1 um) makes it arrive one step with a gap of 0.1 um: the speculative contact then takes the
// whole stop in one step (with a larger gap the stop is split: this step's impulse only brings the ball
// onto the surface, the rest comes the next step), so the hit's impulse is m v_free, checkable tightly.
TEST(ContactEvents, DroppedBallGivesOneBeginAndOneHitWithTheArrivalSpeed) {
  Model m;
  const int floor = add_floor(m);
  const double r = 0.1, mass = 2.0, g = 9.81;
  const int N = 76;
  const double h0 = g * m.dt * m.dt * N * (N + 1) / 2 + 1e-7;  // ~0.498 m
  const int ball = add_free_sphere(m, {0, 0, r + h0}, r, mass);
  m.finalize();
  Data d = make_data(m);
  int begins = 0, hits = 0, ends = 0;
  double v_pre = 0.0;
  for (int i = 0; i < 480; ++i) {
    const double vz = d.v[2];  // the ball's velocity at the start of this step
    step(m, d);
    ends += static_cast<int>(d.contact_end.size());
    if (!d.contact_begin.empty()) {
      ++begins;
      ASSERT_EQ(d.contact_begin.size(), 1u);
      EXPECT_EQ(i, N) << "the touch begins on step N + 1";
      const ContactEvent& e = d.contact_begin[0];
      EXPECT_EQ(e.geom_a, floor);
      EXPECT_EQ(e.body_a, 0);
      EXPECT_EQ(e.body_b, ball);
      ASSERT_EQ(d.hit_events.size(), 1u);
      ++hits;
      const HitEvent& h = d.hit_events[0];
      v_pre = -vz;
      EXPECT_EQ(h.body_b, ball);
      EXPECT_NEAR(h.normal.z(), 1.0, 1e-12);
      EXPECT_NEAR(h.point.z(), 0.0, 1e-6);
      // approach speed = the simulated arrival speed (exact), ~ sqrt(2 g h) within one step's g dt
      EXPECT_NEAR(h.approach_speed, v_pre, 1e-12);
      EXPECT_NEAR(h.approach_speed, std::sqrt(2 * g * h0), g * m.dt);
      // impulse = m v_free (v_free = v_pre + g dt: this step's gravity is stopped too), minus m gap/dt
      EXPECT_NEAR(h.impulse, mass * (v_pre + g * m.dt), mass * 1e-7 / m.dt + 1e-9);
      EXPECT_NEAR(h.impulse, mass * std::sqrt(2 * g * h0), mass * 1.5 * g * m.dt);
    } else {
      EXPECT_TRUE(d.hit_events.empty());
    }
  }
  EXPECT_EQ(begins, 1);  // resting afterwards: no repeated begins
  EXPECT_EQ(hits, 1);
  EXPECT_EQ(ends, 0);
  EXPECT_GT(v_pre, 3.0);
}

TEST(ContactEvents, RestingBoxBeginsOnceAndLiftingItEnds) {
  Model m;
  const int floor = add_floor(m);
  const Vec3 he(0.2, 0.15, 0.1);
  const double mass = 5.0;
  const int box = m.add_body(make_body("box", 0, JointType::Free, at({0, 0, he.z()}), mass, Vec3::Zero(),
                                       box_inertia(mass, he)));
  Geom g;
  g.body = box;
  g.shape.type = ShapeType::Box;
  g.shape.half_extents = he;
  const int box_geom = m.add_geom(g);
  m.finalize();
  Data d = make_data(m);
  // placed exactly on the floor at rest: touching from the first step, approaching at 0 m/s: no hit
  step(m, d);
  ASSERT_EQ(d.contact_begin.size(), 1u);
  EXPECT_EQ(d.contact_begin[0].geom_a, floor);
  EXPECT_EQ(d.contact_begin[0].geom_b, box_geom);
  EXPECT_TRUE(d.hit_events.empty());
  for (int i = 0; i < 480; ++i) {  // 2 s resting: the pair stays touching
    step(m, d);
    EXPECT_TRUE(d.contact_begin.empty()) << i;
    EXPECT_TRUE(d.contact_end.empty()) << i;
  }
  // lift it: 3 m g upwards at the com for 0.3 s
  d.applied_force[box] = Vec3(0, 0, 3 * mass * 9.81);
  int ends = 0, end_step = -1;
  for (int i = 0; i < 72; ++i) {
    step(m, d);
    EXPECT_TRUE(d.contact_begin.empty());
    if (!d.contact_end.empty()) {
      ++ends;
      end_step = i;
      ASSERT_EQ(d.contact_end.size(), 1u);
      EXPECT_EQ(d.contact_end[0].geom_a, floor);
      EXPECT_EQ(d.contact_end[0].geom_b, box_geom);
      EXPECT_EQ(d.contact_end[0].body_b, box);
    }
  }
  EXPECT_EQ(ends, 1);
  EXPECT_LT(end_step, 10);  // accelerating upwards at 2 g: the floor lets go in the first steps
  EXPECT_GT(d.q[2], he.z() + 0.1);
}

// The approach speed is the relative normal speed of the two bodies at the contact point before the
// solve: n . (v_a - v_b) with n from a to b, computed here from the body velocities (not from J).
TEST(ContactEvents, ApproachSpeedOfTwoMovingBodiesIsTheirRelativeNormalSpeed) {
  Model m;
  m.gravity.setZero();
  const double r = 0.1;
  const int a = add_free_sphere(m, {-0.3, 0.0, 1.0}, r, 1.0);
  const int b = add_free_sphere(m, {0.3, 0.08, 1.0}, r, 3.0);
  m.finalize();
  Data d = make_data(m);
  const Vec3 va(1.2, 0.3, 0.0), vb(-0.5, 0.1, 0.2);
  d.v.segment<3>(m.bodies[a].v_index) = va;
  d.v.segment<3>(m.bodies[b].v_index) = vb;
  int hits = 0;
  for (int i = 0; i < 240 && hits == 0; ++i) {
    const Vec3 va0 = d.v.segment<3>(m.bodies[a].v_index), vb0 = d.v.segment<3>(m.bodies[b].v_index);
    step(m, d);
    if (d.hit_events.empty()) continue;
    ++hits;
    ASSERT_EQ(d.hit_events.size(), 1u);
    const HitEvent& h = d.hit_events[0];
    EXPECT_EQ(h.body_a, a);
    EXPECT_EQ(h.body_b, b);
    // spheres do not spin: every point moves with the body
    EXPECT_NEAR(h.approach_speed, h.normal.dot(va0 - vb0), 1e-12);
    EXPECT_EQ(va0, va);  // nothing touched them before: still the initial velocities
    EXPECT_GT(h.approach_speed, 1.0);
    EXPECT_NEAR(h.normal.norm(), 1.0, 1e-12);
    EXPECT_GT(h.normal.y(), 0.05);  // oblique: the normal is not the x axis
    EXPECT_GT(h.impulse, 0.0);
  }
  EXPECT_EQ(hits, 1);
}

TEST(ContactEvents, HitThresholdIsSettable) {
  Model m;
  add_floor(m);
  add_free_sphere(m, {0, 0, 0.1 + 0.05}, 0.1, 1.0);  // lands at ~1 m/s
  m.hit_event_threshold = 5.0;
  m.finalize();
  Data d = make_data(m);
  int begins = 0, hits = 0;
  for (int i = 0; i < 120; ++i) {
    step(m, d);
    begins += static_cast<int>(d.contact_begin.size());
    hits += static_cast<int>(d.hit_events.size());
  }
  EXPECT_EQ(begins, 1);
  EXPECT_EQ(hits, 0);
}
