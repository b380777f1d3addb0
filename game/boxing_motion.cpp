#include "game/boxing_motion.h"

namespace boxing {

eng::anim::MotionGraphOptions boxing_graph_options(const eng::anim::Skeleton& skeleton) {
  eng::anim::MotionGraphOptions o;
  const struct {
    const char* bone;
    Eigen::Vector3d offset;  // bone frame, m
  } points[] = {
      {"glove_l", {0, 0, -0.08}},    // glove centre, below the wrist joint
      {"glove_r", {0, 0, -0.08}},
      {"foot_l", {0.14, 0, -0.08}},  // toe, ahead of and below the ankle
      {"foot_r", {0.14, 0, -0.08}},
      {"head", {0, 0, 0.2}},         // top of the head
  };
  for (const auto& p : points)
    if (skeleton.find(p.bone) >= 0) o.feature_points.push_back({p.bone, p.offset});
  o.entry_only_tags = {"fall", "down", "getup", "reaction"};
  o.no_source_tags = {"fall", "down"};
  o.forced_entry_tags = {"fall", "reaction"};
  o.home_clip = kGuardClip;
  return o;
}

}  // namespace boxing
