#pragma once
// The match (--scenario match): two boxers fight. Each tick after the physics step (match_after_step):
//   1. punches: a boxer entering a clip tagged "punch" has thrown one (an event opens; its target is chosen);
//   2. hits: the solver's hit events (engine/physics/data.h HitEvent) between the punch's striking glove and the
//      opponent: on the head or torso at an approach speed of at least MatchTuning::land_speed it LANDED, on a glove
//      or an arm it was BLOCKED. The contact's impulse over the next impact_window seconds is the punch's impulse;
//      damage = impulse x location factor (head > body) lowers the opponent's consciousness (the root spring's,
//      engine/control/servo/root_spring.h, whose assist and the servo gains scale with it);
//   3. reactions: a landed punch forces the reaction clip (hit_head / hit_body; a hard one the stagger, two steps
//      back: MatchTuning::rock_damage), a heavy one or too little
//      consciousness left a knockdown (fall_back / fall_forward by the push's direction): the body falls limp the way
//      the hit and the crates make it fall; nothing is scripted but the clip;
//   4. the count: once down and lying still, the stand-up is chosen from the lying pose (getup_back / getup_front)
//      and tracked physically with a reported root assist; up before count_seconds fights on, else a knock-out;
//   5. the AI (fighter_ai.h, seeing through fighter_view.h) steers each AI boxer's motion graph: punches when in
//      range, defence after a reaction time when the other's punch starts.
// The parts: referee.h (the rules, the count, get-ups, resets), hits.h (punches, openings, hits to damage),
// fighter_view.h (perception and aim), match_report.h (the report and the HUD); this file's match.cpp runs them.
// Aimed punches: while a punch plays, the glove's desired path is bent toward the opponent's actual head or body,
// full at the clip's impact frame (punch_aim.h); the servo and balance QP track it.
#include <Eigen/Core>
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "game/hud.h"
#include "game/match/body_parts.h"
#include "game/match/bout.h"
#include "game/match/clinch.h"
#include "game/match/defence_metrics.h"
#include "game/match/fighter_ai.h"
#include "game/match/fighter_view.h"
#include "game/match/footwork_ai.h"
#include "game/match/footwork_metrics.h"
#include "game/match/match_report.h"
#include "game/match/player_input.h"
#include "game/match/referee.h"
#include "game/match/replay.h"
#include "game/match/stamina.h"

