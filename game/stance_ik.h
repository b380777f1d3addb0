#pragma once
// Forwarding header: the leg fitting moved to engine/control/biped/leg_ik.h and pose_fk to
// engine/control/servo/world_pose.h. Kept for game/scene_view.cpp (owned by the HUD work); delete once nothing
// includes it.
#include "engine/control/biped/leg_ik.h"
#include "engine/control/servo/world_pose.h"

namespace boxing {
using eng::control::pose_fk;
}  // namespace boxing
