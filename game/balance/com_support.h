#pragma once
// Centre of mass of the actual body and of the desired pose, and the support centres under the feet: what both
// balance controllers measure the com against.
#include <Eigen/Geometry>
#include <vector>

#include "engine/assets/character.h"
#include "engine/physics/data.h"

namespace boxing {

struct Boxer;

// Centre of mass of the actual body (position, velocity) and of the desired pose (its forward kinematics Wd / Pd),
// and the support centres: the mean of the sole centres of the feet in `feet_on` (actual, desired).
struct ComAndSupport {
  Eigen::Vector3d com_a = Eigen::Vector3d::Zero(), vcom = Eigen::Vector3d::Zero(), com_d = Eigen::Vector3d::Zero();
  Eigen::Vector3d centre_a = Eigen::Vector3d::Zero(), centre_d = Eigen::Vector3d::Zero();
  int feet = 0;  // how many feet the centres average
};

ComAndSupport com_and_support(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, const Boxer& b,
                              const std::vector<Eigen::Quaterniond>& Wd, const std::vector<Eigen::Vector3d>& Pd,
                              const int foot_bones[2], const bool feet_on[2]);

}  // namespace boxing
