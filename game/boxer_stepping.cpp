// The boxer's steps (balance QP): the clip's floor under the feet, lift-off gating and the step planner, from the
// biped units in engine/control/biped/.
#include "game/boxer_stepping.h"

#include <algorithm>
#include <cmath>

#include "engine/control/biped/capture_point.h"
#include "engine/control/biped/support_polygon.h"
#include "engine/control/servo/person_space.h"
#include "engine/control/servo/world_pose.h"
#include "engine/physics/dynamics.h"
#include "game/boxer.h"
#include "game/footwork.h"

namespace boxing {

using eng::control::pose_fk;

// The clip's floor under the actual feet (balance QP's steps): b.ctl.support_base.
void update_support_base(const eng::physics::Data& d, const Arena& arena, Boxer& b, double dt) {
  // The clip's floor: the lower of the crate tops under the two feet where they actually are, low-passed
  // (StanceTuning::base_tau) so a swing foot passing over another crate does not jerk the desired root up or down. The stance's
  // crates only hold until the first step: after one they would place the root for crates the feet have left (a leg
  // over-stretched above a lower crate, or crouched on a higher one).
  // A touching foot whose centre reads a top more than kSeamDrop below its sole stands across a seam between crates
  // (12 mm wide; Arena::top_at reads the floor there): its top is the highest under its heel, toe and the centre's
  // sides. Read at the centre alone, the base sinks to the floor and a boxer standing up with a foot across a seam
  // holds a deep squat.
  constexpr double kSeamDrop = 0.05;  // m
  const auto& ft = b.settings.tuning.foot;
  double lowest = 1e9;
  for (int k = 0; k < 2; ++k) {
    const int fb = b.bodies.body[b.bones.foot[k]];
    const Eigen::Vector3d c = d.x[fb].p + d.x[fb].R * ft.centre;
    double top = arena.top_at(c.x(), c.y());
    const double sole = std::min((d.x[fb].p + d.x[fb].R * ft.heel).z(), (d.x[fb].p + d.x[fb].R * ft.toe).z());
    if (b.ctl.contacts.support[k] && top < sole - kSeamDrop) {
      const Eigen::Vector3d side(0.0, 0.04, 0.0);
      for (const Eigen::Vector3d& at : {ft.heel, ft.toe, Eigen::Vector3d(ft.centre + side), Eigen::Vector3d(ft.centre - side)}) {
        const Eigen::Vector3d q = d.x[fb].p + d.x[fb].R * at;
        top = std::max(top, arena.top_at(q.x(), q.y()));
      }
    }
    lowest = std::min(lowest, top);
  }
  // A balance step on its way down to a lower top (off a crate, off the platform): the base goes toward that top
  // from the lift-off, so the stance leg bends and the swing leg reaches it. Read under the feet alone, the base
  // follows only once the foot is over the lower top, and the foot comes down late, set down by the swing's timeout
  // (docs/decisions/balance-steps.md).
  if (b.ctl.balance_steps.step.active) lowest = std::min(lowest, b.ctl.balance_steps.step.to_top);
  if (!b.ctl.have_support_base) b.ctl.support_base = std::min(b.stance.lead_top, b.stance.rear_top), b.ctl.have_support_base = true;
  b.ctl.support_base += (1.0 - std::exp(-dt / b.settings.tuning.stance.base_tau)) * (lowest - b.ctl.support_base);
}

// Where and when the clip puts foot k down again (step_planner.h), from the pose source's preview.
namespace {
eng::control::Touchdown touchdown_of(const eng::anim::Skeleton& skel, Boxer& b, int k) {
  const auto preview = [&b](double ahead) -> const eng::anim::Pose& { return b.source.preview(ahead); };
  eng::control::Touchdown td = eng::control::find_touchdown(skel, preview, b.bones.foot[k], b.settings.tuning.foot,
                                                            b.settings.tuning.step, b.scratch.fk_W, b.scratch.fk_P);
  td.apart = (b.scratch.fk_P[b.bones.foot[k]] - b.scratch.fk_P[b.bones.foot[1 - k]]).head<2>();  // (its last frame's)
  // A carried step held down for the weight shift is still the clip's whole step when it lifts (carry_whole): from
  // where the physical foot still stands, the clip's whole travel, swung in the clip's whole time. Judged by what is
  // left, a step held briefly has too little travel to carry (carry_min_travel) and too little time to its touch-down
  // (the gate's min_swing): the rear foot stays behind, and the lead's next step, landing relative to it, moves the
  // pelvis only a few cm a step (docs/decisions/footwork.md).
  const eng::control::StepTuning& t = b.settings.tuning.step;
  if (t.carry && t.carry_whole) {
    if (!b.ctl.clip_step[k]) {
      b.ctl.clip_step[k] = td;
    } else {
      td.travel = b.ctl.clip_step[k]->travel;
      td.ahead = std::max(td.ahead, b.ctl.clip_step[k]->ahead);
    }
  }
  return td;
}

// Foot k's sole centre where the physical foot is (world).
Eigen::Vector3d sole_centre(const eng::physics::Data& d, const Boxer& b, int k) {
  const int fb = b.bodies.body[b.bones.foot[k]];
  return d.x[fb].p + d.x[fb].R * b.settings.tuning.foot.centre;
}

}  // namespace

// LIFT-OFF GATING (balance QP, lift_off_gate.h): the capture point over the other foot's touching contacts decides
// whether a foot the clip lifts may leave the ground. Measurements: docs/decisions/lift-off-gate.md.
void gate_lift_off(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   const Arena& arena, Boxer& b, bool swing[2], double dt) {
  const auto& skel = desc.skeleton;
  const int pelvis = b.bodies.body[0];
  // A balance step under way resets the gates every tick (take_balance_steps) and overrides the clip's feet: the
  // clip's steps judged meanwhile are not counted (each would count once a tick, inflating steps_taken).
  const bool count = !b.ctl.balance_steps.step.active;
  for (int k = 0; k < 2; ++k) {
    if (!swing[k]) b.ctl.clip_step[k].reset();  // the clip's next step is another
    if (!eng::control::lift_off_gate_due(b.ctl.gate[k], swing[k], !b.ctl.state.fallen())) continue;
    // The other (stance) foot's ground contacts and the capture point. Carried footwork counts none while that foot
    // is in a carried step (still touching as it lifts, it would let this foot go too: both feet swinging) or touches
    // no top (a foot left on a crate's edge by a late landing cannot hold the body on one leg).
    const eng::control::StepPlan& other = b.ctl.step[1 - k];
    const bool no_stance = b.settings.tuning.step.carry && ((other.active && other.carried) || !b.ctl.contacts.on_top[1 - k]);
    const std::vector<Eigen::Vector2d>& stance = no_stance ? b.scratch.no_points : b.ctl.contacts.ground_points[1 - k];
    Eigen::Vector2d xi = Eigen::Vector2d::Zero();
    eng::control::ClipStep step;
    const eng::control::Touchdown td = touchdown_of(skel, b, k);
    if (stance.size() >= 2) {
      const Eigen::Vector3d com = eng::physics::subtree_com(m, d, pelvis);
      const eng::physics::Vec6 h = eng::physics::spatial_momentum(m, d, pelvis);
      const Eigen::Vector3d vcom = h.tail<3>() / b.control_body.total_mass;
      const double z = std::max(0.3, com.z() - b.ctl.support_base);
      xi = eng::control::capture_point(com.head<2>(), vcom.head<2>(), z);
      // The quick-step test's landing: the clip's touch-down placed from where the ankle is now, on the stance's
      // heading (the sole's rectangle; plan_steps may still shift it onto a better foothold).
      const int fb = b.bodies.body[b.bones.foot[k]];
      const Eigen::Rotation2Dd heading(b.stance.heading), yaw(b.stance.heading + td.yaw);
      Eigen::Vector2d ankle = d.x[fb].p.head<2>() + heading * td.travel;
      // A carried step is judged as plan_steps would start it: its landing (the foothold's) and its swing's length
      // (a step up rises at carry_rise_speed). Judged by the clip's short swing, a long step up a crate passes the
      // test, and the body falls over the stance foot during it.
      eng::control::StepPlan& preview = b.scratch.step_preview;
      preview.carried = false;
      if (b.settings.tuning.step.carry) {
        const Eigen::Vector3d from = sole_centre(d, b, k), stance_centre = sole_centre(d, b, 1 - k);
        eng::control::start_step(preview, td, d.x[fb].p, b.stance.heading, from, ground_of(arena),
                                 b.settings.tuning.foot, b.settings.tuning.step, dt,
                                 d.x[b.bodies.body[b.bones.foot[1 - k]]].p.head<2>(), stance_centre.head<2>());
      }
      if (preview.carried) {
        ankle = preview.landing + preview.shift;
        step.swing = preview.duration;
        // A landing where the foot already stands (the relative landing reproduces the stance the feet have) is no
        // step: the foot stays down (else the boxer marks time, lifting a foot and putting it back where it stood).
        if ((ankle - d.x[fb].p.head<2>()).norm() < b.settings.tuning.step.carry_in_place) {
          b.ctl.gate[k].skipped = true, b.ctl.gate[k].holding = false;
          swing[k] = false;
          if (count) ++b.metrics.steps_in_place;
          continue;
        }
      }
      const eng::control::SoleShape& sole = b.settings.tuning.step.foothold.sole;
      b.scratch.landing.clear();
      for (double x : {sole.heel, sole.toe})
        for (double y : {-sole.half_width, sole.half_width}) b.scratch.landing.push_back(ankle + yaw * Eigen::Vector2d(x, y));
      step.landing = &b.scratch.landing;
      step.omega = eng::control::lip_omega(z);
    }
    const eng::control::GateEvent e = eng::control::lift_off_gate_decide(
        b.ctl.gate[k], swing[k], stance, xi, td.ahead, dt, b.settings.tuning.gate, b.scratch.hull, step, &b.scratch.pts);
    if (!count) continue;
    if (e == eng::control::GateEvent::StepTaken) {
      ++b.metrics.steps_taken;
      b.metrics.step_travel[k] = Eigen::Rotation2Dd(b.stance.heading) * td.travel;
      b.metrics.step_from[k] = sole_centre(d, b, k).head<2>();
      b.metrics.step_pending[k] = b.metrics.step_travel[k].norm() > BoxerMetrics::kStepTravelMin;
    }
    if (e == eng::control::GateEvent::StepSkipped) ++b.metrics.steps_skipped;
  }
}

// STEPS ON THE CRATES (balance QP, step_planner.h): a foot the clip just lifted starts a step toward a foothold on
// the crates; every swinging foot's ankle target advances.
void plan_steps(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, const Arena& arena, Boxer& b,
                bool swing[2], double dt) {
  const auto& skel = desc.skeleton;
  const int* feet = b.bones.foot;
  const eng::control::FootGeometry& g = b.settings.tuning.foot;
  std::vector<Eigen::Quaterniond>& W = b.scratch.fk_W;
  std::vector<Eigen::Vector3d>& P = b.scratch.fk_P;
  // A foot the clip just lifted: where (clip floor frame) and when the clip puts it down again.
  bool starts[2] = {false, false};
  eng::control::Touchdown td[2];
  for (int k = 0; k < 2; ++k) {
    eng::control::StepPlan& st = b.ctl.step[k];
    if (st.active && st.carried) {
      // A carried step swings until its sole touches a top past the swing's middle and within a few cm of its landing
      // (a toe brushing the crate it left is not a landing), or late: it then rests until the clip's swing ends (the
      // clip may land the foot sooner or later than the path).
      const Eigen::Vector2d sole = sole_centre(d, b, k).head<2>();
      const bool down = b.ctl.contacts.on_top[k] && st.elapsed > 0.6 * st.duration && (sole - st.path.to).norm() < 0.06;
      if (down || st.elapsed > st.duration + b.settings.tuning.step.carry_late || b.ctl.state.fallen())
        st.active = false, st.landed = true;
      else
        swing[k] = true;
    }
    if (!swing[k]) st.landed = false;
    if (st.landed) swing[k] = false;
    if (!swing[k]) st.active = false;
    st.has_velocity = false;
    if (!swing[k] || st.active) continue;
    starts[k] = true;
    td[k] = touchdown_of(skel, b, k);
  }
  if (!swing[0] && !swing[1]) return;
  pose_fk(skel, b.desired.pose, W, P);  // the placed pose of this tick
  const eng::control::GroundHeight ground = ground_of(arena);
  for (int k = 0; k < 2; ++k) {
    if (!swing[k]) continue;
    eng::control::StepPlan& st = b.ctl.step[k];
    if (starts[k]) {
      const Eigen::Vector3d from = sole_centre(d, b, k), stance = sole_centre(d, b, 1 - k);
      const Eigen::Vector2d stance_ankle = d.x[b.bodies.body[feet[1 - k]]].p.head<2>();
      eng::control::start_step(st, td[k], P[feet[k]], b.stance.heading, from, ground, g, b.settings.tuning.step, dt,
                               stance_ankle, stance.head<2>());
    }
    eng::control::advance_step(st, P[feet[k]], W[feet[k]], ground, g, b.settings.tuning.step, dt);
  }
}

}  // namespace boxing

