#pragma once
// The player's hands on the simulation (README: Controls, Scripted input): drags of any body (a soft point spring
// from the grabbed point to a target), thrown beach balls and crates, pushes, the fight keys and the panel's settings,
// all as timed InputEvents (input_events.h) applied by the world at the start of a physics step. The window queues
// what the mouse and keys do (interaction_submit), --input FILE.json schedules a script, --record FILE.json writes
// every event as it was applied (with the time it was applied), so playing the recording reproduces the run.
//
// Drags are Box2D v3's mouse joint (engine/physics point springs): the soft step with the point's effective mass
// K^+ = (J M^-1 J^T)^+ makes the spring's stiffness m_eff (2 pi f)^2, i.e. scaled by the effective mass at the
// grabbed point, so a hand and a pelvis follow the cursor alike (Gazebo scales by the link's mass, MuJoCo's perturb
// by its inertia; m_eff is what the point actually feels, the rest of the articulation included). The force is
// capped; the strong drag (a held modifier) is stiffer and strong enough to lift a boxer.
//
// Thrown objects come from a pool of free bodies added with the model (a model cannot grow mid-run): a parked
// object collides with nothing, is not drawn and is held still; a throw places the next one of its kind.
#include <array>
#include <nlohmann/json.hpp>
#include <vector>

#include "engine/physics/types.h"
#include "game/interaction/input_events.h"
#include "game/match/body_parts.h"

namespace boxing {

struct World;

struct DragStrength {
  double hertz, damping_ratio, max_force;  // Hz, -, N
};
inline constexpr DragStrength kDragNormal{2.5, 0.9, 450.0};
inline constexpr DragStrength kDragStrong{4.0, 0.9, 2500.0};  // over three body weights: lifts and throws a boxer
// m/s: the spring's target follows the hand (the cursor, a script's offset) at most this fast, as a real hand would;
// a target that jumps 1-2 m at once under the strong spring whips hands and feet past 30 m/s.
inline constexpr double kDragTargetSpeed = 6.0;

struct ObjectSpec {
  ObjectKind kind;
  double mass, radius, half, restitution, friction;
};
// A beach ball: 0.5 m across, 0.4 kg (real ones: 0.1-0.3 kg), bouncy; a crate: 0.4 m, 25 kg.
inline constexpr ObjectSpec kBall{ObjectKind::Ball, 0.4, 0.25, 0.0, 0.75, 0.5};
inline constexpr ObjectSpec kCrate{ObjectKind::Crate, 25.0, 0.0, 0.2, 0.0, 0.7};
inline constexpr int kPoolBalls = 8, kPoolCrates = 3;

struct ThrownObject {
  ObjectKind kind = ObjectKind::Ball;
  int body = -1, geom = -1;
  uint32_t group = 0;    // its collision group when live
  bool live = false;
  double thrown_at = 0.0;
};

// One held point spring: the mouse's (slot 0) or a scripted drag's (slots 1..3).
struct HeldDrag {
  bool active = false;
  int body = -1;
  Eigen::Vector3d local = Eigen::Vector3d::Zero();  // grabbed point, body frame
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // where it was grabbed (world)
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();   // where the hand wants it (world); the spring's target follows
                                                     // at most kDragTargetSpeed
  double release_at = -1.0;                          // scripted: s; the mouse: < 0 (until a release event)
  int log = -1;                                      // its entry in Interaction::drag_log
};

struct ActivePush {
  int body = -1;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  double until = 0.0;
};

// A gamepad as the world sees it: its last state (pad events), what pad_update carries between reads, the boxer it is
// pinned to (-1: pad_boxer's rule) and the actions it gave (the report's pads).
struct PadSlot {
  PadState state;
  PadReader reader;
  int boxer = -1;
  int actions = 0;
  int last_boxer = -1;  // the boxer its last action went to
  bool seen = false;    // a pad event named it
};

struct Interaction {
  std::vector<InputEvent> script;  // --input, in time order
  size_t next_script = 0;
  std::vector<InputEvent> queue;   // submitted by the window, applied at the next step
  bool recording = false;
  std::vector<InputEvent> recorded;  // every applied event, t = the time it was applied (--record)
  std::vector<ThrownObject> objects;
  std::array<HeldDrag, 4> drags;  // [0] the mouse
  std::vector<ActivePush> pushes;
  std::array<PadSlot, kMaxPads> pads;
  std::vector<BodyOwner> owners;  // per physics body: which boxer and bone (body_parts.h)
  // report
  int events_applied = 0;
  struct DragLog {
    int boxer = -1, bone = -1, object = -1;
    bool strong = false, scripted = false;
    double t = 0.0, released_at = -1.0, peak_force = 0.0, max_displacement = 0.0;
  };
  std::vector<DragLog> drag_log;
  int objects_thrown = 0;
  struct ObjectHit {
    double t;
    ObjectKind kind;
    int object;        // index into objects
    double thrown_at;  // which throw of that object
    int boxer, bone;
    double speed, impulse;
  };
  std::vector<ObjectHit> object_hits;
  // The last hits on the boxers (punches, objects, limbs; not the floor), for the debug drawing's flashes.
  struct Flash {
    double t = -1e9;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double speed = 0.0;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // the contact's, from a to b
    double impulse = 0.0;                              // N s, the pair's normal impulse that step
  };
  std::array<Flash, 16> flashes;
  int next_flash = 0;
};

// Adds the object pool's bodies to the model (scenario setup, before Model::finalize).
void interaction_add_objects(World& w);
// After make_data: the body map, the objects parked, the script (--input) loaded into the schedule.
void interaction_setup(World& w, std::vector<InputEvent> script);
// Start of a physics step (before step1): applies the events that are due (script, then queue), parks objects.
void interaction_begin_step(World& w);
// After the boxers' control, before step2: the drags' targets and the pushes' forces.
void interaction_apply_forces(World& w);
// After the step: drag peaks and displacement, object hits.
void interaction_after_step(World& w);
// The gamepads connected now (the assignment rule's count).
int pads_connected(const Interaction& in);
// The window's input: applied at the start of the next physics step.
void interaction_submit(World& w, InputEvent e);

// What is under a ray (the mouse): a boxer's bone or a thrown object, the point in world and body frames.
struct Pick {
  int body = -1, boxer = -1, bone = -1, object = -1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero(), local = Eigen::Vector3d::Zero();
  double distance = 0.0;
};
Pick interaction_pick(const World& w, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir);
// The grab event for a pick (the mouse's press).
InputEvent grab_event(const World& w, const Pick& p, bool strong);
// A held drag's grabbed point (world), its target, the spring's force and cap (slot 0: the mouse); false when idle.
bool drag_state(const World& w, int slot, Eigen::Vector3d& point, Eigen::Vector3d& target, double& force,
                double& max_force);

nlohmann::json interaction_report(const World& w);

}  // namespace boxing
