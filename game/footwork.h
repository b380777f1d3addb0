#pragma once
// FOOTWORK: the boxer's deliberate steps (forward, back, left, right and pivots), asked for by the match's AI or the
// player and carried by the balance controller. A move is one or two steps of the balance steps' machinery
// (engine/control/biped/balance_step.h phase 3: a weight shift over the stance foot, then a swing on a path bent
// around the stance foot onto a foothold on the crates): the foot on the side the move goes steps first and the
// other follows it (a boxer's step-drag), so the feet never cross. A pivot first turns the stance's heading, then
// swings the rear foot round the lead foot to the stance the turned heading asks for. The desired body follows the
// feet (boxer.cpp's anchor); a finished move folds the anchor into the stance, so the walk's placement starts from
// where the boxer now stands. Why this and not the step clips: docs/decisions/footwork-moves.md.
#include <Eigen/Core>
#include <cstdint>

namespace boxing {

struct Arena;
struct Boxer;

enum class FootworkMove : uint8_t { None, Forward, Back, Left, Right, Pivot };
const char* footwork_move_name(FootworkMove m);

struct FootworkTuning {
  double stride = 0.30;       // m, the stance's displacement of a move forward or back
  double side_stride = 0.25;  // m, ... left or right
  double max_turn = 0.5;      // rad, the most a move turns the heading
  double turn_rate = 2.5;     // rad/s, the heading's turn before the feet follow
  double swing = 0.28;        // s, each step's swing (the return step's unhurried 0.45 s is the recovery's)
  double shift_speed = 1.6;   // m/s, the com target's move over the stance foot before the lift
  double unload_share = 0.2;  // ... or as soon as the foot bears less than this share of the body's weight
  double min_shift = 0.08;    // s of weight shift at least before a foot lifts
  double lift_margin = 0.03;  // m, the capture point at touch-down this far inside the stance and landing soles
  double goal_after = 0.3;    // share of a swing after which the com aims at the move's end (FootworkState::goal);
                              // from the lift (0) the com fell onto the swinging foot and it dragged (seed 5, 1 s)
  double skip_within = 0.04;  // m, the following foot stays down when its place is this close already
  double give_up = 4.0;       // s, a move not done by then is dropped (the balance took the feet over)
};

struct FootworkState {
  FootworkMove move = FootworkMove::None;
  Eigen::Vector2d delta = Eigen::Vector2d::Zero();  // world m: the stance's displacement this move
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();   // world m: the feet's middle where the move ends (the com's aim)
  double turn_left = 0.0;  // rad still to turn the heading before the first step
  int phase = 0;           // 0: turning; 1: first foot asked / stepping; 2: second foot; 3: done
  int first = 0;           // the foot that steps first (0 left / lead, 1 right / rear)
  bool asked = false;      // the current phase's step was handed to the balance steps
  double started = 0.0;    // s (the boxer's clock)
  double clock = 0.0;      // s since the boxer's start, advanced by footwork_turn
  int moves = 0, steps = 0, dropped = 0;  // moves finished, steps asked for, moves given up
};

// Starts a move (false: one is under way, or the boxer cannot move its feet now). `turn` is the heading change (rad,
// + left), clamped to max_turn; a Pivot with turn 0 only re-forms the stance.
// The tuning is the boxer's (BoxerTuning::footwork).
bool request_footwork(Boxer& b, FootworkMove m, double turn);
// A move under way (its turn or its steps).
bool footwork_busy(const Boxer& b);
// The move under way given up (a fall, a push's recovery, the referee): the feet are the balance's again.
void cancel_footwork(Boxer& b);
// The heading's turn (before the feet follow) and the move's clock; before the desired pose is placed (boxer_control).
void footwork_turn(Boxer& b, double dt);
// After the balance steps looked at the feet (take_balance_steps): hands the move's next step to them, and moves on
// when it has landed. `want` is where the desired pose has each sole's centre (world, the placed pose's FK).
void footwork_steps(const Arena& arena, Boxer& b, const Eigen::Vector2d sole[2], const Eigen::Vector2d want[2]);
// A move forward / back / left / right: the stance's displacement in the world for the heading (rad).
Eigen::Vector2d footwork_delta(FootworkMove m, double heading, const FootworkTuning& t);

}  // namespace boxing
