// The boxer's steps (balance QP): the clip's floor under the feet, lift-off gating and the step planner, from the
// biped units in engine/control/biped/.
#include "game/boxer_stepping.h"

#include <algorithm>
#include <cmath>

#include "engine/control/biped/capture_point.h"
#include "engine/control/servo/world_pose.h"
#include "engine/physics/dynamics.h"
#include "game/boxer.h"

namespace boxing {

using eng::control::pose_fk;

// The clip's floor under the actual feet (balance QP's steps): b.ctl.support_base.
void update_support_base(const eng::physics::Data& d, const Arena& arena, Boxer& b, double dt) {
  // The clip's floor: the lower of the crate tops under the two feet where they actually are, low-passed
  // (StanceTuning::base_tau) so a swing foot passing over another crate does not jerk the desired root up or down. The stance's
  // crates only hold until the first step: after one the root was placed for crates the feet had left (a leg
  // over-stretched above a lower crate, or crouched on a higher one).
  double lowest = 1e9;
  for (int f : b.bones.foot) {
    const int fb = b.bodies.body[f];
    const Eigen::Vector3d c = d.x[fb].p + d.x[fb].R * b.settings.tuning.foot.centre;
    lowest = std::min(lowest, arena.top_at(c.x(), c.y()));
  }
  if (!b.ctl.have_support_base) b.ctl.support_base = std::min(b.stance.lead_top, b.stance.rear_top), b.ctl.have_support_base = true;
  b.ctl.support_base += (1.0 - std::exp(-dt / b.settings.tuning.stance.base_tau)) * (lowest - b.ctl.support_base);
}

// Where and when the clip puts foot k down again (step_planner.h), from the pose source's preview.
namespace {
eng::control::Touchdown touchdown_of(const eng::anim::Skeleton& skel, Boxer& b, int k) {
  const auto preview = [&b](double ahead) -> const eng::anim::Pose& { return b.source.preview(ahead); };
  return eng::control::find_touchdown(skel, preview, b.bones.foot[k], b.settings.tuning.foot, b.settings.tuning.step, b.scratch.fk_W, b.scratch.fk_P);
}

}  // namespace

// LIFT-OFF GATING (balance QP, lift_off_gate.h): the capture point over the other foot's touching contacts decides
// whether a foot the clip lifts may leave the ground. Measurements: docs/decisions/lift-off-gate.md.
void gate_lift_off(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   Boxer& b, bool swing[2], double dt) {
  const auto& skel = desc.skeleton;
  const int pelvis = b.bodies.body[0];
  for (int k = 0; k < 2; ++k) {
    if (!eng::control::lift_off_gate_due(b.ctl.gate[k], swing[k], !b.ctl.state.fallen())) continue;
    // The other (stance) foot's ground contacts and the capture point.
    const std::vector<Eigen::Vector2d>& stance = b.ctl.contacts.ground_points[1 - k];
    Eigen::Vector2d xi = Eigen::Vector2d::Zero();
    if (stance.size() >= 2) {
      const Eigen::Vector3d com = eng::physics::subtree_com(m, d, pelvis);
      const eng::physics::Vec6 h = eng::physics::spatial_momentum(m, d, pelvis);
      const Eigen::Vector3d vcom = h.tail<3>() / b.control_body.total_mass;
      const double z = std::max(0.3, com.z() - b.ctl.support_base);
      xi = eng::control::capture_point(com.head<2>(), vcom.head<2>(), z);
    }
    const double swing_left = touchdown_of(skel, b, k).ahead;
    const eng::control::GateEvent e =
        eng::control::lift_off_gate_decide(b.ctl.gate[k], swing[k], stance, xi, swing_left, dt, b.settings.tuning.gate, b.scratch.hull);
    if (e == eng::control::GateEvent::StepTaken) ++b.metrics.steps_taken;
    if (e == eng::control::GateEvent::StepSkipped) ++b.metrics.steps_skipped;
  }
}

// STEPS ON THE CRATES (balance QP, step_planner.h): a foot the clip just lifted starts a step toward a foothold on
// the crates; every swinging foot's ankle target advances.
void plan_steps(const eng::physics::Data& d, const eng::assets::CharacterDesc& desc, const Arena& arena, Boxer& b,
                const bool swing[2], double dt) {
  const auto& skel = desc.skeleton;
  const int* feet = b.bones.foot;
  std::vector<Eigen::Quaterniond>& W = b.scratch.fk_W;
  std::vector<Eigen::Vector3d>& P = b.scratch.fk_P;
  // A foot the clip just lifted: where (clip floor frame) and when the clip puts it down again.
  bool starts[2] = {false, false};
  eng::control::Touchdown td[2];
  for (int k = 0; k < 2; ++k) {
    if (!swing[k]) b.ctl.step[k].active = false;
    if (!swing[k] || b.ctl.step[k].active) continue;
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
      const int fb = b.bodies.body[feet[k]];
      const Eigen::Vector3d from = d.x[fb].p + d.x[fb].R * b.settings.tuning.foot.centre;
      eng::control::start_step(st, td[k], P[feet[k]], b.stance.heading, from, ground, b.settings.tuning.foot, b.settings.tuning.step, dt);
    }
    eng::control::advance_step(st, P[feet[k]], W[feet[k]], ground, b.settings.tuning.foot, b.settings.tuning.step, dt);
  }
}

}  // namespace boxing
