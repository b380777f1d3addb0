#pragma once
// A boxer: its bodies in the physics model, its pose source (a keyframed clip, later the motion graph), the servo
// that turns the desired pose into torques, its balance controller, its state (guard, down, ...) and the
// measurements the scenarios report. Composition: settings (configuration, read every tick), controller state,
// scratch, metrics (observe only: control never reads them).
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/anim/clip.h"
#include "engine/assets/character.h"
#include "engine/control/biped/balance_step.h"
#include "engine/control/biped/biped_bones.h"
#include "engine/control/biped/foot_contacts.h"
#include "engine/control/biped/foot_geometry.h"
#include "engine/control/biped/leg_ik.h"
#include "engine/control/biped/lift_off_gate.h"
#include "engine/control/biped/step_planner.h"
#include "engine/control/servo/controller.h"
#include "engine/control/servo/implicit_servo.h"
#include "engine/control/servo/inertial_servo.h"
#include "engine/control/servo/root_spring.h"
#include "engine/physics/data.h"
#include "engine/physics/model.h"
#include "game/arena.h"
#include "game/balance/balance_controller.h"
#include "game/boxer_state.h"
#include "game/boxer_tuning.h"
#include "game/character_builder.h"
#include "game/match/punch_aim.h"
#include "game/pose_source.h"

namespace boxing {

struct BoxerMetrics {
  bool fell = false;
  double fell_at = -1.0;
  std::string fell_reason;
  Eigen::Vector3d fell_pelvis = Eigen::Vector3d::Zero();  // where the pelvis was at the fall (world, m)
  double time_upright = 0.0;
  int steps_taken = 0, steps_skipped = 0;  // balance QP: the clip's steps lifted off / held down (gate_lift_off)
  int steps_in_place = 0;  // carried footwork: the clip's steps not taken, their landing where the foot stands
  int steps_landed_in_place = 0;  // of the steps step_travel follows: set down within kInPlace of their lift-off
  static constexpr double kInPlace = 0.02;  // m
  // How far the clip's steps carried the feet: per step lifted (its clip travel over kStepTravelMin), the foot's
  // displacement from lift-off to its next planting along the clip's travel, as a fraction of it (1: where the clip
  // puts it). Summed here, the report gives the mean (boxers[i].step_travel).
  static constexpr double kStepTravelMin = 0.08;  // m
  int step_travel_count = 0;
  double step_travel_sum = 0.0, step_travel_sq = 0.0;
  bool step_pending[2] = {false, false};
  Eigen::Vector2d step_from[2] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};  // sole centre at lift-off
  Eigen::Vector2d step_travel[2] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};  // the clip's (world)
  int balance_steps = 0, return_steps = 0;  // balance QP: steps the balance took (balance_step.h), steps back to the stance
  int most_steps_in_recovery = 0;           // the longest multi-step recovery
  int late_landings = 0;  // balance steps set down by time, their sole not on a top (BalanceStepTuning::late)
  // re-placements of a foot a recovery left on an edge, started (BalanceStepTuning::replace_edge_foot: the weight shift,
  // then a return step, counted in return_steps, unless the shift is given up)
  int replacements = 0;
  // How far each landing's sole centre came down from where its step planned it (the last re-plan's foothold; m),
  // summed, and the landings counted: [0] a balance step's (phase 1), [1] a return step's.
  double landing_miss_sum[2] = {0.0, 0.0};
  int landings[2] = {0, 0};
  double max_com_speed = 0.0;
  // The legs' clearance: of a boxer's own geoms only the thighs collide with each other (add_boxer), so a shank or a
  // foot swung through the stance leg passes through it with nothing but the balance QP's leg clearance (a soft task,
  // BalanceQpTuning::leg_clearance*) to stop it. The deepest overlap of a left-leg geom
  // (thigh, shank, foot) with a right-leg one on its feet (guard or stunned; m), the time spent overlapping more than
  // kLegsOverlap (s), and the time the thighs touch (a contact between them that touches, physics::is_touching: not
  // only a speculative one within the contact margin; on its feet; s).
  static constexpr double kLegsOverlap = 0.01;  // m
  double legs_overlap_max = 0.0, legs_overlap_s = 0.0, thighs_touch_s = 0.0;
  std::vector<int> leg_geoms[2];  // the model's geoms of each leg (found on the first sample)
  // How far each foot's sole centre slid over the ground while planted, upright (m): per planting (the foot on the
  // ground, no step carrying it) the distance from where it was set down to where it is or lifted, summed over the
  // plantings (net, so the contact's sub-millimetre jitter does not add up). The graph walks' rear foot slid
  // 0.2-1.0 m in 10 minutes under the rear-hand punches until the plan kept the ankles off their limits; 0.05-0.5 m
  // since (docs/decisions/foot-slide.md).
  double foot_slide[2] = {0.0, 0.0};
  double foot_slide_closed[2] = {0.0, 0.0};  // the plantings that ended
  Eigen::Vector2d foot_anchor[2] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};  // where this planting began
  bool foot_was_down[2] = {false, false};
  // The upper arms against the pose the servo tracks (b.ctl.servo.W_d): time in guard with either more than
  // kArmOffPose off (an arm left spread, or swung as a reaction wheel), and the larger error at the last sample.
  static constexpr double kArmOffPose = 1.5;  // rad
  double arm_off_guard_s = 0.0, arm_error_end = 0.0;
  int upper_arm[2] = {-1, -1};  // the skeleton's upper arms (found on the first sample)
  // Root spring use (external torque on the pelvis, no reaction): sum of |tau|^2 dt, peak |tau|, time at its limit.
  double root_torque_sq_dt = 0.0, root_torque_peak = 0.0, root_saturated_time = 0.0;
  std::vector<double> err_sq_sum;  // per bone, world orientation tracking error^2 (rad^2)
  long samples = 0;
  std::vector<double> err_sq_upright;  // the same, only the samples before the first fall
  long samples_upright = 0;
  // Diagnostic trace, in the report as boxers[i].trace (first 4 s at 20 Hz, plus the sample at the fall). Columns:
  // t, foot yaw error l/r (deg, actual - desired heading), foot tilt l/r (deg), the right (rear) sole normal's lean
  // forward / left (deg, heading frame), com - support centre (x, y; heading frame, m; centre = mid of the two
  // sole centres), centre of pressure of the feet's contact forces - support centre (x, y; 0 = no foot force),
  // pelvis height above the lower crate (m).
  std::vector<std::array<double, 12>> trace;
  Eigen::Vector3d foot0[2];
  bool traced_fall = false;
};

