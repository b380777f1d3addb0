#pragma once
// STEPS ON UNEVEN GROUND. When the clip lifts a foot, look ahead in the clip for where it puts it down (the first
// frame whose sole is back within swing_lift of the clip's floor: find_touchdown), place that landing on the ground
// the way the current pose is placed (same heading), and find the smallest shift that lands the sole flat on one
// top (foothold.h): start_step. During the swing the ankle target is the clip's, plus the shift eased in over the
// swing (C1 ease, complete at the clip's touch-down), at the clip's lift above the highest of the tops under the
// foot, under the shifted target and at the landing (the toe clears a higher top's edge before it gets there), and
// pressed swing_press below it unless stepping up (a boxer's shuffle: the sole slides along its top): advance_step.
// CARRIED STEPS (StepTuning::carry, --footwork carry): the pressed sole drags and carries the foot a tenth of the
// clip's travel. A carried step instead swings the foot along its own path (a balance step's, balance_step.h: lift,
// travel, set down, its velocity fed forward) from where it is to where the clip puts it relative to the stance foot
// at touch-down (so a stance the crates stretched or closed comes back to the clip's), on a foothold that prefers a
// shorter step to a longer one, and owns the foot until it touches a top. Measurements: docs/decisions/footwork.md.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "engine/anim/skeleton.h"
#include "engine/control/biped/balance_step.h"
#include "engine/control/biped/foot_geometry.h"
#include "engine/control/biped/foothold.h"
#include "engine/control/biped/ground.h"

