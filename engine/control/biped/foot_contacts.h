#pragma once
// FOOT CONTACTS, worked out once per contact set (after each physics step, and once at the start) and read by every
// consumer of the tick: the servo's support legs, the balance QP's load-bearing feet, the lift-off gate's stance
// contacts and the fall detection. Each consumer is tuned with its own "touching" depth, so the struct keeps one
// named flag per purpose, each with its threshold; docs/decisions/foot-contact-thresholds.md says what unifying
// them would change. Contact depth: > 0 penetrating, < 0 a speculative gap (m).
#include <Eigen/Core>
#include <vector>

#include "engine/control/biped/biped_bones.h"
#include "engine/physics/data.h"

namespace eng::control {

struct FootContactThresholds {
  double support = 0.02;  // m gap: the leg is on the servo's support path (any contact of the foot, with anything;
                          // a wide margin against the support switching on and off as the foot hovers)
  double load = 0.002;    // m gap: the foot carries load in the balance QP's plan and is the lift-off gate's stance
                          // (ground contacts only: static body 0)
  double fallen = 0.005;  // m gap: a link other than the feet and shanks touching the ground (fall detection)
  double top_normal_z = 0.7;  // a ground contact whose normal's z is at least this is on a top, not a crate's side
};

// Ground contacts a foot's list holds without growing (its capacity from construction): a sole over four crate tops
// at the narrowphase's 4 points a pair is 16; twice that. A list growing past its warm-up size mid-recovery would
// allocate in the world's step (tests/game/world_alloc_test.cpp).
inline constexpr int kFootContactCapacity = 32;

struct FootContacts {
  FootContacts() {
    for (std::vector<Eigen::Vector2d>& p : ground_points) p.reserve(kFootContactCapacity);
  }
  bool support[2] = {false, false};    // a contact of the foot within `support`, with any other body
  double normal_force[2] = {0.0, 0.0};  // world z force on the foot over those contacts, last solve (N)
  bool on_ground[2] = {false, false};  // a ground contact of the foot within `load`
  std::vector<Eigen::Vector2d> ground_points[2];  // those contacts' points (floor x, y), in contact order
  // one of them on a top (its normal up; top_normal_z): a swing foot landing, not a toe brushing a crate's side
  bool on_top[2] = {false, false};
  bool other_link_on_ground = false;   // a link other than feet and shanks on the ground within `fallen`
};

// Fills `out` (capacity kept) from the contacts: body_of_bone maps the skeleton's bones to physics bodies.
void find_foot_contacts(const std::vector<physics::Contact>& contacts, const std::vector<int>& body_of_bone,
                        const BipedBones& bones, const FootContactThresholds& t, FootContacts& out);

}  // namespace eng::control
