// The boxer's measurements after each step (report metrics: observe only; the fall detection that control reads is
// detect_fall, game/fall_detection.cpp).
#include <algorithm>
#include <cmath>

#include "engine/control/servo/orientation_error.h"
#include "engine/control/servo/world_pose.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/overlap.h"
#include "game/boxer.h"

namespace boxing {

using eng::control::pose_fk;

void boxer_sense_contacts(const eng::physics::Data& d, Boxer& b) {
  eng::control::find_foot_contacts(d.contacts, b.bodies.body, b.bones, b.settings.tuning.contact, b.ctl.contacts);
}

namespace {

// BoxerMetrics::legs_overlap_*: every left-leg geom against every right-leg one (3 x 3 at most), the legs' bones from
// b.bones and their geoms from the character's per-bone geom ranges (listed on the first sample).
void measure_legs_overlap(const eng::physics::Model& m, const eng::physics::Data& d, Boxer& b, double dt) {
  BoxerMetrics& mt = b.metrics;
  if (mt.leg_geoms[0].empty()) list_leg_geoms(b, mt.leg_geoms);
  const double deepest = eng::physics::deepest_overlap(m, d, mt.leg_geoms[0], mt.leg_geoms[1]);
  mt.legs_overlap_max = std::max(mt.legs_overlap_max, deepest);
  if (deepest > BoxerMetrics::kLegsOverlap) mt.legs_overlap_s += dt;
  const int tl = b.bodies.body[b.bones.leg[0].thigh], tr = b.bodies.body[b.bones.leg[1].thigh];
  for (const eng::physics::Contact& c : d.contacts)
    if (((c.body_a == tl && c.body_b == tr) || (c.body_a == tr && c.body_b == tl)) && eng::physics::is_touching(c)) {
      mt.thighs_touch_s += dt;
      break;
    }
}

// The tracking error in world orientation against the desired pose lifted with the desired root, per bone: summed
// over every sample, and over the samples before the first fall.
void measure_tracking(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, Boxer& b) {
  BoxerMetrics& mt = b.metrics;
  const auto& skel = desc.skeleton;
  const int n = skel.size();
  if (mt.err_sq_sum.empty()) mt.err_sq_sum.assign(n, 0.0);
  eng::control::lift_to_world(skel, b.desired.pose, b.desired.pose.rotation[0], b.scratch.W_d_metric);
  if (mt.err_sq_upright.empty()) mt.err_sq_upright.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const Eigen::Quaterniond Wa(d.x[b.bodies.body[i]].R);
    const double e2 = eng::control::orientation_error(b.scratch.W_d_metric[i], Wa).squaredNorm();
    mt.err_sq_sum[i] += e2;
    if (!mt.fell) mt.err_sq_upright[i] += e2;
  }
  ++mt.samples;
  if (!mt.fell) ++mt.samples_upright;
}

// The root assist's torque (upright) and the upper arms' error from the servo's pose (BoxerMetrics::arm_*).
void measure_root_and_arms(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, Boxer& b, double dt) {
  BoxerMetrics& mt = b.metrics;
  if (!mt.fell) {
    const double t = b.ctl.root_torque.norm();
    mt.root_torque_sq_dt += t * t * dt;
    mt.root_torque_peak = std::max(mt.root_torque_peak, t);
    if (b.settings.root_params.enabled && t >= 0.999 * b.settings.root_params.max_torque) mt.root_saturated_time += dt;
  }
  if (b.limp) return;  // (a limp body has no servo pose)
  if (mt.upper_arm[0] < 0)
    for (int k = 0; k < 2; ++k) mt.upper_arm[k] = desc.skeleton.find(k == 0 ? "upper_arm_l" : "upper_arm_r");
  double worst = 0.0;
  for (int k = 0; k < 2; ++k) {
    const int i = mt.upper_arm[k];
    if (i < 0 || size_t(i) >= b.ctl.servo.W_d.size()) continue;
    const Eigen::Quaterniond Wa(d.x[b.bodies.body[i]].R);
    worst = std::max(worst, eng::control::orientation_error(b.ctl.servo.W_d[i], Wa).norm());
  }
  mt.arm_error_end = worst;
  if (b.ctl.state.state == BoxerState::Guard && worst > BoxerMetrics::kArmOffPose) mt.arm_off_guard_s += dt;
}

// The planted feet's slide (BoxerMetrics::foot_slide), and how much of its travel a clip's step covered once planted.
void measure_foot_slide(const eng::physics::Data& d, Boxer& b) {
  BoxerMetrics& mt = b.metrics;
  for (int k = 0; k < 2; ++k) {
    const int fb = b.bodies.body[b.bones.foot[k]];
    const Eigen::Vector2d sole = (d.x[fb].p + d.x[fb].R * b.settings.tuning.foot.centre).head<2>();
    const eng::control::BalanceStep& step = b.ctl.balance_steps.step;
    const bool carried = b.ctl.step[k].active || (step.active && step.foot == k);
    const bool down = b.ctl.contacts.on_ground[k] && !carried && !mt.fell && !b.limp;
    if (down && !mt.foot_was_down[k]) {
      mt.foot_anchor[k] = sole;
      if (mt.step_pending[k]) {  // a clip's step planted: how much of its travel it covered
        const Eigen::Vector2d& u = mt.step_travel[k];
        const double f = (sole - mt.step_from[k]).dot(u) / u.squaredNorm();
        ++mt.step_travel_count, mt.step_travel_sum += f, mt.step_travel_sq += f * f;
        mt.steps_landed_in_place += (sole - mt.step_from[k]).norm() < BoxerMetrics::kInPlace;
        mt.step_pending[k] = false;
      }
    }
    if (!down && mt.foot_was_down[k]) mt.foot_slide_closed[k] = mt.foot_slide[k];
    if (down) mt.foot_slide[k] = mt.foot_slide_closed[k] + (sole - mt.foot_anchor[k]).norm();
    mt.foot_was_down[k] = down;
  }
}

// The diagnostic trace (BoxerMetrics::trace): every 0.05 s for the first 4 s, and once at the first fall.
void trace_diagnostics(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, Boxer& b,
                       const Eigen::Vector3d& com, double dt) {
  BoxerMetrics& mt = b.metrics;
  const int pelvis = b.bodies.body[0];
  const double support = std::min(b.stance.lead_top, b.stance.rear_top);
  const int* feet = b.bones.foot;
  if (mt.samples == 1)
    for (int k = 0; k < 2; ++k) mt.foot0[k] = d.x[b.bodies.body[feet[k]]].p;
  const long every = std::lround(0.05 / dt);
  const bool fall_now = mt.fell && !mt.traced_fall;
  if ((d.time < 4.0 && mt.samples % every == 0) || fall_now) {
    if (fall_now) mt.traced_fall = true;
    std::vector<Eigen::Quaterniond> Wd;
    std::vector<Eigen::Vector3d> Pd;
    pose_fk(desc.skeleton, b.desired.pose, Wd, Pd);
    std::array<double, 12> r{};
    r[0] = d.time;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double fz = 0;
    Eigen::Vector3d cop = Eigen::Vector3d::Zero();
    for (int k = 0; k < 2; ++k) {
      const int fb = b.bodies.body[feet[k]];
      const Eigen::Matrix3d R = d.x[fb].R;
      const Eigen::Vector3d fa = R.col(0), fd = Wd[feet[k]] * Eigen::Vector3d::UnitX();
      r[1 + k] = std::remainder(std::atan2(fa.y(), fa.x()) - std::atan2(fd.y(), fd.x()), 2 * M_PI) * 180 / M_PI;
      r[3 + k] = std::acos(std::clamp((R * Eigen::Vector3d::UnitZ()).z(), -1.0, 1.0)) * 180 / M_PI;
      // rear (right) foot: sole normal's lean forward / left (heading frame, deg) in the slip columns
      const Eigen::Vector2d up = Eigen::Rotation2Dd(-b.stance.heading) * (R * Eigen::Vector3d::UnitZ()).head<2>();
      if (k == 1) r[5] = std::asin(std::clamp(up.x(), -1.0, 1.0)) * 180 / M_PI, r[6] = std::asin(std::clamp(up.y(), -1.0, 1.0)) * 180 / M_PI;
      centre += 0.5 * (d.x[fb].p + R * Eigen::Vector3d(0.05, 0, 0));
      for (const auto& c : d.contacts) {
        const double f = c.body_b == fb ? c.force.z() : (c.body_a == fb ? -c.force.z() : 0.0);
        if (f == 0.0) continue;
        cop += f * c.point.position;
        fz += f;
      }
    }
    const Eigen::Rotation2Dd toh(-b.stance.heading);
    const Eigen::Vector2d ce = toh * (com - centre).head<2>();
    r[7] = ce.x(), r[8] = ce.y();
    if (fz > 1e-6) {
      const Eigen::Vector2d cp = toh * (cop / fz - centre).head<2>();
      r[9] = cp.x(), r[10] = cp.y();
    }
    r[11] = d.x[pelvis].p.z() - support;
    mt.trace.push_back(r);
  }
}

}  // namespace

void boxer_measure(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   Boxer& b, double dt) {
  BoxerMetrics& mt = b.metrics;
  const int pelvis = b.bodies.body[0];
  measure_tracking(d, desc, b);
  measure_root_and_arms(d, desc, b, dt);
  measure_foot_slide(d, b);
  // The com's velocity from the body's momentum, not differenced positions: the match's referee sets a boxer on its
  // mark (a pose set directly), and differenced, that jump reads as hundreds of m/s.
  const Eigen::Vector3d com = eng::physics::subtree_com(m, d, pelvis);
  const Eigen::Vector3d vcom = eng::physics::spatial_momentum(m, d, pelvis).tail<3>() / b.control_body.total_mass;
  mt.max_com_speed = std::max(mt.max_com_speed, vcom.norm());
  // On its feet (guard or stunned: a match boxer after a get-up too; not falling, down or in the stand-up's kneel).
  const BoxerState state = b.ctl.state.state;
  if (!b.limp && (state == BoxerState::Guard || state == BoxerState::Stunned)) measure_legs_overlap(m, d, b, dt);
  trace_diagnostics(d, desc, b, com, dt);
}

}  // namespace boxing
