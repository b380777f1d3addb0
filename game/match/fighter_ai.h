#pragma once
// The opponent that decides: per boxer, seeded, it steers the motion graph (GraphWalker::request_clip) to punch when
// in range and the graph allows (the walk is in guard or footwork with no plan pending), follows a punch with
// another at once now and then (combinations), and when the other boxer's punch starts it defends with a
// probability after a human reaction time (~0.2 s; visual simple reaction times of trained athletes are 0.15-0.25 s):
// a block, a slip or a duck, chosen for the punch coming (hooks are ducked or blocked, straights slipped or blocked).
// A few style parameters per boxer (aggression, defence, favourite punches) drawn from the seed; the favourites are
// weighted by what has landed on this opponent so far (FighterStyle::prior_throws). It keeps fighting distance with
// the graph's steps, and presses an opponent a hard hit rocked back (FighterView::press).
#include <array>
#include <string>

#include "game/rng.h"

namespace eng::anim {
class GraphWalker;
}

namespace boxing {

inline constexpr std::array<const char*, 7> kPunchClips = {"jab",         "cross",         "lead_hook",      "rear_hook",
                                                           "lead_uppercut", "rear_uppercut", "combo_jab_cross"};

struct FighterStyle {
  double attack_rate = 0.8;  // punch attempts per second while in range and free to act (Poisson)
  double combo = 0.3;        // probability that a punch is followed at once by another
  double defence = 0.4;      // probability of defending a punch seen starting
  double reaction_s = 0.2;   // s from the other's punch starting to the defence being asked for
  double body_share = 0.25;  // share of punches aimed at the torso (the rest at the head)
  std::array<double, kPunchClips.size()> punch_weight{};  // favourite punches (relative)
  // What works: each punch's weight times (landed + 1) / (thrown + prior_throws) on this opponent so far, a boxer
  // throwing more of what lands (1 / prior_throws: the landing rate assumed before any is thrown). 0 = off.
  double prior_throws = 3.0;
};

// The AI's choices: the ranges its seeded styles are drawn from and its fixed habits.
struct FighterAiTuning {
  double attack_rate_min = 1.0, attack_rate_max = 1.6;  // attempts/s, a style's aggression drawn in this range
  double combo_min = 0.15, combo_max = 0.4;              // a style's chance of a combination, drawn in this range
  double defence_min = 0.25, defence_max = 0.55;         // a style's chance of defending a punch seen starting
  // s, a style's reaction time (visual simple reaction times of trained athletes are 0.15-0.25 s)
  double reaction_min = 0.18, reaction_max = 0.26;
  double body_share_min = 0.15, body_share_max = 0.35;  // a style's share of punches to the torso
  // Every punch's base weight (kPunchClips order), the jab most: CompuBox counts about half of all punches thrown as
  // jabs. Flatter gives a more varied, less realistic repertoire.
  std::array<double, kPunchClips.size()> punch_weight = {3.0, 1.5, 1.0, 1.0, 0.7, 0.7, 1.0};
  int favourites = 2;              // punches drawn as a style's favourites ...
  double favourite_weight = 1.0;   // ... each weighted up by this
  double hook_duck_share = 0.5;    // a hook seen coming is ducked this often (else blocked)
  // A straight seen coming: slipped left below slip_left_below, right below slip_right_below, else blocked.
  double slip_left_below = 0.35, slip_right_below = 0.7;
  double step_every = 2.0;         // s between footwork requests (a step takes ~0.3 s and settles): the cadence
  double min_attack_wait = 0.35;   // s, the shortest wait to the next attempt (a punch's own length)
  double min_attack_rate = 1e-3;   // attempts/s at the least (a stunned boxer's scaled rate, never 0)
  // s: the first attempt at first_attack plus up to first_attack_spread (both settle into guard first)
  double first_attack = 1.0, first_attack_spread = 1.0;
  // s a defence decided on but not startable then (a footwork move's feet still moving, the boxer's own punch about
  // to start) is asked for again each tick: without it 11 of 11 defences decided in a 60 s fight were dropped
  // (seed 5: the feet busy or a punch planned at the decision's tick; docs/decisions/defence-motions.md).
  double defence_patience = 0.3;
  // The chance of a counter: the opponent's punch over without landing (missed, blocked, slipped), a punch at once
  // when free and in range, the attack's wait skipped (0: never; hard's habit, docs/decisions/ai-levels.md).
  double counter_chance = 0.0;
  // The footwork's habits (FootworkAiTuning, scaled per boxer): the share of punches followed by a step out or off
  // the line, and the lateral moves' rate at range (1: the match's as tuned; easy's fewer).
  double exit_scale = 1.0, circle_scale = 1.0;
};

// The AI's level (--ai, the title screen): easy and hard move the ranges a style is drawn from and the habits; normal
// leaves the tuning as it is, so the fight at normal is the tuned one bit for bit (the same draws from the same seed).
// Easy: 0.35x the aggression, 0.3x the defence, 0.1 s slower, a predictable repertoire (one favourite weighted far
// up, half the combinations), no steps out after its punches and few lateral moves (it stays in range). Hard: 1.5x
// the aggression, 1.8x the defence, 0.03 s quicker (still within trained athletes' 0.15-0.25 s), 1.5x the
// combinations, counters after a punch of the opponent's misses; its footwork as tuned (more steps cost it punches).
// Measured, hard beats easy on 20 of 20 bouts: docs/decisions/ai-levels.md. false: not a level.
bool apply_ai_level(FighterAiTuning& t, const std::string& level);

// A style drawn from the seed within FighterAiTuning's ranges (aggression, combinations, defence, reaction, body
// share), and its favourite punches weighted up.
FighterStyle draw_fighter_style(Rng& rng, const FighterAiTuning& t = FighterAiTuning{});

struct FighterAi {
  Rng rng{1};
  FighterAiTuning tuning;
  FighterStyle style;
  double next_attack = 1.0;   // s, simulation time of the next attempt
  bool follow_up = false;     // the punch playing asked for a combination
  double defend_at = -1.0;    // s, a defence asked for at this time (< 0 none)
  double next_step = 0.0;     // s, the earliest next footwork request
  const char* defend_with = nullptr;
  double defend_until = -1.0;  // s, the defence asked for again until then (FighterAiTuning::defence_patience)
  int countered = -1;          // the opponent's last missed punch (Match::events index) a counter was weighed for
  int counters = 0;            // counters thrown (for tests and debugging)
  const char* last_request = nullptr;  // the clip last asked for (for the report / tests)
  bool aim_body = false;               // the next / current punch goes to the torso
  std::array<int, kPunchClips.size()> thrown_of{}, landed_of{};  // per punch, in this match (the match counts them)
};

// The kPunchClips index of a punch clip's name (-1: not one).
int punch_index(const std::string& clip);
// The next punch: a favourite (FighterStyle::punch_weight) weighted by what has landed (prior_throws), drawn from ai.rng.
const char* pick_punch(FighterAi& ai);

// What the AI sees this tick.
struct FighterView {
  double time = 0.0;
  bool free = false;           // in guard or footwork, no plan pending, standing (not stunned out, not down)
  bool punching = false;       // a punch clip is playing
  bool in_range = false;       // the other's head within reach of a straight punch
  bool too_far = false;        // out of reach: step in
  bool too_close = false;      // crowded: step out
  // A balance step (or its return to the stance) under way, or the feet left where the body cannot fight from
  // (stance_can_fight: crossed, in line, too wide): no footwork asked for. With the stagger, a step_forward over a
  // return step or from a switched stance puts the boxer down.
  bool feet_busy = false;
  bool press = false;          // the other boxer was just rocked back: step in after him at once (not at the cadence)
  const char* other_started = nullptr;  // the punch the other boxer started this tick (nullptr: none)
  bool other_to_body = false;  // ... aimed at the torso (a low block for it)
  // Standing in guard with no punch and no footwork move under way: a defence can start (a planned punch or step of
  // its own gives way to it).
  bool can_defend = false;
  int other_missed = -1;  // the other boxer's last punch (Match::events index) if it is over and did not land (-1)
  double slow = 1.0;           // attempts rate scale (a stunned boxer punches less)
};

// One tick of decisions; steers the walker. Returns the punch asked for this tick (nullptr none).
const char* fighter_ai_tick(FighterAi& ai, eng::anim::GraphWalker& walker, const FighterView& view, double dt);

}  // namespace boxing
