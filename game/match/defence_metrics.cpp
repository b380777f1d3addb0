#include "game/match/defence_metrics.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "game/match/match.h"
#include "game/match/match_internal.h"

namespace boxing {

void measure_defences(World& w) {
  Match& mt = *w.match;
  const MatchBones& mb = mt.bones;
  for (int k = 0; k < 2; ++k) {
    const Boxer& b = w.boxers[k];
    const eng::anim::GraphWalker* walker = b.source.walker();
    DefenceTrack& tr = mt.defence_track[k];
    const int idx = walker ? walker->current_clip_index() : -1;
    const eng::anim::Clip* c = idx >= 0 ? &w.graph.clips[idx] : nullptr;
    const bool defending = c && c->has_tag("defence") && standing_state(b.ctl.state.state);
    if (tr.clip >= 0 && idx != tr.clip) tr.clip = -1;  // ended (its record's `whole` says how)
    if (!defending) continue;
    const Eigen::Vector3d head = bone_centre(w, b, mb.head);
    if (tr.clip < 0) {
      tr.clip = idx;
      tr.head0 = head;
      const Eigen::Vector2d line = (head - bone_centre(w, w.boxers[1 - k], mb.head)).head<2>();
      const Eigen::Vector2d u = line.norm() > 1e-6 ? Eigen::Vector2d(line.normalized()) : Eigen::Vector2d::UnitX();
      // u points from the opponent to this boxer: this boxer faces -u, and its left is -u turned a quarter left.
      tr.left = Eigen::Vector2d(u.y(), -u.x());
      tr.record = static_cast<int>(mt.defences.size());
      DefenceMotion d;
      d.boxer = k, d.clip = c->name, d.t = w.data.time;
      mt.defences.push_back(d);
    }
    DefenceMotion& d = mt.defences[tr.record];
    const Eigen::Vector3d dh = head - tr.head0;
    const double lateral = dh.head<2>().dot(tr.left);
    const double side = c->name == "slip_left" ? lateral : c->name == "slip_right" ? -lateral : std::abs(lateral);
    d.side_m = std::max(d.side_m, side);
    d.drop_m = std::max(d.drop_m, -dh.z());
    const double gz[2] = {bone_centre(w, b, mb.glove[0]).z(), bone_centre(w, b, mb.glove[1]).z()};
    d.gloves_above_head_m = std::max(d.gloves_above_head_m, std::min(gz[0], gz[1]) - head.z());
    d.gloves_below_chest_m = std::max(d.gloves_below_chest_m, bone_centre(w, b, mb.chest).z() - std::max(gz[0], gz[1]));
    // Played to its end: within two 60 Hz frames of the clip's length (the walk leaves it at the end).
    d.whole = walker->clip_time() >= c->duration() - 2.0 / 60.0;
  }
  // The defence each open punch meets before its first touch.
  for (int k = 0; k < 2; ++k) {
    const MatchFighter& f = mt.fighter[k];
    if (f.open_punch < 0) continue;
    PunchEvent& e = mt.events[f.open_punch];
    const DefenceTrack& tr = mt.defence_track[1 - k];
    if (e.hit_part.empty() && e.defence.empty() && tr.clip >= 0) e.defence = mt.defences[tr.record].clip;
  }
}

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

nlohmann::json defence_report(const World& w) {
  const Match& mt = *w.match;
  struct Acc {
    int n = 0, whole = 0;
    std::vector<double> side, drop, above, below;
  };
  std::map<std::string, Acc> by_clip;
  for (const DefenceMotion& d : mt.defences) {
    Acc& a = by_clip[d.clip];
    ++a.n;
    if (!d.whole) continue;
    ++a.whole;
    a.side.push_back(d.side_m), a.drop.push_back(d.drop_m);
    a.above.push_back(d.gloves_above_head_m), a.below.push_back(d.gloves_below_chest_m);
  }
  nlohmann::json motions = nlohmann::json::object();
  for (const auto& [clip, a] : by_clip)
    motions[clip] = {{"n", a.n}, {"whole", a.whole}, {"head_side_median_m", median(a.side)},
                     {"head_drop_median_m", median(a.drop)}, {"gloves_above_head_median_m", median(a.above)},
                     {"gloves_below_chest_median_m", median(a.below)}};
  std::map<std::string, std::array<int, 2>> met;  // defence ("none") -> punches thrown into it, landed
  for (const PunchEvent& e : mt.events) {
    auto& m = met[e.defence.empty() ? "none" : e.defence];
    ++m[0];
    m[1] += e.landed ? 1 : 0;
  }
  nlohmann::json punches = nlohmann::json::object();
  for (const auto& [d, m] : met) punches[d] = {{"thrown", m[0]}, {"landed", m[1]}};
  nlohmann::json list = nlohmann::json::array();
  for (const DefenceMotion& d : mt.defences)
    list.push_back({{"boxer", d.boxer}, {"clip", d.clip}, {"t", d.t}, {"head_side_m", d.side_m},
                    {"head_drop_m", d.drop_m}, {"gloves_above_head_m", d.gloves_above_head_m},
                    {"gloves_below_chest_m", d.gloves_below_chest_m}, {"whole", d.whole}});
  return {{"motions", motions}, {"punches_into", punches}, {"list", list}};
}

}  // namespace boxing
