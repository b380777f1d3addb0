#include "game/getup_metrics.h"

#include <algorithm>
#include <cmath>

#include "game/person_strength.h"
#include "game/world.h"

namespace boxing {

namespace {

// A contact's normal force this much or more: the body part bears weight (a graze does not).
constexpr double kSupportForce = 20.0;  // N

bool standing(BoxerState s) { return s == BoxerState::Guard || s == BoxerState::Stunned; }

const std::string kDown = "down", kUp = "up", kNoClip = "stand-up";

// The phase a fallen boxer is in: down, or the clip its stand-up plays (a reference: no string built per tick).
const std::string& phase_of(const World& w, const Boxer& b) {
  if (b.ctl.state.state != BoxerState::GettingUp) return kDown;
  if (const QpBalance* q = std::get_if<QpBalance>(&b.ctl.balance); q && q->getup.active)
    return getup_phase_name(q->getup);  // the unassisted get-up's phase (getup_plan.h)
  const eng::anim::GraphWalker* walker = b.source.walker();
  return walker ? w.graph.clips[walker->current_clip_index()].name : kNoClip;
}

void index_bodies(World& w) {
  GetUpTracker& g = w.getups;
  g.bone_of_body.assign(w.model.bodies.size(), -1);
  g.boxer_of_body.assign(w.model.bodies.size(), -1);
  for (int k = 0; k < static_cast<int>(w.boxers.size()); ++k)
    for (size_t bone = 0; bone < w.boxers[k].bodies.body.size(); ++bone) {
      g.bone_of_body[w.boxers[k].bodies.body[bone]] = static_cast<int>(bone);
      g.boxer_of_body[w.boxers[k].bodies.body[bone]] = k;
    }
  g.pressing.assign(w.boxers.size() * w.boxer_desc.skeleton.size(), 0);
  if (g.open.size() != w.boxers.size()) g.open.assign(w.boxers.size(), -1);  // (bodies added later keep them)
}

}  // namespace

const char* lying_of(const World& w, const Boxer& b) {
  const int chest = w.boxer_desc.skeleton.find("chest");
  const Eigen::Vector3d front = w.data.x[b.bodies.body[chest >= 0 ? chest : 0]].R * Eigen::Vector3d::UnitX();
  return front.z() > 0.0 ? "back" : "front";
}

void measure_getups(World& w) {
  GetUpTracker& g = w.getups;
  if (g.bone_of_body.size() != w.model.bodies.size() || g.open.size() != w.boxers.size()) index_bodies(w);
  const int bones = w.boxer_desc.skeleton.size();
  const double t = w.data.time, dt = kPhysicsDt;
  std::fill(g.pressing.begin(), g.pressing.end(), 0);
  for (const eng::physics::Contact& c : w.data.contacts) {
    if ((c.body_a == 0) == (c.body_b == 0)) continue;  // the crates and floor (body 0) against a body
    const int body = c.body_a == 0 ? c.body_b : c.body_a;
    if (body >= static_cast<int>(g.bone_of_body.size()) || g.bone_of_body[body] < 0) continue;
    if (std::abs(c.force.dot(c.point.normal)) >= kSupportForce) g.pressing[g.boxer_of_body[body] * bones + g.bone_of_body[body]] = 1;
  }
  for (int k = 0; k < static_cast<int>(w.boxers.size()); ++k) {
    const Boxer& b = w.boxers[k];
    const BoxerState s = b.ctl.state.state;
    if (g.open[k] < 0) {
      if (standing(s) || s == BoxerState::GettingUp) continue;
      g.open[k] = static_cast<int>(g.records.size());
      GetUpRecord r;
      r.boxer = k;
      r.down_at = t;
      r.support_s.assign(bones, 0.0);
      r.torque_peak.assign(bones, 0.0);
      r.phases.emplace_back(kDown, t);
      g.records.push_back(std::move(r));
    }
    GetUpRecord& r = g.records[g.open[k]];
    // The phases: down, then each clip the stand-up plays (a stand-up given up goes down again), then up.
    const std::string& phase = standing(s) ? kUp : phase_of(w, b);
    if (r.phases.back().first != phase) {
      r.phases.emplace_back(phase, t);
      if (s == BoxerState::GettingUp && r.lying.empty()) r.lying = lying_of(w, b);
    }
    r.time += dt;
    const double f = b.ctl.root_force.norm(), tau = b.ctl.root_torque.norm();
    r.lift_force_sq_dt += f * f * dt, r.lift_force_peak = std::max(r.lift_force_peak, f);
    r.root_torque_sq_dt += tau * tau * dt, r.root_torque_peak = std::max(r.root_torque_peak, tau);
    for (int bone = 0; bone < bones; ++bone) {
      if (g.pressing[k * bones + bone]) r.support_s[bone] += dt;
      const eng::physics::Body& body = w.model.bodies[b.bodies.body[bone]];
      if (bone > 0 && body.nv > 0)
        r.torque_peak[bone] = std::max(r.torque_peak[bone], (w.data.tau.segment(body.v_index, body.nv) +
                                                              w.data.passive.segment(body.v_index, body.nv)).norm());
    }
    if (standing(s)) {  // up this tick (its step still counted: the stand-up's torques acted in it)
      r.up_at = t;
      g.open[k] = -1;
    }
  }
}

nlohmann::json getups_report(const World& w) {
  nlohmann::json out = nlohmann::json::array();
  const auto& names = w.boxer_desc.skeleton.name;
  for (const GetUpRecord& r : w.getups.records) {
    nlohmann::json support = nlohmann::json::object(), peak = nlohmann::json::object(),
                   limit = nlohmann::json::object(), fraction = nlohmann::json::object(),
                   phases = nlohmann::json::array();
    for (size_t bone = 0; bone < names.size(); ++bone) {
      if (r.support_s[bone] > 0.0) support[names[bone]] = r.support_s[bone];
      const double strength = person_strength(names[bone]);
      if (bone == 0 || strength <= 0.0) continue;
      peak[names[bone]] = r.torque_peak[bone];
      limit[names[bone]] = strength;
      fraction[names[bone]] = r.torque_peak[bone] / strength;
    }
    for (const auto& [name, from] : r.phases) phases.push_back({{"name", name}, {"from_s", from}});
    auto rms = [&r](double sq_dt) { return r.time > 0.0 ? std::sqrt(sq_dt / r.time) : 0.0; };
    out.push_back({{"boxer", r.boxer},
                   {"down_at_s", r.down_at},
                   {"up_at_s", r.up_at >= 0.0 ? nlohmann::json(r.up_at) : nlohmann::json(nullptr)},
                   {"lying", r.lying.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.lying)},
                   {"lift_force_rms_n", rms(r.lift_force_sq_dt)},
                   {"lift_force_peak_n", r.lift_force_peak},
                   {"root_torque_rms_nm", rms(r.root_torque_sq_dt)},
                   {"root_torque_peak_nm", r.root_torque_peak},
                   {"support_contacts", support},
                   {"joint_torque_peak_nm", peak},
                   {"joint_torque_limit_nm", limit},
                   {"joint_torque_peak_fraction", fraction},
                   {"phases", phases},
                   {"mode", w.options.getup}});  // --getup assisted | unassisted
  }
  return out;
}

}  // namespace boxing