namespace boxing {

void observe_push(const eng::physics::Model& m, const eng::physics::Data& d, Boxer& b, double dt) {
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  // The boxer's bodies: one run of indices (add_character adds a character's bodies together).
  const auto [lo, hi] = std::minmax_element(b.bodies.body.begin(), b.bodies.body.end());
  Eigen::Vector2d f = Eigen::Vector2d::Zero();
  for (const eng::physics::Contact& c : d.contacts) {  // the ground's (static body 0) forces on the boxer
    if (c.body_a == 0 && c.body_b >= *lo && c.body_b <= *hi) f += c.force.head<2>();
    if (c.body_b == 0 && c.body_a >= *lo && c.body_a <= *hi) f -= c.force.head<2>();
  }
  const double mass = b.control_body.total_mass;
  const Eigen::Vector2d vcom = eng::physics::spatial_momentum(m, d, b.bodies.body[0]).tail<3>().head<2>() / mass;
  if (st.push_have_vcom) {
    const Eigen::Vector2d acc = (vcom - st.push_vcom) / dt - f / mass;
    st.push_acc += std::min(1.0, dt / b.settings.tuning.balance_step.push_filter_tau) * (acc - st.push_acc);
  }
  st.push_vcom = vcom;
  st.push_have_vcom = true;
}

bool on_poor_foothold(const eng::physics::Data& d, const Arena& arena, const Boxer& b, int k) {
  const eng::physics::Pose& x = d.x[b.bodies.body[b.bones.foot[k]]];
  return !eng::control::foothold_ok(ground_of(arena), x.p.head<2>(), eng::control::heading_of(Eigen::Quaterniond(x.R)),
                                    b.settings.tuning.step.foothold);
}

bool stance_can_fight(const eng::physics::Data& d, const Boxer& b) {
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  const Eigen::Vector2d l = sole_centre(d, b, 0).head<2>(), r = sole_centre(d, b, 1).head<2>();
  const Eigen::Vector2d fwd(std::cos(b.stance.heading), std::sin(b.stance.heading)), left(-fwd.y(), fwd.x());
  const double apart = (l - r).norm();
  return left.dot(l - r) >= t.return_keep_width && apart >= t.min_gap && apart <= t.max_reach;
}

namespace {

// The body and the feet as the balance steps read them this tick.
struct StepView {
  Eigen::Vector3d com;
  Eigen::Vector2d vcom;
  double omega;
  Eigen::Vector2d xi;  // the capture point
  Eigen::Vector2d sole[2];
  double yaw[2];
  // What each foot can hold: its sole's rectangle on the floor while it touches the ground (the centre of pressure
  // can go anywhere in it; the contact points alone, a foot on its edge for a moment, make a hull the com at rest can
  // stand outside of, and a step is taken for nothing). Empty for a foot off the ground (b.scratch.sole_corners).
  std::vector<Eigen::Vector2d>* corners;
  eng::control::GroundHeight ground;
};

StepView view_for_steps(const eng::physics::Model& m, const eng::physics::Data& d, const Arena& arena, Boxer& b) {
  StepView v;
  const int pelvis = b.bodies.body[0];
  v.com = eng::physics::subtree_com(m, d, pelvis);
  v.vcom = eng::physics::spatial_momentum(m, d, pelvis).tail<3>().head<2>() / b.control_body.total_mass;
  v.omega = eng::control::lip_omega(v.com.z() - b.ctl.support_base);
  v.xi = v.com.head<2>() + v.vcom / v.omega;
  v.corners = b.scratch.sole_corners;
  const eng::control::SoleShape& shape = b.settings.tuning.step.foothold.sole;
  for (int k = 0; k < 2; ++k) {
    const int fb = b.bodies.body[b.bones.foot[k]];
    v.sole[k] = sole_centre(d, b, k).head<2>();
    v.yaw[k] = eng::control::heading_of(Eigen::Quaterniond(d.x[fb].R));
    v.corners[k].clear();
    if (!b.ctl.contacts.on_ground[k]) continue;
    const Eigen::Rotation2Dd R(v.yaw[k]);
    const Eigen::Vector2d a = d.x[fb].p.head<2>();
    for (double x : {shape.heel, shape.toe})
      for (double y : {-shape.half_width, shape.half_width}) v.corners[k].push_back(a + R * Eigen::Vector2d(x, y));
  }
  v.ground = ground_of(arena);
  return v;
}

// The step under way: its landing re-planned while the push acts, then its touch-down.
void swing_balance_step(const StepView& v, Boxer& b, double dt) {
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  eng::control::BalanceStep& s = st.step;
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  s.elapsed += dt;
  // Touch-down: the sole on a top past the swing's middle, or late: set down where it is. A top, not the ground: a
  // sole brushing a crate's side (the contact's normal level) would end the swing short, in the air
  // (docs/decisions/balance-steps.md).
  const bool down = b.ctl.contacts.on_top[s.foot] && s.elapsed > 0.6 * s.duration;
  const bool pushed = st.push_acc.norm() > t.push_acc && s.elapsed < t.push_replan_until * s.duration;
  if (!s.returning && (s.elapsed < t.replan_until * s.duration || pushed) && !v.corners[1 - s.foot].empty()) {
    // Re-planned from the body's state now, for the swing's time left (longer while the push still acts).
    std::vector<Eigen::Vector2d>& stance_hull = b.scratch.stance_hull;
    eng::control::convex_hull_2d(v.corners[1 - s.foot], stance_hull);
    eng::control::BalanceStepTuning left = t;
    left.min_duration = std::max(0.05, s.duration - s.elapsed);
    left.swing_speed = 1e9;  // the time left is what it is
    const eng::control::StepLanding land = eng::control::place_balance_step(
        b.settings.placement, v.com.head<2>(), v.vcom, v.omega, s.from, v.sole[1 - s.foot], stance_hull,
        b.stance.heading, &b.ctl.step_lqr, left);
    eng::control::replan_balance_step(s, land.to, v.ground, b.settings.tuning.foot, t.foothold, t);
  }
  if (down || s.elapsed > s.duration + t.late) {
    if (!down && !s.returning) ++b.metrics.late_landings;
    b.metrics.landing_miss_sum[s.returning] += (v.sole[s.foot] - s.to).norm();
    ++b.metrics.landings[s.returning];
    s.active = false;
    st.settled = 0.0;
    if (s.returning && t.replace_edge_foot && st.follow_ups < t.follow_ups && !st.recovering) {
      st.follow_up = true;
      ++st.follow_ups;
    }
  }
}

// PHASE 1, change of support: foot k (the one the push unloaded) steps to where the body can stop.
void start_recovery_step(const StepView& v, Boxer& b, int k) {
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  const std::vector<Eigen::Vector2d>* sole_hull = b.scratch.sole_hull;
  const eng::control::StepLanding land = eng::control::place_balance_step(
      b.settings.placement, v.com.head<2>(), v.vcom, v.omega, v.sole[k], v.sole[1 - k], sole_hull[1 - k],
      b.stance.heading, &b.ctl.step_lqr, t);
  eng::control::start_balance_step(st.step, k, false, v.sole[k], land.to, v.sole[1 - k], t.pass_clearance, v.yaw[k],
                                   land.duration, v.ground, b.settings.tuning.foot, t.foothold);
  ++st.steps_in_recovery;
  st.recovering = true;
  st.follow_up = false;
  st.follow_ups = 0;
  ++b.metrics.balance_steps;
  b.metrics.most_steps_in_recovery = std::max(b.metrics.most_steps_in_recovery, st.steps_in_recovery);
}

// PHASE 3's return: the foot r farther from the com goes back to where the stance has it relative to the other (the
// desired pose's feet, b.scratch.fk_P / fk_W posed by the caller); `to` is its landing. With
// BalanceStepTuning::return_onto_platform, the other foot returns instead where r's return would step off the
// platform and the other's would not.
void choose_return(const StepView& v, const Arena& arena, const Boxer& b, int& r, Eigen::Vector2d& to) {
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  const eng::control::FootGeometry& g = b.settings.tuning.foot;
  const int* feet = b.bones.foot;
  const Eigen::Vector2d* sole = v.sole;
  r = (v.com.head<2>() - sole[0]).norm() > (v.com.head<2>() - sole[1]).norm() ? 0 : 1;
  Eigen::Vector2d want[2];
  for (int j = 0; j < 2; ++j)
    want[j] = (b.scratch.fk_P[feet[j]] + b.scratch.fk_W[feet[j]] * g.centre).head<2>();
  to = sole[1 - r] + (want[r] - want[1 - r]);
  if (!t.return_onto_platform) return;
  // Off the platform: foot j's return to `at` lands on the floor (its foothold's top, as the step will find it)
  // while the stance foot stands on a crate (the top under its sole's centre).
  const auto off_platform = [&](int j, const Eigen::Vector2d& at) {
    eng::control::BalanceStep probe;
    eng::control::start_balance_step(probe, j, true, sole[j], at, sole[1 - j], t.pass_clearance,
                                     eng::control::heading_of(b.scratch.fk_W[feet[j]]), t.return_duration,
                                     v.ground, g, t.foothold);
    return arena.top_at(sole[1 - j].x(), sole[1 - j].y()) > kFloorTop && probe.to_top < kFloorTop;
  };
  const Eigen::Vector2d other = sole[r] + (want[1 - r] - want[r]);
  if (off_platform(r, to) && !off_platform(1 - r, other)) r = 1 - r, to = other;
}

// No return: a foot the recovery left on a poor foothold (an edge under its sole, by the clips' margins) steps onto
// the nearest good one, by the return's machinery (the weight shift, then the step), the foot farther from the com
// (r) first.
void replace_poor_foothold(const eng::physics::Data& d, const StepView& v, const Arena& arena, Boxer& b, int r) {
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  for (int j : {r, 1 - r}) {
    if (!on_poor_foothold(d, arena, b, j)) continue;
    // Searched at the heading the return step lands with (the desired pose's foot), where its own search (the
    // balance step's foothold) will find it good already.
    const double land_yaw = eng::control::heading_of(b.scratch.fk_W[b.bones.foot[j]]);
    const Eigen::Vector2d ankle = v.sole[j] - Eigen::Rotation2Dd(land_yaw) * b.settings.tuning.foot.centre.head<2>();
    const eng::control::Foothold fh = eng::control::find_foothold(v.ground, ankle, land_yaw, land_yaw, t.replace_foothold);
    if (!fh.found || fh.shift.norm() < 0.01) continue;
    st.shifting = j;
    st.shift_time = 0.0;
    st.return_to = v.sole[j] + fh.shift;
    ++b.metrics.replacements;
    break;
  }
}

// PHASE 2 (the QP's com task over the new support) until the com has all but stopped (`out`: how far the capture
// point is out of the feet's hull); then PHASE 3: the foot farther from the com steps back to its place in the stance
// (choose_return), after a weight shift over the other foot (the shorter shift of the two feet). The foot that moved
// last often stands under the com after a cross-over, and returning it first sends the com back over the other foot
// while the thighs stand crossed (docs/decisions/balance-steps.md). After a return or re-placement has landed
// (follow_up), the same look at the feet once more (BalanceStepTuning::follow_ups).
void settle_then_return(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, const StepView& v,
                        const Arena& arena, Boxer& b, double out, double dt) {
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  st.settled = v.vcom.norm() < t.settle_speed && out < 0.0 ? st.settled + dt : 0.0;
  if (st.settled > t.settle_time) {
    pose_fk(desc.skeleton, b.desired.pose, b.scratch.fk_W, b.scratch.fk_P);
    int r;
    Eigen::Vector2d to;
    choose_return(v, arena, b, r, to);
    if ((to - v.sole[r]).norm() > t.return_tolerance && !stance_can_fight(d, b) && b.settings.stepping) {
      st.shifting = r;  // first the weight goes over the other foot (shift_weight_for_return), then the foot steps
      st.shift_time = 0.0;
      st.return_to = to;
    } else if (t.replace_edge_foot && b.settings.stepping) {
      replace_poor_foothold(d, v, arena, b, r);
    }
    st.recovering = false;
    st.follow_up = false;
    st.steps_in_recovery = 0;
    st.settled = 0.0;
  }
}

// No step under way: the capture point out of the feet's hull starts one (PHASE 1); a recovery goes on to settle and
// return (PHASES 2 and 3).
void watch_capture_point(const eng::physics::Model& m, const eng::physics::Data& d,
                         const eng::assets::CharacterDesc& desc, const StepView& v, const Arena& arena, Boxer& b,
                         double dt) {
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  // The feet's contact hull and how far the capture point is out of it.
  std::vector<Eigen::Vector2d>& pts = b.scratch.pts;
  pts.clear();
  for (int k = 0; k < 2; ++k) pts.insert(pts.end(), v.corners[k].begin(), v.corners[k].end());
  eng::control::convex_hull_2d_in_place(pts, b.scratch.hull);
  const double out = eng::control::outside_distance(b.scratch.hull, v.xi);
  // The stepping foot: the one farther from the capture point; with one foot off the ground, Yin's rule (the push's
  // direction) says which the push unloaded.
  std::vector<Eigen::Vector2d>* sole_hull = b.scratch.sole_hull;
  for (int j = 0; j < 2; ++j) eng::control::convex_hull_2d(v.corners[j], sole_hull[j]);
  const int k = !v.corners[0].empty() && !v.corners[1].empty() ? eng::control::stepping_foot(sole_hull, v.xi)
                                                                : eng::control::unloaded_foot(v.vcom, v.sole);
  const std::vector<Eigen::Vector2d>& stance_pts = v.corners[1 - k];
  const double reach = t.assist_reach_share * assist_reach(m, b);  // what the root assist holds in place
  if (b.settings.stepping && out > t.trigger_margin + reach && v.vcom.norm() > t.min_speed && !stance_pts.empty() &&
      st.steps_in_recovery < t.max_steps) {
    start_recovery_step(v, b, k);
  } else if (st.recovering || st.follow_up) {
    settle_then_return(d, desc, v, arena, b, out, dt);
  }
}

// A footwork step (footwork.h; its own swing time) lifts once the weight is off the foot enough for a quick step: the
// capture point, with the centre of pressure held in the stance foot (its sole's centre) for the swing, ends inside the
// stance and landing soles together (the lift-off gate's quick-step test, Pratt et al. 2006 eq. 8 for xi(t)) and
// at least FootworkTuning::min_shift has passed. The recovery's return waits for the com at rest over the other foot
// (return_shift_margin, return_lift_speed): a second or two, where a boxer's step takes a fraction of one.
bool footwork_may_lift(Boxer& b, const StepView& v, const std::vector<Eigen::Vector2d>& stance_hull, int r) {
  const eng::control::BalanceStepState& st = b.ctl.balance_steps;
  const FootworkTuning& ft = b.settings.tuning.footwork;
  if (st.shift_time < ft.min_shift) return false;
  // Unweighted: the foot bears less than unload_share of the body's weight (the com over the other foot's side).
  if (b.ctl.contacts.normal_force[r] < ft.unload_share * b.control_body.total_mass * 9.81) return true;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : stance_hull) centre += p;
  centre /= static_cast<double>(stance_hull.size());
  const Eigen::Vector2d xi_end = eng::control::capture_point_after(v.xi, centre, v.omega, st.return_duration);
  const eng::control::SoleShape& sole = b.settings.tuning.step.foothold.sole;
  const Eigen::Rotation2Dd R(eng::control::heading_of(b.scratch.fk_W[b.bones.foot[r]]));
  std::vector<Eigen::Vector2d>& pts = b.scratch.pts;
  pts = stance_hull;
  const Eigen::Vector2d ankle = st.return_to - R * b.settings.tuning.foot.centre.head<2>();
  for (double x : {sole.heel, sole.toe})
    for (double y : {-sole.half_width, sole.half_width}) pts.push_back(ankle + R * Eigen::Vector2d(x, y));
  eng::control::convex_hull_2d_in_place(pts, b.scratch.hull);
  return eng::control::outside_distance(b.scratch.hull, xi_end) < -ft.lift_margin;
}

// The return step's weight shift (a loaded foot lifted at once tips the body over it): the QP's com target goes over
// the other foot (the lift-off gate's `holding`) until the capture point is inside its sole; then the return step
// starts. True while the weight is still shifting (the foot held down).
bool shift_weight_for_return(const eng::assets::CharacterDesc& desc, const StepView& v, Boxer& b, bool swing[2],
                             double dt) {
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  const int r = st.shifting;
  st.shift_time += dt;
  std::vector<Eigen::Vector2d>& other = b.scratch.stance_hull;
  eng::control::convex_hull_2d(v.corners[1 - r], other);
  if (st.shift_time > t.return_shift_max || other.empty() || st.step.active) {
    st.shifting = -1;
    st.return_duration = 0.0;
  } else if (st.return_duration > 0.0 ? footwork_may_lift(b, v, other, r)
                                       : eng::control::outside_distance(other, v.xi) < -t.return_shift_margin &&
                                             v.vcom.norm() < t.return_lift_speed) {
    pose_fk(desc.skeleton, b.desired.pose, b.scratch.fk_W, b.scratch.fk_P);
    eng::control::start_balance_step(st.step, r, true, v.sole[r], st.return_to, v.sole[1 - r], t.pass_clearance,
                                     eng::control::heading_of(b.scratch.fk_W[b.bones.foot[r]]),
                                     st.return_duration > 0.0 ? st.return_duration : t.return_duration, v.ground,
                                     b.settings.tuning.foot, t.foothold);
    ++b.metrics.return_steps;
    st.step.quick = st.return_duration > 0.0;
    st.shifting = -1;
    st.return_duration = 0.0;
  } else {
    swing[r] = false;
    b.ctl.gate[r].holding = true;
    return true;
  }
  return false;
}

// The step overrides the clip's feet: the stepping foot swings to the step's target, the other stays planted.
void override_clip_feet(Boxer& b, bool swing[2]) {
  const eng::control::BalanceStep& s = b.ctl.balance_steps.step;
  const eng::control::BalanceStepTuning& t = b.settings.tuning.balance_step;
  const int k = s.foot;
  Eigen::Vector3d velocity, acceleration;
  const Eigen::Vector3d target = eng::control::balance_step_sole_target(s, t, &velocity, &acceleration);
  const Eigen::Quaterniond R(Eigen::AngleAxisd(s.yaw, Eigen::Vector3d::UnitZ()));
  eng::control::StepPlan& plan = b.ctl.step[k];
  plan.active = true;
  plan.carried = plan.landed = false;  // a carried step it interrupts is over
  plan.target = target - R * b.settings.tuning.foot.sole_offset();
  plan.clip_z = plan.target.z();
  plan.has_velocity = true;
  plan.velocity = velocity;
  plan.acceleration = acceleration;
  b.ctl.step[1 - k].active = false;
  swing[k] = true;
  swing[1 - k] = false;
  for (eng::control::LiftGate& gate : b.ctl.gate) gate = {};
}

}  // namespace

