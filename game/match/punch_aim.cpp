#include "game/match/punch_aim.h"

#include <algorithm>
#include <cmath>

#include "engine/control/ik/two_bone_ik.h"
#include "engine/control/servo/world_pose.h"

namespace boxing {

namespace {
double smooth(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}
}  // namespace

double aim_weight(double t, double impact, double duration) {
  if (impact <= 0.0 || t < 0.0) return 0.0;
  // Full aim from 3/4 of the way to the impact frame: the clip's glove slows into its full extension there, the aim
  // keeps it going through the target.
  if (t <= impact) return smooth(t / (0.75 * impact));
  const double back = std::max(1e-3, 0.6 * (duration - impact));
  return 1.0 - smooth((t - impact) / back);
}

double strike_weight(double t, double impact, double follow) {
  if (impact <= 0.0 || t < 0.0 || t > impact + follow) return 0.0;
  return smooth((t - 0.25 * impact) / (0.35 * impact));
}

void apply_punch_aim(const eng::assets::CharacterDesc& desc, const PunchAim& aim, eng::anim::Pose& pose,
                     std::vector<Eigen::Quaterniond>& W, std::vector<Eigen::Vector3d>& P) {
  if (!aim.active || aim.weight <= 0.0 || aim.glove <= 0) return;
  const auto& skel = desc.skeleton;
  const int forearm = skel.parent[aim.glove];
  const int upper = forearm > 0 ? skel.parent[forearm] : -1;
  if (upper <= 0) return;
  const auto& elbow = desc.bones[forearm];
  // The elbow flexes toward the middle of its range (content: [0, 2.6] rad about its axis).
  eng::control::TwoBoneChain arm{upper, forearm, aim.glove, elbow.axis, elbow.lower + elbow.upper >= 0.0 ? 1.0 : -1.0};
  eng::control::pose_fk(skel, pose, W, P);
  // The glove's centre sits at its com from the wrist joint: the wrist goes where it puts the centre on the target.
  const Eigen::Vector3d glove_centre = W[aim.glove] * desc.bones[aim.glove].com;
  const Eigen::Vector3d wrist_goal = aim.target - glove_centre;
  const Eigen::Vector3d wrist = P[aim.glove] + aim.weight * (wrist_goal - P[aim.glove]);
  eng::control::solve_two_bone(skel, arm, W, P, wrist, pose);
}

}  // namespace boxing
