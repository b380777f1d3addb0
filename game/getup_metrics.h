#pragma once
// Every knockdown and get-up in every scenario, measured from the physics (the report's top-level `getups`, issue
// 63): from the tick a boxer falls (BoxerState Falling or Down) to the tick it stands again (Guard or Stunned), the
// external help it had (the stand-up's root assist: a force and a torque on the pelvis), the body parts that bore
// weight on the crates, each joint's peak torque, and the phases it went through. Observe only: nothing reads these
// back into the simulation.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace boxing {

struct World;

struct GetUpRecord {
  int boxer = 0;
  double down_at = 0.0, up_at = -1.0;  // s (up_at < 0: not up)
  std::string lying;                   // back | front, read as the stand-up starts ("" before)
  double time = 0.0;                   // s measured (down to up, or to the end)
  double lift_force_sq_dt = 0.0, lift_force_peak = 0.0;    // N: external force on the boxer (the root assist's)
  double root_torque_sq_dt = 0.0, root_torque_peak = 0.0;  // N m: the root torque (the root spring / assist)
  std::vector<double> support_s;    // per bone: seconds it pressed on the crates or the floor
  // per bone: its joint's peak torque (N m, vector norm): the control's torque plus the servo springs' (Data::passive:
  // the world-space servo drives the stand-up through implicit joint springs); reported against a person's strength
  // (person_strength.h)
  std::vector<double> torque_peak;
  std::vector<std::pair<std::string, double>> phases;  // name, from (s): down, then the stand-up's clips
};

struct GetUpTracker {
  std::vector<int> open;  // per boxer: its record under way (-1: standing)
  std::vector<GetUpRecord> records;
  std::vector<int> bone_of_body;  // body -> bone of its boxer (-1: not a boxer's), sized on the first step
  std::vector<int> boxer_of_body;
  std::vector<char> pressing;     // per boxer x bone, this tick (scratch)
};

struct Boxer;
// How a boxer lies: "back" when its chest's front (+X of the bone) looks up, else "front" (the referee's choice of
// get-up and the records' `lying`).
const char* lying_of(const World& w, const Boxer& b);

// After each physics step (after fall detection).
void measure_getups(World& w);
nlohmann::json getups_report(const World& w);

}  // namespace boxing