// Configuration: set at setup (world.cpp), read every tick (a panel may edit it live).
struct BoxerSettings {
  eng::control::ServoSpace space = eng::control::ServoSpace::World;
  eng::control::ServoGains gains;
  eng::control::MeathookParams hook;
  eng::control::RootSpringParams root_params;  // enabled per scenario (world.cpp), off = no root help
  BoxerTuning tuning;                          // every tuning value of the boxer's control (boxer_tuning.h)
  bool balance_qp = true;  // the balance QP where the servo space allows (world / person), else the PD layer
  bool stepping = true;    // balance QP: balance steps when the capture point leaves the feet (--stepping)
  eng::control::StepPlacement placement = eng::control::StepPlacement::CapturePoint;  // where (--step-placement)
};

// Controller state carried from tick to tick.
struct BoxerControlState {
  eng::control::ServoState servo;
  eng::control::RootSpring root_spring;
  Eigen::Vector3d root_torque = Eigen::Vector3d::Zero();  // applied this tick (for the metrics)
  Eigen::Vector3d root_force = Eigen::Vector3d::Zero();   // the stand-up's root assist force this tick (stand_up.h)
  // The pose source's clip played at this share of its speed (1 = as authored; the walk ticks dt x this): standing, a
  // tired boxer's punch plays slower (the match, game/match/stamina.h); getting up, the unassisted get-up's plan slows
  // and holds its clip while the body catches up (getup_plan.h, set by the balance for the next tick).
  double clip_rate = 1.0;
  // World / Person space: eq. 3 as implicit joint springs rooted at the feet (implicit_servo.h). Per skeleton
  // bone: the joint's servo (gains also written into the Model's Body::stiffness/damping at build time).
  std::vector<eng::control::ImplicitServoJoint> joints;
  BalanceController balance;  // PD or QP (balance_controller.h), with its own state
  eng::control::FootContacts contacts;  // of the last physics step (boxer_sense_contacts)
  // Balance QP: the step each foot is taking (step_planner.h) and its lift-off gate (lift_off_gate.h).
  eng::control::StepPlan step[2];
  eng::control::LiftGate gate[2];
  // The clip's step as it was when the clip lifted the foot (StepTuning::carry_whole): its whole travel and swing.
  std::optional<eng::control::Touchdown> clip_step[2];  // none: the clip's step not seen yet
  eng::control::BalanceStepState balance_steps;  // balance QP: the balance's own steps (balance_step.h)
  FootworkState footwork;  // the deliberate steps under way (footwork.h)
  eng::control::CartPoleLqr step_lqr;            // StepPlacement::InvertedPendulumLqr's gain (solved at setup)
  // The player's hands (or the chaos soak's) hold or push one of its bodies until this time (s; step_world): the
  // balance QP's Kudoh priorities stay off meanwhile (qp_balance.h BalanceQpTuning::trunk_weight).
  double handled_until = -1.0;
  double support_base = 0.0;  // balance QP: the clip's floor height under the actual feet (low-passed)
  bool have_support_base = false;
  double person_heading = 0.0;  // person space: low-passed pelvis heading (boxer_control)
  bool have_person_heading = false;
  // Where the desired motion sits on the crates (boxer_control): the horizontal offset (world, m) that keeps the
  // clip's planted feet on the physical feet, re-measured every tick from the feet that are both planted in the
  // clip and touching the crates. A walk that steps, or feet that slip, move the whole desired body with them.
  Eigen::Vector2d anchor = Eigen::Vector2d::Zero();
  BoxerStateMachine state;  // guard / down ... (boxer_state.h): control reads this, never the metrics
  // The match (game/match/match.h) writes these before control: the punch's aim (punch_aim.h), the servo gains'
  // scale (lower when stunned or knocked down).
  PunchAim aim;
  double gain_scale = 1.0;
  double yaw_offset = 0.0;  // rad, added to the stance heading when placing the clip (the reset faces the opponent)
};

