#pragma once
// THE BOUT: the match as boxing, round by round. N rounds of round_seconds opened and closed by the bell, a rest
// between them in which both boxers walk to their own corners and get part of their consciousness back, three judges
// scoring each round on the 10-point must system, and the result: a knock-out (not up by ten, referee.cpp), a
// technical knock-out (tko_knockdowns knockdowns in one round: the three-knockdown rule), else the judges' decision or
// a draw. Rules and their sources: docs/decisions/bout-rules.md.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace boxing {

struct Match;
struct PunchEvent;
struct World;

struct BoutTuning {
  int rounds = 3;
  double rest_seconds = 60.0;
  int tko_knockdowns = 3;       // knockdowns of one boxer in one round: the referee stops the fight
  double rest_recovery = 0.5;   // share of the consciousness a boxer is missing that a rest gives back
  double even_share = 0.1;      // a judge's measure closer than this share of the larger side: an even round (10-10)
  int min_score = 6;            // no round card below this
};

// What one judge weighs in a round (each judge a different reading of "effective punching", so the three cards can
// differ): landed punches, their damage, their impulse.
enum class JudgeReads { Landed, Damage, Impulse };
inline constexpr std::array<JudgeReads, 3> kJudges = {JudgeReads::Landed, JudgeReads::Damage, JudgeReads::Impulse};

struct RoundCard {
  int round = 1;
  double from_s = 0.0, to_s = 0.0;  // the match clock at its bells
  std::array<int, 2> landed{}, thrown{}, knockdowns{};
  std::array<std::array<int, 2>, 3> judges{};  // per judge: [red, blue]
};

enum class BoutPhase { Fighting, Rest, Over };

struct BoutResult {
  int winner = -1;        // 0 red, 1 blue, -1 none (a draw, or not decided)
  std::string method;     // "ko" | "tko" | "decision" | "draw" ("" while the bout goes on)
  int round = 0;          // the round it ended in
  double time_s = 0.0;    // into that round
  std::string text;       // for the HUD and the report ("RED WINS BY KO IN ROUND 2 (1:12)")
};

struct Bout {
  BoutTuning tuning;
  double round_seconds = 180.0;
  int round = 1;
  BoutPhase phase = BoutPhase::Fighting;
  double phase_from = 0.0;                   // s, the match clock when this round or rest began
  std::array<int, 2> landed0{}, thrown0{}, knockdowns0{};  // the fighters' totals at this round's bell
  std::vector<RoundCard> cards;              // the rounds scored so far
  BoutResult result;
  std::array<Eigen::Vector2d, 2> corner{};  // the corners the boxers rest in (world m, floor plane; set at each bell)
};

// One judge's card for a round: reading `what` of the round's landed punches (events in [from, to)), the round's
// winner 10 and the loser 9 (10-10 even within even_share), one point off per knockdown suffered, then both raised
// until the better is 10 (the must), none below min_score.
std::array<int, 2> judge_round(JudgeReads what, const std::vector<PunchEvent>& events, double from, double to,
                               const std::array<int, 2>& knockdowns, const BoutTuning& t);
// The round [from, to) scored by the three judges, with its punch counts (the fighters' totals less those at its bell).
RoundCard score_round(const Match& mt, int round, double from, double to);
// The decision over the cards: each judge's totals name a winner or a draw; the boxer a majority of the judges names
// wins, else a draw (one card each and one even, or one card and two even). (winner, judges for red, judges for blue)
std::array<int, 3> decide(const std::vector<RoundCard>& cards);

// The bout's start: the rounds and their length.
void bout_setup(World& w);
// After the referee each tick: the three-knockdown rule, the bell (a round's end waits for a count under way to end),
// the rest and the next round.
void bout_tick(World& w);
// The bout over now: the result (a KO from the referee, a TKO, the decision).
void bout_end(World& w, int winner, const char* method);
// The round's clock: seconds left in the round (or the rest).
double bout_clock_left(const World& w);

}  // namespace boxing
