// The ring's ropes (game/ring_ropes.h): the force's closed form, and a boxer pushed at them stopped.
#include <gtest/gtest.h>

#include "game/interaction/interaction.h"
#include "game/match/match.h"
#include "game/ring_ropes.h"
#include "game/world.h"

using namespace boxing;
using Eigen::Vector3d;

namespace {
Ring test_ring() {
  Ring r;
  r.present = true;
  r.half_inside = 2.5;
  r.top_mean = 0.3;
  return r;
}
}  // namespace

TEST(RingRopes, ForceIsZeroInsideAboveAndBelowAndASpringDamperInwardPastTheLine) {
  const Ring r = test_ring();
  const RopeTuning t;
  const double m = 2.0, z = 0.3 + 0.85;  // a 2 kg point at the middle rope's height
  EXPECT_EQ(rope_force(r, t, Vector3d(2.4, 0, z), Vector3d(5, 0, 0), m), Vector3d::Zero());
  // 5 cm past the +X line moving out at 0.5 m/s: -x m (k d + c v).
  Vector3d f = rope_force(r, t, Vector3d(2.55, 0.3, z), Vector3d(0.5, 0.2, 0), m);
  EXPECT_NEAR(f.x(), -m * (t.stiffness * 0.05 + t.damping * 0.5), 1e-9);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
  EXPECT_NEAR(f.z(), 0.0, 1e-12);
  // Past the -Y line moving back in: the damping lowers the push ...
  f = rope_force(r, t, Vector3d(0, -2.6, z), Vector3d(0, 1.0, 0), m);
  EXPECT_NEAR(f.y(), m * (t.stiffness * 0.1 - t.damping * 1.0), 1e-9);
  // ... and never turns it into a pull.
  EXPECT_EQ(rope_force(r, t, Vector3d(0, -2.51, z), Vector3d(0, 5.0, 0), m), Vector3d::Zero());
  // A corner: both sides push.
  f = rope_force(r, t, Vector3d(2.6, 2.6, z), Vector3d::Zero(), m);
  EXPECT_NEAR(f.x(), -m * t.stiffness * 0.1, 1e-9);
  EXPECT_NEAR(f.y(), -m * t.stiffness * 0.1, 1e-9);
  // Below the band (a foot under the bottom rope) and above it: free. No ring: free.
  double depth = 0.0;
  EXPECT_EQ(rope_force(r, t, Vector3d(2.7, 0, 0.3 + 0.45 - t.below - 0.01), Vector3d::Zero(), m, &depth), Vector3d::Zero());
  EXPECT_NEAR(depth, 0.2, 1e-12);
  EXPECT_EQ(rope_force(r, t, Vector3d(2.7, 0, 0.3 + 1.25 + t.above + 0.01), Vector3d::Zero(), m), Vector3d::Zero());
  EXPECT_EQ(rope_force(Ring{}, t, Vector3d(2.7, 0, z), Vector3d::Zero(), m), Vector3d::Zero());
}

TEST(RingRopes, GeomSupportIsTheFarthestPointAlongTheDirection) {
  eng::physics::Shape cap;
  cap.type = eng::physics::ShapeType::Capsule;
  cap.radius = 0.05, cap.half_length = 0.2;
  eng::physics::Pose x;
  x.p = Vector3d(1, 0, 1);
  x.R = Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitY()).toRotationMatrix();  // the capsule's axis along +-X
  EXPECT_NEAR((geom_support(cap, x, Vector3d::UnitX()) - Vector3d(1.25, 0, 1)).norm(), 0.0, 1e-12);
  eng::physics::Shape box;
  box.type = eng::physics::ShapeType::Box;
  box.half_extents = Vector3d(0.1, 0.2, 0.3);
  EXPECT_NEAR((geom_support(box, eng::physics::Pose{}, Vector3d(0, -1, 0)).y()), -0.2, 1e-12);
}

namespace {
// Boxer 0 of the match pushed toward the -X ropes at the chest by `force` N for `seconds`:
// the deepest its pelvis went past the rope line (m).
double deepest_past_ropes(bool ropes, double force, double seconds) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.scenario = "match";
  o.seed = 2;
  o.player = 0;  // the player's boxer: no AI footwork walking it back against the push
  auto made = make_world(o);
  EXPECT_TRUE(made) << made.error();
  if (!made) return 1e9;
  World& w = **made;
  if (!ropes) w.arena.ring.present = false;  // (the ropes only: the ring's crates and posts stay)
  const int chest = w.boxers[0].bodies.body[w.boxer_desc.skeleton.find("chest")];
  const double line = -2.5;  // the -X ropes (make_ring: half_inside 2.5 m)
  double deepest = -1e9;
  for (int i = 0; i < static_cast<int>(seconds * 240); ++i) {
    w.interaction->pushes.push_back({chest, Vector3d(-force, 0, 0), w.data.time + 0.5 / 240.0});
    step_world(w);
    deepest = std::max(deepest, line - w.data.x[w.boxers[0].bodies.body[0]].p.x());
  }
  return deepest;
}
}  // namespace

TEST(RingRopes, ABoxerPushedIntoTheRopesIsStoppedAtThem) {
  // 450 N on the chest for 5 s: the boxer is driven 1.1 m to the ropes (stepping or falling; 250 N no longer carried
  // it there once its balance steps re-formed the stance after each catch); they hold its pelvis within 0.3 m of
  // their line, where without them it goes on over the apron.
  const double with = deepest_past_ropes(true, 450.0, 5.0);
  EXPECT_LT(with, 0.3);
  const double without = deepest_past_ropes(false, 450.0, 5.0);
  EXPECT_GT(without, with + 0.3);
  std::printf("pelvis past the rope line: %.3f m with the ropes, %.3f m without\n", with, without);
}
