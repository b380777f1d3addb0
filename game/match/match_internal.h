#pragma once
// Small helpers the match's files share (match.cpp, referee.cpp, hits.cpp, fighter_view.cpp, match_report.cpp):
// internal to game/match/.
#include <Eigen/Core>

#include "engine/anim/clip.h"
#include "engine/anim/motion_graph.h"
#include "engine/physics/dynamics.h"
#include "game/boxer_state.h"
#include "game/world.h"

namespace boxing {

// The clip boxer b's walk plays now (nullptr: b does not walk the graph).
inline const eng::anim::Clip* clip_of(const World& w, const Boxer& b) {
  const eng::anim::GraphWalker* walker = b.source.walker();
  return walker ? &w.graph.clips[walker->current_clip_index()] : nullptr;
}

inline bool is_punch(const eng::anim::Clip* c) { return c && c->has_tag("punch") && c->glove >= 0; }

// A bone's centre of mass in the world (m).
inline Eigen::Vector3d bone_centre(const World& w, const Boxer& b, int bone) {
  const auto& x = w.data.x[b.bodies.body[bone]];
  return x.p + x.R * w.boxer_desc.bones[bone].com;
}

inline Eigen::Vector3d body_velocity_at(const World& w, int body, const Eigen::Vector3d& p) {
  return eng::physics::point_velocity(w.data, body, p);
}

// On its feet and fighting (in guard or stunned): the states a punch lands on and the AI acts from.
inline bool standing_state(BoxerState s) { return s == BoxerState::Guard || s == BoxerState::Stunned; }

}  // namespace boxing
