#pragma once
// Where a boxer's desired motion comes from: a looping keyframed clip (guard, for the stand and push scenarios)
// or a random walk of the motion graph (graph-walk, match). Either way the result is a PoseSample in the clip's
// own floor frame (authored facing +X at the origin); the boxer places it on its stance.
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/anim/clip.h"
#include "engine/anim/motion_graph.h"

namespace boxing {

class PoseSource {
 public:
  static PoseSource looping_clip(const eng::anim::Clip& clip);
  static PoseSource graph_walk(const eng::anim::MotionGraph& graph, uint64_t seed);
  // A drill: guard (looping), and `clip` played once from guard every `every` seconds, then guard again. The clips
  // start and end in guard's first key, so the seams are the clips' own; the root carries on from where the clip
  // ended (a step moves the drill with it).
  static PoseSource drill(const eng::anim::Clip& guard, const eng::anim::Clip& clip, double every);

  // The desired pose at the current time, then advances by dt. Keeps a graph walk near its start: when the root
  // (plus `anchor`, the offset at which the boxer places the walk, in the clip frame) has drifted more than
  // `leash` metres along its heading, it asks the graph for a step back / forward.
  eng::anim::PoseSample tick(double dt, const Eigen::Vector2d& anchor = Eigen::Vector2d::Zero());
  // The source's pose (clip floor frame, like tick's) `ahead` seconds after the last tick, staying in the clip now
  // playing (a walk's next transition is not known yet). preview(0) is the last tick's pose.
  eng::anim::Pose preview(double ahead) const;
  const std::string& current_clip() const;
  bool is_walk() const { return walker_ != nullptr; }
  eng::anim::GraphWalker* walker() { return walker_.get(); }
  // Seconds spent per clip so far.
  const std::map<std::string, double>& clip_time() const { return clip_time_; }
  // Every clip change: (time it started, clip), in order; the report's clip timeline.
  const std::vector<std::pair<double, std::string>>& timeline() const { return timeline_; }

 private:
  const eng::anim::Clip* clip_ = nullptr;
  const eng::anim::Clip* drill_ = nullptr;  // drill: the clip played every drill_every_ seconds
  double drill_every_ = 0.0, drill_start_ = -1.0, drill_next_ = 0.0;
  Eigen::Vector3d drill_offset_ = Eigen::Vector3d::Zero();
  double t_ = 0.0;
  std::unique_ptr<eng::anim::GraphWalker> walker_;
  std::map<std::string, double> clip_time_;
  std::vector<std::pair<double, std::string>> timeline_;
  double now_ = 0.0;
  double last_dt_ = 0.0;
  double leash_ = 0.25;
};

}  // namespace boxing
