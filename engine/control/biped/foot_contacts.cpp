#include "engine/control/biped/foot_contacts.h"

#include <cmath>

namespace eng::control {

void find_foot_contacts(const std::vector<physics::Contact>& contacts, const std::vector<int>& body_of_bone,
                        const BipedBones& bones, const FootContactThresholds& t, FootContacts& out) {
  int foot_body[2], shank_body[2];
  for (int k = 0; k < 2; ++k) {
    foot_body[k] = body_of_bone[bones.leg[k].foot];
    shank_body[k] = body_of_bone[bones.leg[k].shank];
    out.support[k] = out.on_ground[k] = out.on_top[k] = false;
    out.normal_force[k] = 0.0;
    out.ground_points[k].clear();
  }
  out.other_link_on_ground = false;
  for (const auto& c : contacts) {
    if (c.point.depth >= -t.support)
      for (int k = 0; k < 2; ++k) {
        const int fb = foot_body[k];
        if (c.body_a == fb || c.body_b == fb) out.support[k] = true;
        if (c.body_b == fb) out.normal_force[k] += c.force.z();
        if (c.body_a == fb) out.normal_force[k] -= c.force.z();
      }
    const int other = c.body_a == 0 ? c.body_b : (c.body_b == 0 ? c.body_a : -1);  // the link on the ground
    if (other < 0) continue;
    if (c.point.depth >= -t.load)
      for (int k = 0; k < 2; ++k)
        if (other == foot_body[k]) {
          out.on_ground[k] = true;
          out.on_top[k] = out.on_top[k] || std::abs(c.point.normal.z()) >= t.top_normal_z;
          out.ground_points[k].push_back(c.point.position.head<2>());
        }
    if (c.point.depth >= -t.fallen && other != foot_body[0] && other != foot_body[1] && other != shank_body[0] &&
        other != shank_body[1])
      for (int body : body_of_bone)
        if (body == other) out.other_link_on_ground = true;
  }
}

}  // namespace eng::control
