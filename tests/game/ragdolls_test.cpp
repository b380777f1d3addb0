// The ragdolls scenario end to end (no rendering): limp humanoids and loose crates dropped on the arena tumble,
// collide and come to rest: nothing tunnels below the floor or into a crate, nothing blows up, all of it settles.
#include <gtest/gtest.h>

#include "engine/physics/dynamics.h"
#include "game/cli.h"
#include "game/world.h"

namespace {

double max_body_speed(const boxing::World& w) {
  double v = 0;
  for (size_t b = 1; b < w.data.v_body.size(); ++b) {
    const auto& s = w.data.v_body[b];
    const Eigen::Vector3d lin = s.tail<3>() + s.head<3>().cross(w.data.com_world[b]);
    v = std::max(v, lin.norm());
  }
  return v;
}

}  // namespace

TEST(RagdollsScenario, BodiesTumbleCollideAndComeToRestAboveTheFloor) {
  auto o = boxing::parse_cli({"--scenario", "ragdolls", "--seed", "2"});
  ASSERT_TRUE(o.ok());
  auto w = boxing::make_world(*o);
  ASSERT_TRUE(w.ok()) << w.error();
  boxing::World& world = **w;
  double peak = 0;
  const int steps = int(8.0 / boxing::kPhysicsDt);
  for (int i = 0; i < steps; ++i) {
    boxing::step_world(world);
    peak = std::max(peak, max_body_speed(world));
  }
  eng::physics::forward_kinematics(world.model, world.data);
  EXPECT_GT(peak, 3.0) << "they fell and tumbled";
  EXPECT_LT(peak, 12.0) << "free fall from < 3 m stays below ~8 m/s; more means something exploded";
  EXPECT_LT(max_body_speed(world), 0.05) << "everything is at rest after 8 s";
  for (size_t b = 1; b < world.data.x.size(); ++b) {
    ASSERT_TRUE(world.data.x[b].p.allFinite());
    EXPECT_GT(world.data.com_world[b].z(), 0.0) << world.model.bodies[b].name << " is above the floor";
    // Not sunk inside a crate: a body's com is never deeper than 5 cm below the top under it.
    const double top = world.arena.top_at(world.data.com_world[b].x(), world.data.com_world[b].y());
    EXPECT_GT(world.data.com_world[b].z(), top - 0.05) << world.model.bodies[b].name << " sank into a crate";
  }
}
