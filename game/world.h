#pragma once
// The simulated world of one scenario: the arena's crates (static), the boxers (servo-driven articulations),
// limp ragdolls and loose crates, stepped at a fixed 240 Hz; four physics steps per 60 Hz display frame.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/anim/clip.h"
#include "engine/anim/motion_graph.h"
#include "engine/assets/character.h"
#include "engine/assets/gltf.h"
#include "engine/core/result.h"
#include "engine/physics/data.h"
#include "engine/physics/model.h"
#include "engine/physics/step.h"
#include "game/arena.h"
#include "game/boxer.h"
#include "game/cli.h"
#include "game/getup_metrics.h"
#include "game/health.h"
#include "game/ring_ropes.h"

namespace boxing {

inline constexpr double kPhysicsDt = 1.0 / 240.0;
inline constexpr int kStepsPerFrame = 4;  // 60 Hz display frames

// The world's parts that live in game/match/ and game/interaction/ (those headers include this one's neighbours, not
// the other way round): owned here through pointers, created by make_world.
struct Match;
struct Interaction;
struct Chaos;
struct SoundEventLog;

struct LooseBody {
  int body = 0;
  eng::physics::Shape shape;
  Eigen::Vector3f color;
};

// The world's own setup numbers (the boxers' are in boxer_tuning.h, the fight's in MatchTuning).
struct WorldTuning {
  double floor_friction = 0.9;  // the floor's Coulomb mu (a pair takes sqrt(mu_a mu_b)); lower, the feet slide more
  double crate_friction = 0.9;  // the crates' tops and sides, the same as the floor's
  double arena_min_step = 0.10;  // m, make_arena's least height step between neighbouring crates (arena.h)
  double standing_com_height = 0.95;  // m, the guard's com over the soles (Kwon's pendulum length, step_lqr)
  // s a boxer stays handled (BoxerControlState::handled_until) after the hands last hold, push or hit it with a
  // thrown object: longer keeps it on the plain balance priorities longer after a drag.
  double handled_hold = 2.0;
};

struct World {
  World();
  ~World();  // (in world.cpp: the parts' types are complete there)
  Options options;
  WorldTuning tuning;
  Arena arena;
  eng::assets::GltfScene boxer_scene;
  eng::assets::CharacterDesc boxer_desc;
  std::vector<eng::anim::Clip> clips;
  eng::anim::MotionGraph graph;         // built for the graph-walk and match scenarios
  eng::physics::Model model;
  eng::physics::Data data;
  std::vector<Boxer> boxers;            // servo-driven (or limp ragdolls in the ragdolls scenario)
  std::vector<LooseBody> loose;         // free crates
  long steps = 0;
  double physics_ms_total = 0.0;        // wall time spent in physics (reporting only, never fed back)
  // Wall time per stage of step_world, summed over the steps (reporting only): step1 (input events, kinematics,
  // collision, constraint rows, M and c), control (every boxer: pose source, servo, balance controller; the
  // scenario's and the player's forces), step2 (passive forces, dynamics, constraint solve, integration), sense (foot
  // contacts, metrics, scenario hooks). With profile_stages, also the physics step's and the boxers' control's own
  // stages (control summed over the boxers): the report's tick_profile_ms (docs/decisions/tick-stages.md).
  struct TickProfile {
    double step1_ms = 0.0, control_ms = 0.0, step2_ms = 0.0, sense_ms = 0.0;
    eng::physics::StageTimes physics;  // collision, dynamics, solver, integration (ms)
    ControlStageTimes control;         // graph, pose, stepping, servo, qp (ms)
  } profile;
  bool profile_stages = true;  // off: step1 / step2 / boxer_control read no clock (a few hundred ns a tick)
  bool push_active = false;
  // The push scenario's time series at 120 Hz (the report's push.trace, Kudoh's Figs. 3.1-3.4): t, com and centre of
  // pressure in the stance's heading frame about its mark (the pelvis between the feet; x forward, y left), both upper arms'
  // swing (rad, forward from hanging, in the sagittal plane).
  std::vector<std::array<double, 7>> push_trace;
  std::unique_ptr<Match> match;  // the match scenario's fight (game/match/match.h); inactive elsewhere
  std::unique_ptr<Interaction> interaction;  // the player's hands: drags, thrown objects, scripted and recorded input
  std::unique_ptr<Chaos> chaos;              // --chaos: seeded random input events (game/interaction/chaos.h)
  std::unique_ptr<SoundEventLog> sounds;     // each tick's sound events, read from the step (game/audio/sound_events.h)
  Health health;                             // measured every step (the report's health block)
  GetUpTracker getups;                       // every knockdown and get-up, measured (the report's getups)
  RingRopesState ropes;                      // the match ring's ropes (ring_ropes.h): their push and who touched them
};

// Loads content (boxer, clips) from options.content_dir and builds the scenario (and --input's script).
eng::Result<std::unique_ptr<World>> make_world(const Options& options);
// One physics step: control, external pushes, physics, measurements.
void step_world(World& w);
// The scenario's results for the report (per boxer: fell, time upright, max com speed, tracking error, servo).
nlohmann::json world_report(const World& w);

std::string content_dir(const Options& options);

}  // namespace boxing
