#pragma once
// The boxer's balance controller: ONE interface, two implementations, chosen at setup (--balance):
//   PdBalance (pd_balance.h)  the servo's springs + a PD shift of the desired root + the root spring
//   QpBalance (qp_balance.h)  the whole-body balance QP, the root spring as its assist
// A std::variant: one std::visit per boxer per tick, no virtual call per body. Each implementation provides
//   adjust_desired(c, tick)  before the legs are fitted to the actual ankles (the desired pose may move)
//   actuate(c, tick)         after the servo's targets: torques / spring references into the physics Data
//   stance_rise / stance_drop (placement of the clip on the crates), plans_steps, model_springs (setup).
#include <Eigen/Geometry>
#include <variant>
#include <vector>

#include "engine/control/servo/wrench.h"
#include "game/balance/pd_balance.h"
#include "game/balance/qp_balance.h"

namespace eng::assets {
struct CharacterDesc;
}

namespace boxing {

using BalanceController = std::variant<PdBalance, QpBalance>;

// What a balance controller reads and writes in one tick.
struct BalanceTick {
  const eng::physics::Model& m;
  eng::physics::Data& d;
  const eng::assets::CharacterDesc& desc;
  Boxer& b;
  const bool* loaded;  // [2] the servo's support feet this tick (contacts within 2 cm, not swinging)
  double dt;
  const std::vector<Eigen::Quaterniond>* Wd = nullptr;  // adjust_desired: the desired pose's forward kinematics
  const std::vector<Eigen::Vector3d>* Pd = nullptr;
  double heading = 0.0;                 // actuate: the servo's heading (person space: low-passed)
  eng::control::Wrench help{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};  // actuate: control_step's root help
};

}  // namespace boxing
