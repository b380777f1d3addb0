#include "game/balance/com_support.h"

#include "engine/physics/dynamics.h"
#include "game/boxer.h"

namespace boxing {

ComAndSupport com_and_support(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, const Boxer& b,
                              const std::vector<Eigen::Quaterniond>& Wd, const std::vector<Eigen::Vector3d>& Pd,
                              const int foot_bones[2], const bool feet_on[2]) {
  ComAndSupport r;
  const double M = desc.total_mass();
  for (int i = 0; i < desc.skeleton.size(); ++i) {
    const int body = b.bodies.body[i];
    const double mi = desc.bones[i].mass;
    const Eigen::Vector3d c = d.com_world[body];
    r.com_a += mi * c;
    r.vcom += mi * eng::physics::point_velocity(d, body, c);
    r.com_d += mi * (Pd[i] + Wd[i] * desc.bones[i].com);
  }
  r.com_a /= M, r.vcom /= M, r.com_d /= M;
  for (int k = 0; k < 2; ++k) {
    if (!feet_on[k]) continue;
    const int fb = b.bodies.body[foot_bones[k]];
    r.centre_a += d.x[fb].p + d.x[fb].R * b.settings.tuning.foot.centre;
    r.centre_d += Pd[foot_bones[k]] + Wd[foot_bones[k]] * b.settings.tuning.foot.centre;
    ++r.feet;
  }
  if (r.feet > 0) r.centre_a /= r.feet, r.centre_d /= r.feet;
  return r;
}

}  // namespace boxing
