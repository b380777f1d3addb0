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
  // The same into *out, reusing its storage (the per-tick call: no allocation once warm).
  void tick(double dt, const Eigen::Vector2d& anchor, eng::anim::PoseSample* out);
  // The source's pose (clip floor frame, like tick's) `ahead` seconds after the last tick, staying in the clip now
  // playing (a walk's next transition is not known yet). preview(0) is the last tick's pose.
  // The pose is the source's own: valid until the next preview or tick.
  const eng::anim::Pose& preview(double ahead) const;
  const std::string& current_clip() const;
  bool is_walk() const { return walker_ != nullptr; }
  // How far (m, along the heading) a walk may drift from its spot before it steps back toward it (default 0.25).
  void set_leash(double metres) { leash_ = metres; }
  eng::anim::GraphWalker* walker() { return walker_.get(); }
  const eng::anim::GraphWalker* walker() const { return walker_.get(); }
  // Seconds spent per clip so far (the clips played, by name; built for the report).
  std::map<std::string, double> clip_time() const;
  // Every clip change: (time it started, clip), in order; the report's clip timeline.
  std::vector<std::pair<double, std::string>> timeline() const;

 private:
  const eng::anim::Clip* clip_ = nullptr;
  const eng::anim::Clip* drill_ = nullptr;  // drill: the clip played every drill_every_ seconds
  double drill_every_ = 0.0, drill_start_ = -1.0, drill_next_ = 0.0;
  Eigen::Vector3d drill_offset_ = Eigen::Vector3d::Zero();
  double t_ = 0.0;
  std::unique_ptr<eng::anim::GraphWalker> walker_;
  const eng::anim::MotionGraph* graph_ = nullptr;
  // Per clip slot (the graph's clip index; else 0 = the looping clip, 1 = the drill's): seconds played and whether
  // it played at all; the timeline as (start time, slot), capacity kept for hours of clip changes (no allocation per
  // tick).
  int slot() const;
  const std::string& slot_name(int slot) const;
  void init_slots(size_t n);
  std::vector<double> seconds_;
  std::vector<char> played_;
  std::vector<std::pair<double, int>> timeline_;
  double now_ = 0.0;
  double last_dt_ = 0.0;
  double leash_ = 0.25;
  bool leashed_ = false;       // the leash's repeated step is asked for, since leashed_at_ (s)
  double leashed_at_ = 0.0;
  double leash_rest_until_ = 0.0;  // s, a leash given up (its steps got nowhere) rests until then
  mutable eng::anim::Pose preview_;
};

}  // namespace boxing