// Per-tick scratch (capacity kept, no allocation once sized).
struct BoxerScratch {
  std::vector<Eigen::Quaterniond> fk_W, W_d_metric;
  std::vector<Eigen::Vector3d> fk_P;
  std::vector<Eigen::Quaterniond> W_a;  // actual world orientation per bone
  std::vector<Eigen::Vector3d> omega_a;  // actual world angular velocity per bone
  std::vector<Eigen::Vector3d> q_joint, spring_ref;  // implicit servo: joint rotations, spring references
  std::vector<Eigen::Vector2d> hull, pts, landing;  // lift-off gate (landing: a quick step's sole), balance steps
  eng::control::StepPlan step_preview;  // lift-off gate: a carried step as it would start
  static inline const std::vector<Eigen::Vector2d> no_points;  // an empty contact set (a stance foot that is stepping itself)
  // balance steps: the soles on the ground (corners, hulls), the stance's hull
  std::vector<Eigen::Vector2d> sole_corners[2], sole_hull[2], stance_hull;
};

struct Boxer {
  int index = 0;
  Eigen::Vector3f team_color{1, 0, 0};
  Stance stance;
  bool limp = false;  // a ragdoll: no servo at all
  CharacterBodies bodies;
  eng::control::BipedBones bones;  // leg and foot bone indices, resolved once (world.cpp add_boxer)
  eng::control::ControlBody control_body;  // per-bone servo inertias, total mass (setup)
  BoxerSettings settings;
  BoxerControlState ctl;
  BoxerScratch scratch;
  PoseSource source;              // looping clip or motion-graph walk
  eng::anim::PoseSample desired;  // world-placed desired pose (after fitting the legs to the crates)
  BoxerMetrics metrics;

