#pragma once
#include <array>
// A boxer: its bodies in the physics model, its pose source (a keyframed clip, later the motion graph), the servo
// that turns the desired pose into torques, and the measurements the scenarios report.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "engine/anim/clip.h"
#include "engine/assets/character.h"
#include "engine/control/balance/balance_qp.h"
#include "engine/control/servo/controller.h"
#include "engine/control/servo/implicit_servo.h"
#include "engine/control/servo/inertial_servo.h"
#include "engine/control/servo/root_spring.h"
#include "engine/physics/data.h"
#include "engine/physics/model.h"
#include "game/arena.h"
#include "game/character_builder.h"
#include "game/pose_source.h"
#include "engine/control/biped/biped_bones.h"
#include "engine/control/biped/foot_contacts.h"
#include "engine/control/biped/foot_geometry.h"
#include "engine/control/biped/leg_ik.h"
#include "engine/control/biped/lift_off_gate.h"
#include "engine/control/biped/step_planner.h"

namespace boxing {

struct BoxerMetrics {
  bool fell = false;
  double fell_at = -1.0;
  std::string fell_reason;
  Eigen::Vector3d fell_pelvis = Eigen::Vector3d::Zero();  // where the pelvis was at the fall (world, m)
  double time_upright = 0.0;
  int steps_taken = 0, steps_skipped = 0;  // balance QP: the clip's steps lifted off / held down (gate_lift_off)
  double max_com_speed = 0.0;
  // Root spring use (external torque on the pelvis, no reaction): sum of |tau|^2 dt, peak |tau|, time at its limit.
  double root_torque_sq_dt = 0.0, root_torque_peak = 0.0, root_saturated_time = 0.0;
  double standing_height = 0.0;  // pelvis above its support at the start
  std::vector<double> err_sq_sum;  // per bone, world orientation tracking error^2 (rad^2)
  long samples = 0;
  std::vector<double> err_sq_upright;  // the same, only the samples before the first fall
  long samples_upright = 0;
  double ground_contact_time = 0.0;  // continuous time a non-foot, non-shank link touches crates / floor
  Eigen::Vector3d last_com = Eigen::Vector3d::Zero();
  bool have_com = false;
  // Diagnostic trace, in the report as boxers[i].trace (first 4 s at 20 Hz, plus the sample at the fall). Columns:
  // t, foot yaw error l/r (deg, actual - desired heading), foot tilt l/r (deg), the right (rear) sole normal's lean
  // forward / left (deg, heading frame), com - support centre (x, y; heading frame, m; centre = mid of the two
  // sole centres), centre of pressure of the feet's contact forces - support centre (x, y; 0 = no foot force),
  // pelvis height above the lower crate (m).
  std::vector<std::array<double, 12>> trace;
  Eigen::Vector3d foot0[2];
  bool traced_fall = false;
};

// The biped layer's settings (typed, with their defaults; read every tick, so a panel can edit them live).
struct BipedSettings {
  eng::control::FootGeometry foot;
  eng::control::StepTuning step;
  eng::control::LiftOffGateTuning gate;
  eng::control::FootContactThresholds contact;
};

struct Boxer {
  int index = 0;
  eng::control::BipedBones bones;  // leg and foot bone indices, resolved once (world.cpp add_boxer)
  BipedSettings biped;
  eng::control::FootContacts contacts;  // of the last physics step (boxer_sense_contacts), read by control and metrics
  Eigen::Vector3f team_color{1, 0, 0};
  Stance stance;
  CharacterBodies bodies;
  eng::control::ServoSpace space = eng::control::ServoSpace::World;
  eng::control::ServoGains gains;
  eng::control::ControlBody control_body;
  eng::control::MeathookParams hook;
  eng::control::ServoState servo;
  eng::control::RootSpringParams root_params;  // enabled per scenario (world.cpp), off = no root help
  eng::control::RootSpring root_spring;
  Eigen::Vector3d root_torque = Eigen::Vector3d::Zero();  // applied this tick (for the metrics)
  // World / Person space: eq. 3 as implicit joint springs rooted at the feet (implicit_servo.h). Per skeleton
  // bone: the joint's servo (gains also written into the Model's Body::stiffness/damping at build time), the
  // actual joint rotation and the spring reference written to Data::spring_ref every tick.
  std::vector<eng::control::ImplicitServoJoint> joints;
  std::vector<Eigen::Vector3d> q_joint, spring_ref;
  bool limp = false;  // a ragdoll: no servo at all
  // Balance QP (--balance qp): joint torques from engine/control/balance/balance_qp.h instead of the implicit springs and
  // the PD root shift. Inputs rebuilt every tick (capacity kept), workspace and last result kept for reports.
  bool balance_qp = false;
  eng::control::BalanceQpInput qp_in;
  eng::control::BalanceQpParams qp_params;
  eng::control::BalanceQp qp_ws;
  eng::control::BalanceQpResult qp_out;
  Eigen::Vector3d com_d_rel_last = Eigen::Vector3d::Zero();  // desired com - desired support centre, last tick
  bool have_com_d = false;
  int qp_support_set = 0;  // which feet were planted last tick (bit 0 left, bit 1 right)
  bool swing_prev[2] = {false, false};  // balance QP: the foot was swinging last tick (swing feed-forward)
  Eigen::Vector3d swing_target_prev[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // Balance QP: the step each foot is taking (step_planner.h) and its lift-off gate (lift_off_gate.h).
  eng::control::StepPlan step[2];
  eng::control::LiftGate gate[2];
  double support_base = 0.0;  // balance QP: the clip's floor height under the actual feet (low-passed)
  bool have_support_base = false;
  std::vector<Eigen::Vector2d> qp_pts, qp_hull;  // scratch: contact points on the floor, their hull
  double person_heading = 0.0;  // person space: low-passed pelvis heading (boxer_control)
  bool have_person_heading = false;
  double plant_yaw[2] = {0, 0};
  bool plant_yaw_set[2] = {false, false};
  // Where the desired motion sits on the crates (boxer_control): the horizontal offset (world, m) that keeps the
  // clip's planted feet on the physical feet, re-measured every tick from the feet that are both planted in the
  // clip and touching the crates. A walk that steps, or feet that slip, move the whole desired body with them.
  Eigen::Vector2d anchor = Eigen::Vector2d::Zero();
  // Scratch for forward kinematics of desired poses in boxer_control (no per-tick allocation).
  std::vector<Eigen::Quaterniond> fk_W;
  std::vector<Eigen::Vector3d> fk_P;

  PoseSource source;                      // looping clip or motion-graph walk
  eng::anim::PoseSample desired;          // world-placed desired pose (after fitting the legs to the crates)
  std::vector<Eigen::Quaterniond> W_a, W_d_metric;
  std::vector<Eigen::Vector3d> omega_a;
  BoxerMetrics metrics;
};

eng::control::ServoSpace servo_space_from_name(const std::string& name);
const char* servo_space_name(eng::control::ServoSpace s);

// Places a desired pose from the pose source (clip floor frame, facing +X) on the boxer's stance (heading, crate
// heights), in place.
void place_desired_pose(const eng::assets::CharacterDesc& desc, const Arena& arena, const Boxer& b,
                        eng::anim::PoseSample& pose);

// Reads the boxer's actual world orientations / angular velocities, runs its servo and applies the torques
// (+tau on each bone, -tau on its parent; root help on the pelvis without reaction).
void boxer_control(const eng::physics::Model& m, eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   const Arena& arena, Boxer& b, double dt);

// Works out the boxer's foot contacts from the contacts of the last physics step (once per contact set: after every
// step and once before the first): b.contacts.
void boxer_sense_contacts(const eng::physics::Data& d, Boxer& b);

// Updates fell / upright time / com speed / tracking error after a physics step.
void boxer_measure(const eng::physics::Model& m, const eng::physics::Data& d, const eng::assets::CharacterDesc& desc,
                   Boxer& b, double dt);

}  // namespace boxing
