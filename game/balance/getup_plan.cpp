// The unassisted get-up's plan (getup_plan.h).
#include "game/balance/getup_plan.h"

#include <algorithm>

#include "engine/anim/skeleton.h"
#include "game/person_strength.h"

namespace boxing {

namespace {

// The phases follow the clips' keys (content/clips/src/getup_front.clip, getup_back.clip): each phase ends at the key
// where the clip has moved the body onto its next support set.
const std::vector<std::string> kLying = {"pelvis",  "abdomen",   "chest",       "head",       "upper_arm_l",
                                         "upper_arm_r", "forearm_l", "forearm_r", "glove_l",    "glove_r",
                                         "thigh_l", "thigh_r",   "shank_l",     "shank_r",    "foot_l",
                                         "foot_r"};

GetUpSchedule front_schedule() {
  GetUpSchedule s;
  s.clip = "getup_front";
  // 0-0.5 s: the arms come under the chest and push it up (key 0.25: hands under the shoulders; 0.5: knees bent).
  s.phases.push_back({"push_up", 0.0, 0.5, kLying});
  // 0.5-1.0 s: on hands and knees, the hips drawn back over the knees and feet (key 1.0: crouched, hands down).
  s.phases.push_back({"hands_knees", 0.5, 1.0,
                      {"glove_l", "glove_r", "forearm_l", "forearm_r", "thigh_l", "thigh_r", "shank_l", "shank_r",
                       "foot_l", "foot_r"}});
  // 1.0-1.5 s: the hands come off, the left foot steps forward, the right knee stays down (key 1.5: one knee).
  s.phases.push_back({"one_knee", 1.0, 1.5, {"glove_l", "glove_r", "shank_l", "shank_r", "foot_l", "foot_r"}});
  // 1.5-2.0 s: up from the knee onto both feet (key 2.0: guard).
  s.phases.push_back({"stand", 1.5, 2.0, {"shank_r", "foot_l", "foot_r"}});
  return s;
}

GetUpSchedule back_schedule() {
  GetUpSchedule s;
  s.clip = "getup_back";
  // 0-0.6 s: sit up, the hands behind, the feet drawn in (key 0.6: sitting on the buttocks, hands and feet).
  s.phases.push_back({"sit_up", 0.0, 0.6, kLying});
  // 0.6-1.2 s: turn onto the right knee with the left foot planted, a hand down (key 1.2: hips up, one knee).
  s.phases.push_back({"hand_and_knee", 0.6, 1.2,
                      {"pelvis", "glove_l", "glove_r", "forearm_l", "forearm_r", "thigh_r", "shank_l", "shank_r",
                       "foot_l", "foot_r"}});
  // 1.2-1.7 s: on one knee, the hands off (key 1.7: rising on the left foot).
  s.phases.push_back({"one_knee", 1.2, 1.7, {"glove_l", "glove_r", "shank_r", "foot_l", "foot_r"}});
  // 1.7-2.2 s: up onto both feet (key 2.2: guard).
  s.phases.push_back({"stand", 1.7, 2.2, {"shank_r", "foot_l", "foot_r"}});
  return s;
}

void mark(const eng::anim::Skeleton& s, const std::vector<std::string>& names, std::vector<uint8_t>& out) {
  out.assign(s.size(), 0);
  for (const std::string& n : names) {
    const int i = s.find(n);
    if (i >= 0) out[i] = 1;
  }
}

const std::string kNone;

}  // namespace

const GetUpSchedule& getup_schedule(bool from_back) {
  static const GetUpSchedule front = front_schedule(), back = back_schedule();
  return from_back ? back : front;
}

void getup_plan_start(GetUpPlan& p, bool from_back, const eng::anim::Skeleton& s) {
  p.active = true;
  p.from_back = from_back;
  p.phase = 0;
  p.clip_time = 0.0;
  p.held = 0.0;
  p.rate = 0.0;
  p.have_offset = false;
  const GetUpSchedule& sc = getup_schedule(from_back);
  p.masks.resize(sc.phases.size());  // (capacity kept: a get-up's start allocates only the first time)
  for (size_t k = 0; k < sc.phases.size(); ++k) mark(s, sc.phases[k].supports, p.masks[k]);
  p.strength.assign(s.size(), 0.0);
  for (int i = 0; i < s.size(); ++i) p.strength[i] = person_strength(s.name[i]);
}

bool getup_plan_done(const GetUpPlan& p) {
  const GetUpSchedule& sc = getup_schedule(p.from_back);
  return p.phase + 1 >= int(sc.phases.size()) && p.clip_time >= sc.phases.back().clip_to;
}

double getup_plan_advance(GetUpPlan& p, const GetUpPlanTuning& t, const GetUpMeasure& m, double dt) {
  const GetUpSchedule& sc = getup_schedule(p.from_back);
  const int last = int(sc.phases.size()) - 1;
  const GetUpPhase& ph = sc.phases[p.phase];
  // The last phase played to its end: the clip goes on into guard at its own speed (the referee calls the boxer up).
  if (getup_plan_done(p)) return p.rate = 1.0;
  // The body behind the clip: the clip waits (a quasi-static get-up: the targets never run off from the body).
  const bool keeping_up = m.com_error <= t.track_tolerance;
  if (p.clip_time < ph.clip_to) {
    p.rate = keeping_up ? t.clip_rate : 0.0;
    p.clip_time = std::min(ph.clip_to, p.clip_time + p.rate * dt);
    return p.rate;
  }
  // At the phase's end: the gate. The next support set touches and the com is over it (or the wait is over).
  if (p.phase < last) {
    const bool carried = m.next_points >= t.min_support_points && m.next_inside >= t.support_margin;
    p.held += dt;
    if (!carried && p.held < t.max_hold) return p.rate = 0.0;
    ++p.phase;
    p.held = 0.0;
  }
  p.rate = keeping_up ? t.clip_rate : 0.0;
  p.clip_time += p.rate * dt;
  return p.rate;
}

const std::vector<uint8_t>& getup_supports(const GetUpPlan& p) { return p.masks[p.phase]; }

const std::vector<uint8_t>& getup_next_supports(const GetUpPlan& p) {
  return p.masks[std::min(p.phase + 1, int(p.masks.size()) - 1)];
}

const std::string& getup_phase_name(const GetUpPlan& p) {
  if (!p.active) return kNone;
  return getup_schedule(p.from_back).phases[p.phase].name;
}

}  // namespace boxing
