#pragma once
// The PD balance controller (--balance pd): the servo's own springs carry the body, with Kudoh's "PD near the
// centre" on top (the desired root shifted against the com's error over the feet, the legs re-fitted to the actual
// ankles so the support servo pushes the body back) and the paper's torque-limited root spring on the pelvis tilt.
// One of the two balance controllers (balance_controller.h).
#include <Eigen/Core>
#include <vector>

namespace eng::physics {
struct Model;
struct Data;
}  // namespace eng::physics

namespace boxing {

struct Boxer;
struct BalanceTick;

// Tuning (read every tick). Measurements: docs/decisions/pd-balance-gains.md, docs/decisions/stance-placement.md.
struct PdBalanceTuning {
  double kp = 2.0;          // desired-root shift per metre of com error (-): stand 10/10, all pushes at 2.0 / 0.5
  double kd = 0.5;          // desired-root shift per m/s of com speed (s)
  double max_shift = 0.15;  // m, the shift's bound
  double rear_rise = 0.75;  // the clip lifted by this share of the rear crate's step when the rear crate is higher ...
  double max_rise = 0.09;   // m ... at most this (a lead leg over-extended otherwise)
};

// The PD controller keeps no state of its own (the servo's is the boxer's).
struct PdBalance {};

// Before the legs are fitted to the ankles: the desired root shifted to bring the com back over the support.
void adjust_desired(PdBalance&, BalanceTick& t);
// After the servo's targets: root spring, then the servo's springs (implicit) or torques (explicit) applied.
void actuate(PdBalance&, BalanceTick& t);
// The clip's rise over the lower crate (m): part of the step when the rear crate is the higher one.
double stance_rise(const PdBalance&, const Boxer& b);
inline double stance_drop(const PdBalance&, const Boxer&) { return 0.0; }
inline constexpr bool plans_steps(const PdBalance&) { return false; }  // no lift-off gate, no step planner
inline constexpr bool model_springs(const PdBalance&) { return true; }  // the servo's gains as implicit springs

}  // namespace boxing