namespace boxing {

struct World;

inline constexpr double kReplaySeconds = 4.0;

// Where best_opening (hits.cpp) looks for an opening: the aim points on the target and the guard's parts as spheres.
struct OpeningTuning {
  // Aim points on the head (face, chin, both temples, crown) and torso (solar plexus, both sides of the ribs), m in
  // the bone's frame (+X forward, +Y left, +Z up) about its centre of mass: more points, finer aim, more to weigh.
  std::array<Eigen::Vector3d, 5> head{{{0.09, 0, 0.0}, {0.07, 0, -0.07}, {0.03, 0.08, 0.02}, {0.03, -0.08, 0.02},
                                       {0.05, 0, 0.09}}};
  std::array<Eigen::Vector3d, 3> torso{{{0.12, 0, -0.08}, {0.08, 0.13, -0.05}, {0.08, -0.13, -0.05}}};
  double glove_radius = 0.07;       // m, a guarding glove's sphere
  double upper_arm_radius = 0.055;  // m, the upper arm's two spheres (mid arm and elbow)
  double elbow_along = 1.8;         // the elbow's sphere at this multiple of the upper arm's com along the bone
  double forearm_radius = 0.05;     // m, the forearm's two spheres
  double forearm_near = 0.5, forearm_far = 1.5;  // ... at these multiples of the forearm's com along the bone
  double hook_side = 0.35;          // m: a hook comes from this far to the striking hand's side of the target
  double hook_back = 0.1;           // m ... and this far behind it (toward the attacker)
  double uppercut_below = 0.35;     // m: an uppercut comes from this far below the target
  double uppercut_back = 0.15;      // m ... and this far behind it
  double jitter = 0.01;             // m, the seeded AI's tie-break noise on the clearance: more, a less exact aim
};

// Measured and chosen in docs/decisions/match-fight.md.
struct MatchTuning {
  double punch_arm_gain = 1.0;     // the striking arm's servo frequency x this during an aimed punch (punch_aim.h)
  // The strike (PunchAim::strike, docs/decisions/match-fight.md): the glove driven toward the target at up to
  // strike_speed (0 = off), until its first touch or strike_follow s past the clip's impact frame.
  double strike_speed = 10.0;      // m/s
  double strike_follow = 0.03;     // s
  double strike_rate = 40.0, strike_omega = 40.0, strike_weight = 15.0;  // PunchAim's
  // m: punches aim this far THROUGH the target's centre, the glove meeting it still accelerating (the servo lags its
  // target: aimed at the surface, the glove arrives slow); more drives the glove on past the surface.
  double aim_through = 0.2;
  double switch_to_body_below = 0.04;  // m: a head opening narrower than this sends an AI's punch to the body if wider there
  OpeningTuning opening;           // best_opening's aim points and guard spheres
  // The fighter's view (fighter_view.h). m: a straight punch's glove centre ahead of the chest at full extension
  // (the jab's desired pose at its impact frame).
  double reach = 0.74;
  // m past reach still in range (a head's depth). Both out of range is "apart" for the referee: the same bound, else
  // boxers hovering between the two bounds neither punch nor get brought together.
  double in_range_margin = 0.08;
  double too_far_margin = 0.03;    // m past reach: the AI steps in (footwork)
  double too_close_margin = 0.25;  // m inside reach: the AI steps back out
  double stunned_attack_scale = 0.4;  // a stunned boxer's punch attempt rate x this
  double land_speed = 2.0;         // m/s, a glove's approach speed on head / torso for a punch to count as landed
  double impact_window = 0.05;     // s, the contact impulse summed this long after the first touch
  // Consciousness lost per N s of impulse on the head: a landed head punch (median 8 N s) takes 0.12, and a boxer up
  // from a count (0.75) goes down again after about five; more keeps a boxer down and stunned (match-fight.md).
  double head_damage_per_ns = 0.015;
  double body_damage_per_ns = 0.01;   // ... on the torso
  double knockdown_damage = 0.35;     // one hit taking this much is a knockdown
  double knockdown_below = 0.15;     // consciousness below this after a hit is a knockdown
  double stun_below = 0.6;           // stunned (lower gains, slower punches) below this consciousness
  double unstun_margin = 0.05;       // ... and back in guard at stun_below + this (no flicker at the bound)
  // Servo gains' scale when stunned: lower, a stunned boxer sways off its pose on its softer legs and goes over on
  // its own with no punch on it (docs/decisions/match-fight.md).
  double stunned_gain_scale = 0.85;
  double recovery_rate = 0.01;       // consciousness per second recovered (after recovery_delay)
  double recovery_delay = 1.0;       // s after the last hit
  // s: a fall this long after a landed hit on the boxer is the hit's (falls_after_hit, balance_steps_after_hit),
  // later it is a fall without a hit.
  double fall_after_hit_window = 1.5;
  double still_speed = 0.4;          // m/s, pelvis speed under which a downed boxer lies still
  double still_time = 0.6;           // s lying still before the stand-up starts
  double min_down_time = 1.2;        // s down before the stand-up at the earliest
  double getup_consciousness = 0.6;  // consciousness set at the stand-up's start (the servo's gains with it)
  double count_seconds = 10.0;       // the referee's count: not up in time = knock-out
  // m, pelvis to pelvis: the count runs only while the standing boxer is this far from the downed one (in a neutral
  // corner); closer, the referee stops counting until he is back (referee.cpp, docs/decisions/count-distance.md).
  double count_when_away = 2.0;
  double up_height = 0.8;            // share of the standing pelvis height that counts as up (with guard playing)
  double settle_time = 0.5;          // s up and still before the fight goes on
  double after_count = 0.75;         // consciousness at least this once up from a knockdown
  // A boxer getting up: its thighs pass through each other, as they pass through the opponent: colliding, a leg left
  // behind the other caught on the other thigh and the boxer stood on one foot (docs/decisions/match-fight.md).
  bool getup_thighs_pass = true;
  // s in the stand-up without getting up: it is given up, the boxer sinks back (down, limp) and starts it again (the
  // stand-up is not a balance the body can always finish from where it got to; a retry starts it from the ground).
  double stand_up_give_up = 8.0;
  double step_in_after_hit = 2.0;    // s after a landed hit before the AI steps in (footwork) again
  // A hard hit short of a knockdown rocks the boxer back: at this much damage or more the stagger clip (two steps
  // back; the balance steps catch the rest) plays instead of the reaction in place (0 = never).
  double rock_damage = 0.25;
  // s after rocking the opponent back that the AI presses him: steps in as soon as free and out of reach, not at the
  // footwork's cadence, so the rocked boxer does not end out of reach (docs/decisions/footwork.md).
  double press_for = 4.0;
  // The balance's re-placement of a foot a recovery left on an edge (BalanceStepTuning::replace_edge_foot): off in the
  // fight, whose carried steps re-place the feet; its weight shifts and steps kept the boxers apart (balance-steps.md).
  bool replace_edge_feet = false;
  // The boxers' balance QP priorities in the fight (BalanceQpTuning::trunk_weight, com_weight; 1 / 1 elsewhere).
  double trunk_weight = 100.0;
  double com_weight = 30.0;
  FootworkAiTuning footwork;  // the AI's steps in the ring (footwork_ai.h)
  double clinch_within = 0.45;  // m, reach_distance under which the boxers are locked (clinch.h)
  StaminaTuning stamina;      // both boxers' wind (stamina.h, docs/decisions/stamina.md)
  PlayerInputTuning input;    // the player's presses: the buffer, the refusal's notice (player_input.h)
};

struct PunchEvent {
  double t = 0.0;
  int boxer = 0;
  std::string punch;
  std::string target = "head";  // aimed at: head | torso
  bool landed = false, blocked = false;
  std::string hit_part;   // what it touched first: head | torso | glove | arm ("" = missed)
  std::string other_clip;  // what the opponent was doing then (its clip)
  std::string defence;     // the defence clip the opponent was in before the first touch ("" none: defence_metrics.h)
  double speed = 0.0;     // m/s, approach speed at the first touch (along the contact normal: what lands it)
  double fist_speed = 0.0;  // m/s, the glove's speed (its centre, world) at the first touch: the fist speed at contact
  double peak_speed = 0.0;  // m/s, the striking glove's fastest over the punch (world)
  double opening = 0.0;   // m, the chosen opening's clearance at the punch's start (best_opening: < 0 covered)
  std::array<double, 2> consciousness{};  // the thrower's and the opponent's at the punch's start
  double impulse = 0.0;   // N s over impact_window
  double damage = 0.0;
  double landed_at = -1.0;  // s, the tick it landed (its first touch on head or torso); < 0: did not land
  double stamina = 1.0;     // the thrower's at the punch's start (stamina.h: below the band, slower and weaker)
};

struct GetUp {
  int boxer = 0;
  double down_at = 0.0, up_at = -1.0;  // s (up_at < 0: not up)
  std::string lying;                   // back | front ("" until chosen)
  double assist_sq_dt = 0.0, assist_time = 0.0;  // root assist torque^2 dt over the stand-up
  double assist_force_sq_dt = 0.0;               // root assist force^2 dt
  int retries = 0;  // stand-ups given up and started again (MatchTuning::stand_up_give_up)
  // m: the closest the other boxer came to the downed one (pelvis to pelvis, floor plane) while the count ran, and
  // from down_at to up_at whether it ran or not (measure_footwork; -1 until measured).
  double count_distance_min = -1.0;
  double down_distance_min = -1.0;
  // The count runs only while the standing boxer is MatchTuning::count_when_away from the downed one (in a neutral
  // corner), as a referee counts: count_from is the first tick it ran (< 0: not yet), counted_ticks the ticks it has
  // run since, paused_ticks those it was stopped for the standing boxer too close. counting: it ran this tick.
  double count_from = -1.0;
  int counted_ticks = 0, paused_ticks = 0;
  bool counting = false;
};

// What the player asks of a boxer (keys, game/app.cpp): a punch, a defence or a step; started from guard at once, or
// buffered while something is under way, or refused with a reason (player_input.h).
enum class FightCommand : uint8_t {
  None, Jab, Cross, LeadHook, RearHook, LeadUppercut, RearUppercut, Block, SlipLeft, SlipRight, Duck, StepForward,
  StepBack, StepLeft, StepRight, PivotLeft, PivotRight
};
const char* fight_command_clip(FightCommand c);  // the clip it asks for ("" for None)

struct MatchFighter {
  FighterAi ai;
  bool player = false;           // --player (or a fight key in the window): the keyboard steers this one (no AI)
  // The player's presses waiting, in order, and the last refusal (player_input.h: each press started, buffered or
  // refused with a reason; none dropped unseen).
  PlayerQueue input;
  int commands_taken = 0;        // player commands started
  Stamina stamina;               // stamina.h (both boxers, the same rule)
  int thrown = 0, landed = 0, knockdowns = 0, falls_without_hit = 0;
  // Of the knockdowns, those the match did not call: the boxer fell on its own within fall_after_hit_window of a
  // landed hit (rocked and went over; what a balance step is for).
  int falls_after_hit = 0;
  // The boxer's balance steps (--stepping): those started within fall_after_hit_window of a landed hit on it (a
  // boxer rocked by a punch stepping), of all it took (BoxerMetrics::balance_steps, counted here as they start).
  int balance_steps_after_hit = 0, balance_steps_seen = 0;
  int last_clip = -1;            // the graph clip of the last tick
  int open_punch = -1;           // events index of the punch now playing (-1 none)
  int landing = -1;              // events index of a landed punch still summing its impulse (on the opponent)
  double landing_until = 0.0;
  double last_hit_at = -1e9;     // last landed hit ON this boxer
  double rocked_at = -1e9;       // last hit that rocked this boxer back (MatchTuning::rock_damage)
  int rocked = 0;                // hits that rocked this boxer back
  double still = 0.0;            // s lying still
  double settled = 0.0;          // s up and still (the end of a stand-up)
  int getup = -1;                // getups index of the current knockdown
  const char* saw_punch = nullptr;  // the other boxer started this punch on the last tick (for the AI)
  // The AI's footwork (footwork_ai.h): the earliest next move, when the last one ended, its way round the opponent
  // (+1 left), and the referee's errand (a neutral corner while the other is down). The first move comes 1 s in: the
  // boxers settle into their guard on the crates first.
  double next_move = 1.0, last_move_end = 0.0, punching_until = -1e9;
  bool was_moving = false;
  int circle_side = 1;
  bool go_to_active = false;
  Eigen::Vector2d go_to = Eigen::Vector2d::Zero();
  // The punch's target: a point fixed to the opponent's head or chest (bone frame), the opening chosen at the punch's
  // start (best_opening) and followed as the opponent moves.
  int aim_bone = -1;
  Eigen::Vector3d aim_local = Eigen::Vector3d::Zero();
  Eigen::Vector3d aim_dir_local = Eigen::Vector3d::UnitX();  // the punch's approach direction (same frame)
};

// The boxer's bones the match reads every tick, resolved by name once (match_setup).
struct MatchBones {
  int head = -1, chest = -1;
  int glove[2] = {-1, -1}, forearm[2] = {-1, -1}, upper_arm[2] = {-1, -1};  // [0] left, [1] right
};

struct Match {
  bool active = false;
  MatchBones bones;
  MatchTuning tuning;
  std::vector<BodyOwner> owners;
  std::array<MatchFighter, 2> fighter;
  std::vector<PunchEvent> events;
  std::vector<GetUp> getups;
  bool over = false;
  int teleports = 0;   // a boxer's pose set directly after the start (footwork_metrics.h: a pelvis jump no velocity explains)
  std::array<FootworkMetrics, 2> footwork;  // the footwork as measured (footwork_metrics.h)
  FootworkMetricsTuning footwork_tuning;
  ReplayBuffer replay;  // the last kReplaySeconds of the bodies' coordinates at 60 Hz (the window's instant replay)
  Bout bout;           // the rounds, the judges' cards, the result (bout.h)
  ClinchMetrics clinch;  // the time the boxers spend locked together (clinch.h)
  std::vector<DefenceMotion> defences;     // every defence as the bodies made it (defence_metrics.h)
  std::array<DefenceTrack, 2> defence_track;
  std::vector<PlayerPress> presses;  // every fight key pressed, in order, and what became of it (player_input.h)
};

// After the boxers exist (scenario setup + place): the body map, the AI styles (seeded), consciousness dynamics.
void match_setup(World& w);
// Before the boxers' control: aims the punches now playing (punch_aim.h) and runs the AI.
void match_before_control(World& w);
// After the physics step and measurements: punches, hits, damage, reactions, knockdowns, the count, get-ups.
void match_after_step(World& w);
// The player's command for boxer k: started, buffered or refused (player_input.h; the boxer becomes the player's
// from now on).
void match_command(World& w, int k, FightCommand c);

}  // namespace boxing
