#pragma once
// Building a world's boxers, for the scenarios (game/scenarios/): internal to the game.
#include <Eigen/Core>
#include <cstdint>

#include "game/arena.h"

namespace boxing {

struct World;
struct Boxer;

inline constexpr uint32_t kStaticGroup = 1u;  // the floor's and crates' collision group (a boxer's: 2u << index)

// Adds a boxer's bodies to the model (before Model::finalize) with its servo, balance controller and pose source.
void add_boxer(World& w, int index, const Eigen::Vector3f& color, bool limp, const Stance& stance);
// (Re)builds a boxer's control from its settings (servo space, gains, balance_qp, root spring): the servo's joint
// gains and the model's implicit springs, the balance controller's kind and prices. At setup, and when the panel or
// an input event changes a setting mid-run.
void configure_boxer_control(World& w, Boxer& b);
// Puts a boxer in its first desired pose, placed on its stance (after make_data).
void place_boxer(World& w, Boxer& b);

}  // namespace boxing
