#include "game/pose_source.h"

#include <cmath>

#include "game/boxing_motion.h"

namespace boxing {

PoseSource PoseSource::looping_clip(const eng::anim::Clip& clip) {
  PoseSource s;
  s.clip_ = &clip;
  s.init_slots(2);
  return s;
}

PoseSource PoseSource::graph_walk(const eng::anim::MotionGraph& graph, uint64_t seed) {
  PoseSource s;
  s.walker_ = std::make_unique<eng::anim::GraphWalker>(graph, seed, kGuardClip);
  // The clips face the opponent; the yaw the graph's transitions accumulate (a random walk) is steered away, as a
  // player or an AI keeps a boxer facing: without it a walk's desired heading wandered 40 deg in 100 s and the
  // planted feet, which cannot follow it without steps, pivoted after it and slid off their crates.
  s.walker_->heading_hold = kHeadingHold;
  s.graph_ = &graph;
  s.init_slots(graph.clips.size());
  return s;
}

void PoseSource::init_slots(size_t n) {
  seconds_.assign(n, 0.0);
  played_.assign(n, 0);
  timeline_.reserve(1 << 14);
}

int PoseSource::slot() const {
  if (walker_) return walker_->current_clip_index();
  return drill_ && drill_start_ >= 0.0 ? 1 : 0;
}

const std::string& PoseSource::slot_name(int s) const {
  if (graph_) return graph_->clips[s].name;
  return s == 1 ? drill_->name : clip_->name;
}

std::map<std::string, double> PoseSource::clip_time() const {
  std::map<std::string, double> out;
  for (size_t s = 0; s < seconds_.size(); ++s)
    if (played_[s]) out[slot_name(static_cast<int>(s))] = seconds_[s];
  return out;
}

std::vector<std::pair<double, std::string>> PoseSource::timeline() const {
  std::vector<std::pair<double, std::string>> out;
  for (const auto& [t, s] : timeline_) out.emplace_back(t, slot_name(s));
  return out;
}

PoseSource PoseSource::drill(const eng::anim::Clip& guard, const eng::anim::Clip& clip, double every) {
  PoseSource s;
  s.clip_ = &guard;
  s.drill_ = &clip;
  s.drill_every_ = every;
  s.drill_next_ = every;
  s.init_slots(2);
  return s;
}

const std::string& PoseSource::current_clip() const {
  if (walker_) return walker_->current_clip();
  return drill_ && drill_start_ >= 0.0 ? drill_->name : clip_->name;
}

const eng::anim::Pose& PoseSource::preview(double ahead) const {
  if (walker_) return walker_->preview(ahead);
  const double t = now_ - last_dt_ + ahead;  // tick() sampled the clips at now_ - dt
  if (drill_ && drill_start_ >= 0.0)
    eng::anim::sample_clip_pose(*drill_, std::min(t - drill_start_, drill_->duration()), &preview_);
  else  // looping guard (t_ has advanced past the sampled time already)
    eng::anim::sample_clip_pose(*clip_, t_ - last_dt_ + ahead, &preview_);
  preview_.root_position += drill_offset_;
  return preview_;
}

eng::anim::PoseSample PoseSource::tick(double dt, const Eigen::Vector2d& anchor) {
  eng::anim::PoseSample s;
  tick(dt, anchor, &s);
  return s;
}

void PoseSource::tick(double dt, const Eigen::Vector2d& anchor, eng::anim::PoseSample* out) {
  eng::anim::PoseSample& s = *out;
  last_dt_ = dt;
  const int now_slot = slot();
  seconds_[now_slot] += dt;
  played_[now_slot] = 1;
  if (timeline_.empty() || slot_name(timeline_.back().second) != current_clip()) timeline_.emplace_back(now_, now_slot);
  now_ += dt;
  if (drill_) {
    // Guard until drill_next_, then the clip from its start (the next play drill_every_ later, or 0.5 s after the clip
    // ends if it is longer); back to guard from its start, the root carrying on from where the clip left it.
    const double t = now_ - dt;
    if (drill_start_ < 0.0 && t >= drill_next_ - 1e-9) {
      drill_start_ = t;
      drill_next_ = t + std::max(drill_every_, drill_->duration() + 0.5);
      drill_offset_ += eng::anim::sample_clip_pose(*clip_, t_).root_position - drill_->keys.front().root_position;
      drill_offset_.z() = 0.0;
    }
    if (drill_start_ >= 0.0 && t - drill_start_ > drill_->duration()) {
      drill_offset_ += drill_->keys.back().root_position - clip_->keys.front().root_position;
      drill_offset_.z() = 0.0;
      drill_start_ = -1.0;
      t_ = 0.0;
    }
    if (drill_start_ >= 0.0)
      eng::anim::sample_clip(*drill_, t - drill_start_, &s);
    else
      eng::anim::sample_clip(*clip_, t_, &s);
    if (drill_start_ < 0.0) t_ += dt;
    s.pose.root_position += drill_offset_;
    return;
  }
  if (!walker_) {
    eng::anim::sample_clip(*clip_, t_, &s);
    t_ += dt;
    return;
  }
  walker_->tick(dt, &s);
  // The crates are a small stage: a walk that has wandered off its spot steps back toward it (the way a player
  // or an AI keeps a boxer in range), using the graph's own footwork clips.
  // Only the drift along the facing direction can be undone by stepping forward or back.
  const Eigen::Vector2d drift = s.pose.root_position.head<2>() + anchor;
  const Eigen::Vector3d fwd3 = s.pose.rotation[0] * Eigen::Vector3d::UnitX();
  const Eigen::Vector2d fwd = fwd3.head<2>().normalized();
  const double along = fwd.dot(drift);
  // The repeated step lets go once the walk is back within half the leash (the walk goes on at random), or after
  // kLeashGiveUp when the crates keep the steps from getting there (then it rests kLeashRest): kept, a walk whose
  // steps carried it back stepped on for the rest of its ten minutes, 500 step_backs, and one whose steps could not
  // climb onto the crate ahead looped step_forward - lead_uppercut 900 times (--footwork carry).
  constexpr double kLeashGiveUp = 4.0, kLeashRest = 10.0;  // s
  const bool back = std::abs(along) < 0.5 * leash_, stuck = now_ - leashed_at_ > kLeashGiveUp;
  if (leashed_ && (back || stuck)) {
    walker_->request_clip(kGuardClip);
    leashed_ = false;
    if (!back) leash_rest_until_ = now_ + kLeashRest;
  }
  if (!walker_->has_plan() && std::abs(along) > leash_ && now_ >= leash_rest_until_) {
    walker_->request_clip(along > 0 ? "step_back" : "step_forward", /*repeat=*/true);
    if (!leashed_) leashed_at_ = now_;  // (asked again each tick the walk is in the step already: no plan to it)
    leashed_ = true;
  }
}

}  // namespace boxing
