#pragma once
// The unassisted get-up's plan (--getup unassisted, issue 63 item 1): which body parts bear weight in each phase of a
// get-up, and when the get-up clip may go on. No physics here: the balance QP plumbing that follows the plan is
// unassisted_getup.h.
//
// WHY a schedule. The balance QP can take contacts on any link (balance_qp.h), but a lying body has a dozen links on
// the ground; planned with all of them, nothing ever leaves it, and planned with the soles only (the standing plan)
// its torques make the limbs flail (qp_balance.cpp, down_or_getting_up). A human get-up is a sequence of support sets,
// the ones issue 63 names (prone: push up -> hands and knees -> one knee -> stand; supine: sit up -> a hand and a knee
// -> one knee -> stand). Each phase names its support set; its links are the plan's contacts, every other link is
// lifted by the clip's bone tasks.
//
// WHY gates. The get-up clips (content/clips/src/getup_front.clip, getup_back.clip) are authored fast (2 s, carried
// by the assisted get-up's root spring). Here the clip's clock is the plan's: it runs at GetUpPlanTuning::clip_rate
// while the body keeps up (its com within track_tolerance of the clip's), waits otherwise, and at a phase's end waits
// until the next phase can carry the body -- its support links touching and the com over their polygon
// (support_margin inside): a quasi-static get-up, the com never asked to leave the support that will hold it next.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace eng::anim {
struct Skeleton;
}

namespace boxing {

// One phase: a span of the get-up clip's time and the bones that may bear weight during it.
struct GetUpPhase {
  std::string name;
  double clip_from = 0.0, clip_to = 0.0;  // s into the clip
  std::vector<std::string> supports;      // bone names
};

// A get-up from one lying position: its clip (the motion graph's) and its phases in order.
struct GetUpSchedule {
  std::string clip;
  std::vector<GetUpPhase> phases;
};

// The schedules: from the back (getup_back) and from the front (getup_front).
const GetUpSchedule& getup_schedule(bool from_back);

struct GetUpPlanTuning {
  // The clip played at this share of its authored speed while the body keeps up (0.3 / 0.5 / 0.4 tried: 0.4 reached
  // the furthest phases inside the referee's 8 s give-up; docs/decisions/unassisted-getup.md) ...
  double clip_rate = 0.4;
  double track_tolerance = 0.25;    // m, ... the com this far from its target: the clip waits for the body (0.12: stuck)
  double support_margin = 0.02;     // m, the com this far inside the next support polygon to end a phase
  int min_support_points = 3;       // contact points of the next support set needed (a polygon)
  double max_hold = 1.5;            // s, a gate waits at most this long, then the phase goes on all the same
  double com_omega = 4.0;           // rad/s, the com's PD toward its target (critically damped)
  double max_com_acc = 4.0;         // m/s^2
  double com_weight = 30.0;         // the com / momentum tasks' price, times the standing plan's (1: stuck lying)
  double max_root_torque = 40.0;    // N m: the root assist's limit (issue 63: at most 40 N m rms)
  double root_price = 0.3;          // per (N m)^2, the root assist's price in the QP (BoxerTuning root.assist_price)
  double torque_price = 1e-3;       // per (N m)^2, joint torques' price (root.qp_torque_price)
  double momentum_damping = 2.0;    // 1/s, the angular momentum about the com damped toward zero ...
  double max_momentum_rate = 100.0; // N m, ... at most this fast
};

// The plan's state (reset when a get-up starts).
struct GetUpPlan {
  bool active = false;
  bool from_back = false;
  int phase = 0;
  double clip_time = 0.0;    // s, the plan's clock in the clip
  double held = 0.0;         // s the current gate has waited
  double rate = 1.0;         // this tick's clip rate (what the pose source plays the clip at)
  // The actual com less the clip's at the start: the clip's com motion is followed from where the body lies (the
  // clip's lying pose is not the body's; its com can be 30 cm off).
  Eigen::Vector3d com_offset = Eigen::Vector3d::Zero();
  bool have_offset = false;
  std::vector<std::vector<uint8_t>> masks;     // per phase, per bone: 1 in the phase's support set
  std::vector<double> strength;                // per bone: its joint's strength (N m, person_strength.h)
};

// What the physics says this tick (unassisted_getup.cpp measures it).
struct GetUpMeasure {
  Eigen::Vector2d com = Eigen::Vector2d::Zero();  // the actual com's floor point
  double com_error = 0.0;                         // m, |actual com - the clip's com|
  int next_points = 0;                            // contact points on the next phase's supports
  double next_inside = -1.0;                      // m, how far the com lies inside their polygon (< 0: outside)
};

// A get-up starts: from the back or the front, the bones' support sets and strengths looked up by name.
void getup_plan_start(GetUpPlan& p, bool from_back, const eng::anim::Skeleton& s);
// One tick: the clip's rate for the next tick (p.rate, also returned), the phase moved on where its gate opens.
double getup_plan_advance(GetUpPlan& p, const GetUpPlanTuning& t, const GetUpMeasure& m, double dt);
// Per bone, 1 in the current phase's support set / the next phase's (the last phase's own when it is the last).
const std::vector<uint8_t>& getup_supports(const GetUpPlan& p);
const std::vector<uint8_t>& getup_next_supports(const GetUpPlan& p);
// The current phase's name ("" when no get-up is planned).
const std::string& getup_phase_name(const GetUpPlan& p);
// True once the last phase's end is reached (the clip goes on into guard by itself).
bool getup_plan_done(const GetUpPlan& p);

}  // namespace boxing
