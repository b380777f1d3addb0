#pragma once
// The joint strengths an adult man has, per joint of the boxer (named by the bone the joint moves): the torque a joint
// can give at most (N m, the norm of a ball joint's torque). Issue 63's figures for the legs and arms ("for an adult
// male, roughly hip extension 250 N m, knee 250, ankle 150, shoulder 100, elbow 70"); the spine's and the neck's are
// our estimates inside the ranges the isometric-strength literature reports for adult men (trunk extension 200-300
// N m, neck extension 30-50), not one source's figures. The gloves are welded to the forearms: no wrist joint.
// Today the get-ups' report measures against it (getup_metrics.h); the balance QP still guards every joint at one
// 500 N m (BalanceQpTuning::joint_torque_limit). docs/decisions/getup-measures.md.
#include <string_view>

namespace boxing {

struct JointStrength {
  std::string_view bone;  // the bone whose parent joint it is
  std::string_view joint;
  double max_torque;      // N m
};

inline constexpr JointStrength kPersonStrength[] = {
    {"abdomen", "lower spine", 250.0},  {"chest", "upper spine", 250.0},  {"head", "neck", 40.0},
    {"upper_arm_l", "shoulder", 100.0}, {"upper_arm_r", "shoulder", 100.0}, {"forearm_l", "elbow", 70.0},
    {"forearm_r", "elbow", 70.0},
    {"thigh_l", "hip", 250.0},          {"thigh_r", "hip", 250.0},        {"shank_l", "knee", 250.0},
    {"shank_r", "knee", 250.0},         {"foot_l", "ankle", 150.0},       {"foot_r", "ankle", 150.0},
};

// The strength of the joint that moves `bone` (N m); 0 for a bone the table does not name (the root).
inline double person_strength(std::string_view bone) {
  for (const JointStrength& j : kPersonStrength)
    if (j.bone == bone) return j.max_torque;
  return 0.0;
}

}  // namespace boxing