// BALANCE STEPS (balance_step.h): Yin & van de Panne's three phases on the balance QP. Measurements:
// docs/decisions/balance-steps.md.
void take_balance_steps(const eng::physics::Model& m, const eng::physics::Data& d,
                        const eng::assets::CharacterDesc& desc, const Arena& arena, Boxer& b, bool swing[2], double dt) {
  eng::control::BalanceStepState& st = b.ctl.balance_steps;
  if (b.limp || b.ctl.state.fallen() || b.ctl.state.state == BoxerState::GettingUp) {
    st = {};
    return;
  }
  if (!b.settings.stepping && !st.step.active && st.shifting < 0) return;  // --stepping off: in place
  const StepView v = view_for_steps(m, d, arena, b);
  if (st.step.active)
    swing_balance_step(v, b, dt);
  else
    watch_capture_point(m, d, desc, v, arena, b, dt);
  if (footwork_busy(b)) {
    // The deliberate steps (footwork.h) go through the return's machinery: where the desired pose has the soles.
    pose_fk(desc.skeleton, b.desired.pose, b.scratch.fk_W, b.scratch.fk_P);
    Eigen::Vector2d want[2];
    for (int j = 0; j < 2; ++j)
      want[j] = (b.scratch.fk_P[b.bones.foot[j]] + b.scratch.fk_W[b.bones.foot[j]] * b.settings.tuning.foot.centre).head<2>();
    footwork_steps(arena, b, v.sole, want);
  }
  if (st.shifting >= 0 && !st.step.active && shift_weight_for_return(desc, v, b, swing, dt)) return;
  if (!st.step.active) return;
  override_clip_feet(b, swing);
}

}  // namespace boxing
