#pragma once
// Building a world's boxers, for the scenarios (game/scenarios/): internal to the game.
#include <Eigen/Core>

#include "game/arena.h"

namespace boxing {

struct World;
struct Boxer;

// Adds a boxer's bodies to the model (before Model::finalize) with its servo, balance controller and pose source.
void add_boxer(World& w, int index, const Eigen::Vector3f& color, bool limp, const Stance& stance);
// Puts a boxer in its first desired pose, placed on its stance (after make_data).
void place_boxer(World& w, Boxer& b);

}  // namespace boxing