  bool uses_qp() const { return std::holds_alternative<QpBalance>(ctl.balance); }
};

eng::control::ServoSpace servo_space_from_name(const std::string& name);
const char* servo_space_name(eng::control::ServoSpace s);

// Places a desired pose from the pose source (clip floor frame, facing +X) on the boxer's stance (heading, crate
// heights), in place.
void place_desired_pose(const eng::assets::CharacterDesc& desc, const Arena& arena, const Boxer& b,
                        eng::anim::PoseSample& pose);

// Wall time of boxer_control's stages (milliseconds, ADDED by every tick given it; the caller resets). The stages
// partition the tick (engine/core/stage_laps.h). Reporting only: control never reads it.
struct ControlStageTimes {
  double graph = 0.0;     // the pose source's tick: the clip, or the motion-graph walk (transitions, blending)
  double pose = 0.0;      // the actual state read, the desired pose placed on the crates, anchored on the feet,
                          // the legs fitted to the ankles, the punch's aim
  double stepping = 0.0;  // balance QP: support base, lift-off gate, step planner, balance steps
  double servo = 0.0;     // the servo's heading and its tick (control_step: eq. 3's targets, implicit springs)
  double qp = 0.0;        // the balance controller's actuation: the QP's inputs built and solved (or the PD layer)
  double total() const { return graph + pose + stepping + servo + qp; }
};

// Reads the boxer's actual world orientations / angular velocities, runs its servo and balance controller and
// applies the torques (+tau on each bone, -tau on its parent; root help on the pelvis without reaction).
// profile: when non-null, each stage's wall time is added to it.
void boxer_control(const eng::physics::Model& m, eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   const Arena& arena, Boxer& b, double dt, ControlStageTimes* profile = nullptr);

// Works out the boxer's foot contacts from the contacts of the last physics step (once per contact set: after every
// step and once before the first): b.ctl.contacts.
void boxer_sense_contacts(const eng::physics::Data& d, Boxer& b);

// A boxer's joints get the engine's soft speed limit (eng::physics::Body::max_speed, kLimpJointMaxSpeed) while it
// falls, lies or gets up, or is handled by the player's hands (BoxerControlState::handled_until: dragged, pushed,
// struck by a thrown object or by the other boxer while that one is handled), none while it stands. Why: a limp arm
// flung by a strong drag, or the glove of a boxer yanked by its head while still on its feet, whips at over 80 rad/s
// (gloves over 30 m/s); standing, the elbows of punches and blocks reach 60-86 rad/s, and a 30 rad/s limit on every
// joint at all times slows the landed punches (docs/decisions/joint-speed.md).
inline constexpr double kLimpJointMaxSpeed = 30.0;  // rad/s
void boxer_joint_speed_limits(eng::physics::Model& m, const Boxer& b, double time);

// The root assist's torque limit now (N m): the root spring's, scaled by consciousness (the paper's Fig. 7: the root
// spring "lowers its motor gains when knocked out"); 0 without a root spring.
double root_assist_limit(const Boxer& b);
// How far beyond the feet that assist moves the centroidal moment pivot: tau / (m g) (Popovic, Goswami & Herr 2005),
// m; 0 without a root spring. The balance steps' trigger and the balance step's swing pivot read it.
double assist_reach(const eng::physics::Model& m, const Boxer& b);

// Each leg's geoms (thigh, shank, foot; b.bones.leg[k]), from the character's per-bone geom ranges: leg k's appended
// to out[k]. The report's leg-overlap metric and the balance QP's leg clearance read them.
void list_leg_geoms(const Boxer& b, std::vector<int> (&out)[2]);

// After a physics step: the metrics (com speed, tracking error, foot slide, trace); observe only.
void boxer_measure(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   Boxer& b, double dt);
// After boxer_measure: the fall detection (the state machine: a fall, Guard -> Down), which control reads on the next
// tick; the metrics record the first fall and the time upright before it (game/fall_detection.cpp).
void detect_fall(const eng::physics::Data& d, Boxer& b, double dt);

}  // namespace boxing
