#pragma once
// The fighter's view of the fight: where the other boxer is (reach_distance, in_range), which way a boxer faces, the
// view the AI decides from (FighterView, fighter_ai.h) and the aim of a punch now playing (punch_aim.h).
#include <Eigen/Core>

#include "game/match/fighter_ai.h"

namespace eng::anim {
struct Clip;
}

namespace boxing {

struct World;
struct Boxer;

// The boxer's facing in the world (the pelvis's forward axis, +X of the bone, on the floor; unit).
Eigen::Vector2d facing(const World& w, const Boxer& b);
// The other boxer's head from boxer k's chest, on the floor (m): the AI's range and the referee's "apart".
double reach_distance(const World& w, int k);
// Boxer k's straight punch reaches the other's head (the AI's "in range"; both out of it is the referee's "apart").
bool in_range(const World& w, int k);
// Boxer k's aim for the punch clip c playing now (BoxerControl::aim): on while it stands and throws an aimed punch.
void aim_punch(World& w, int k, const eng::anim::Clip& c, bool standing);
// What boxer k's AI sees this tick (its clip c playing; standing: in guard or stunned).
FighterView fighter_view(const World& w, int k, const eng::anim::Clip& c, bool standing);

}  // namespace boxing