namespace eng::control {

struct StepTuning {
  double swing_lift = 0.015;         // m, a clip sole higher than this above its floor is swinging (the step's lift)
  double lookahead = 0.8;            // s, how far ahead a step's touch-down is looked for (60 Hz frames)
  double swing_press = 0.10;         // m, a stepping ankle aimed this far below the clip's: the sole shuffles along its top
  double step_up_tolerance = 0.01;   // m, a landing top higher than the start's by more is a step up (no press)
  FootholdParams foothold;           // the landing's search
  // Carried steps (off: the shuffle above). A clip step travelling at least carry_min_travel swings on its own path,
  // carry_lift over the highest top on its way and set down carry_press into its landing top; a swing that must rise
  // takes at least (rise + lift) / carry_rise_speed (a shuffle's 0.13 s rises too late: the heel catches a higher
  // crate's edge), and past a higher top's edge it rises at that speed and travels once
  // carry_edge_clearance above the top; the landing relative to the stance foot unless that lands more than
  // carry_max_extra farther than the clip's travel from the foot (the body has turned off the stance's heading).
  bool carry = false;
  double carry_min_travel = 0.04;   // m
  double carry_lift = 0.04;         // m
  double carry_press = 0.02;        // m
  double carry_rise_speed = 0.6;    // m/s
  double carry_max_extra = 0.12;    // m
  double carry_edge_clearance = 0.02;  // m, a sole rising past a higher top travels once this far above it
  double carry_late = 0.15;         // s, a carried swing not down this long after its duration is set down anyway
  double carry_in_place = 0.02;     // m, a carried landing this near where the foot stands is not stepped (the gate's)
  double carry_pass_clearance = 0.16;  // m, the path bent around the stance foot (balance_step.h)
  // A carried step the lift-off gate held for its weight shift lifts as the clip's whole step (false: what is left of
  // its travel and swing, often too little to carry: the foot stays and the stance stretches)
  bool carry_whole = true;
  // The carried landing's foothold: the balance steps' margins, and a shift away from the stance foot costs 4 times
  // one toward it (a landing shifted farther stretches the stance, and the next steps fall out of it)
  FootholdParams carry_foothold = {.side_margin = 0.035, .back_cost = 4.0, .clearance = 0.05, .sole = {}};
};

// The clip's sole above its floor: the lower of the heel's and toe's heights (clip floor frame, z = 0 the floor).
double clip_sole_gap(const std::vector<Eigen::Quaterniond>& W, const std::vector<Eigen::Vector3d>& P, int foot,
                     const FootGeometry& g);

// Where and when the clip puts a lifted foot down again: ahead (s), travel = landing - now (clip floor frame, x y),
// yaw = the foot's heading there (clip frame). When no frame within lookahead touches down: the last frame looked at.
struct Touchdown {
  double ahead = 0.0;
  Eigen::Vector2d travel = Eigen::Vector2d::Zero();
  double yaw = 0.0;
  Eigen::Vector2d apart = Eigen::Vector2d::Zero();  // the landing ankle less the other ankle then (clip floor frame)
};

// preview(ahead, out): the clip's pose `ahead` seconds after now (clip floor frame). W, P: scratch.
template <class Preview>
Touchdown find_touchdown(const anim::Skeleton& skel, const Preview& preview, int foot, const FootGeometry& g,
                         const StepTuning& t, std::vector<Eigen::Quaterniond>& W, std::vector<Eigen::Vector3d>& P);

// One foot's step: where the clip will put it down (world x, y of the ankle), the foothold shift, the swing's
// timing, and this tick's ankle target (world) and its clip-floor height (a feed-forward's height).
struct StepPlan {
  bool active = false;
  Eigen::Vector2d landing = Eigen::Vector2d::Zero(), shift = Eigen::Vector2d::Zero();
  double duration = 0.0, elapsed = 0.0;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double clip_z = 0.0;
  bool step_up = false;  // the landing top is higher than the one the foot leaves (no shuffle, it lifts over)
  bool has_velocity = false;  // a balance or carried step: the target's velocity, from its path (world, m/s) ...
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // ... and its acceleration (m/s^2)
  bool carried = false;  // a carried step (StepTuning::carry): the target is path's, and the step owns the foot ...
  bool landed = false;   // ... until it touches down; then the clip's swing is ignored until it ends
  BalanceStep path;
};

// Starts a step: ankle_placed = the placed desired pose's ankle now (world), heading = the placement's heading (rad),
// foot_centre_now = the physical foot's sole centre (world, where it steps from). A carried step also takes the
// stance foot's ankle and sole centre (world x, y).
void start_step(StepPlan& st, const Touchdown& td, const Eigen::Vector3d& ankle_placed, double heading,
                const Eigen::Vector3d& foot_centre_now, GroundHeight ground, const FootGeometry& g,
                const StepTuning& t, double dt, const Eigen::Vector2d& stance_ankle = Eigen::Vector2d::Zero(),
                const Eigen::Vector2d& stance_centre = Eigen::Vector2d::Zero());

// Advances a step by dt: the target from the placed desired ankle (world position and foot orientation).
void advance_step(StepPlan& st, const Eigen::Vector3d& ankle_placed, const Eigen::Quaterniond& foot_placed,
                  GroundHeight ground, const FootGeometry& g, const StepTuning& t, double dt);

}  // namespace eng::control

#include "engine/control/servo/person_space.h"
#include "engine/control/servo/world_pose.h"

namespace eng::control {

template <class Preview>
Touchdown find_touchdown(const anim::Skeleton& skel, const Preview& preview, int foot, const FootGeometry& g,
                         const StepTuning& t, std::vector<Eigen::Quaterniond>& W, std::vector<Eigen::Vector3d>& P) {
  Touchdown td;
  pose_fk(skel, preview(0.0), W, P);
  const Eigen::Vector2d now_clip = P[foot].head<2>();
  for (int i = 1; i * (1.0 / 60.0) <= t.lookahead; ++i) {
    td.ahead = i / 60.0;
    pose_fk(skel, preview(td.ahead), W, P);
    td.travel = P[foot].head<2>() - now_clip;
    td.yaw = heading_of(W[foot]);
    if (clip_sole_gap(W, P, foot, g) <= t.swing_lift) break;
  }
  return td;
}

}  // namespace eng::control
