// The match's rules as the player meets them, each built directly rather than waited for in a fight: both boxers are
// handed to the (idle) player, so no AI punch changes the situation, and a boxer is put down by taking its
// consciousness (the panel's set event) and pushing its chest (a push event), the public input path.
//  * the knock-out at ten: a downed boxer kept down (its stand-up never starts: MatchTuning::min_down_time past the
//    count) is counted 1 to 10 on the HUD's banner and loses by KO the tick the count passes count_seconds;
//  * the neutral corner: a standing opponent within neutral_corner_within of the downed boxer's pelvis when its get-up
//    starts is sent to its mark; out of that distance it stays where it is;
//  * the bout: at the last round's bell the judges' decision (each judge's card from the round's landed punches and
//    knockdowns, 10-point must); the three-knockdown rule; a rest between rounds in the corners;
//  * the HUD's round clock: round number and m:ss left.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "game/hud.h"
#include "game/interaction/interaction.h"
#include "game/match/match.h"
#include "game/world.h"

namespace boxing {
namespace {

constexpr int kTicksPerSecond = 240;

std::unique_ptr<World> idle_match(double round_seconds = 180.0, int rounds = 3, double start_apart = -1.0) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.scenario = "match";
  o.seed = 1;
  o.round_seconds = round_seconds;
  o.rounds = rounds;
  if (start_apart > 0.0) o.start_apart = start_apart;
  auto w = make_world(o);
  EXPECT_TRUE(w) << w.error();
  if (!w) return nullptr;
  // Both boxers the player's: neither punches unless commanded (match_command), so nothing but the test acts.
  for (int k = 0; k < 2; ++k) {
    InputEvent e;
    e.kind = InputKind::Set;
    e.boxer = k;
    e.control = "player";
    interaction_submit(**w, e);
  }
  return std::move(*w);
}

void run(World& w, double seconds) {
  for (int i = 0; i < static_cast<int>(seconds * kTicksPerSecond); ++i) step_world(w);
}

// Boxer k put down: no consciousness left (the servo's gains and the root assist scale with it) and a push on its
// chest along `dir` (world, horizontal): 1500 N for 0.2 s, which floors a boxer standing in guard either way (seed
// 1 at 1 s: down 0.6 s after it pushed away from the opponent, 1.1 s after it pushed toward him; 900 N toward him
// left it standing). Returns whether the match counted it down (a GetUp opened) within 4 s.
bool put_down(World& w, int k, const Eigen::Vector3d& dir) {
  InputEvent out;
  out.kind = InputKind::Set;
  out.boxer = k;
  out.consciousness = 0.0;
  interaction_submit(w, out);
  InputEvent push;
  push.kind = InputKind::Push;
  push.boxer = k;
  push.bone = "chest";
  push.vec = 1500.0 * dir.normalized();
  push.duration = 0.2;
  interaction_submit(w, push);
  for (int i = 0; i < 4 * kTicksPerSecond && w.match->fighter[k].getup < 0; ++i) step_world(w);
  return w.match->fighter[k].getup >= 0;
}

// From boxer k's pelvis toward the other's (floor plane).
Eigen::Vector3d toward_other(const World& w, int k) {
  const Eigen::Vector3d a = w.data.x[w.boxers[k].bodies.body[0]].p, b = w.data.x[w.boxers[1 - k].bodies.body[0]].p;
  Eigen::Vector3d d = b - a;
  d.z() = 0.0;
  return d.normalized();
}

double pelvis_distance(const World& w) {
  return (w.data.x[w.boxers[0].bodies.body[0]].p - w.data.x[w.boxers[1].bodies.body[0]].p).head<2>().norm();
}

// Boxer k down and kept down (its stand-up would start at min_down_time: moved past the count, it never does): the
// banner counts "RED DOWN   1" to "RED DOWN   10" (BLUE for boxer 1), one number a second from the count's start, and the
// tick the count passes count_seconds the match is over, a KO for the other boxer, shown on the banner and in the
// report. The boxer still lies there: nothing but the count ended it.
void knock_out_at_ten(int k) {
  auto w = idle_match();
  ASSERT_TRUE(w);
  World& world = *w;
  Match& mt = *world.match;
  mt.tuning.min_down_time = 2.0 * mt.tuning.count_seconds;
  run(world, 1.0);
  ASSERT_TRUE(put_down(world, k, -toward_other(world, k))) << "boxer " << k << " did not go down";
  const GetUp& g = mt.getups[mt.fighter[k].getup];
  const std::string side = k == 0 ? "RED" : "BLUE";
  std::vector<std::string> banners;
  double over_at = -1.0;
  // The standing boxer walks to a neutral corner first (the count runs only from count_when_away): 20 s is ample.
  const double most = 20.0 + mt.tuning.count_seconds;
  for (int i = 0; i < static_cast<int>(most * kTicksPerSecond) && over_at < 0; ++i) {
    const std::string b = match_hud(world).banner;
    if (banners.empty() || banners.back() != b) banners.push_back(b);
    EXPECT_FALSE(mt.over) << "over at " << world.data.time - g.count_from << " s into the count";
    step_world(world);
    if (mt.over) over_at = world.data.time;
  }
  // "RED DOWN" until the count starts (the other in a neutral corner), then one number a second.
  std::vector<std::string> count;
  if (!banners.empty() && banners.front() == side + " DOWN") count.push_back(side + " DOWN");
  for (int n = 1; n <= 10; ++n) count.push_back(side + " DOWN   " + std::to_string(n));
  EXPECT_EQ(banners, count);
  ASSERT_GE(over_at, 0.0) << "no knock-out " << mt.tuning.count_seconds + 1.0 << " s after the knockdown";
  // The first tick past the count (kPhysicsDt = 1/240 s): not a tick earlier, not a tick later; every tick from the
  // count's start either counted or stopped (the standing boxer too close).
  ASSERT_GE(g.count_from, g.down_at);
  EXPECT_EQ(g.counted_ticks, static_cast<int>(mt.tuning.count_seconds) * kTicksPerSecond + 1);
  EXPECT_NEAR(over_at - g.count_from, static_cast<double>(g.counted_ticks + g.paused_ticks) / kTicksPerSecond, 1e-9);
  EXPECT_GE(g.count_distance_min, mt.tuning.count_when_away);
  // The bout ends at once: the winner, by KO, in round 1 at the time the count passed ten.
  const std::string ko = std::string(k == 1 ? "RED" : "BLUE") + " WINS BY KO IN ROUND 1";
  EXPECT_EQ(mt.bout.result.text.rfind(ko, 0), 0u) << mt.bout.result.text;
  EXPECT_EQ(match_hud(world).banner, mt.bout.result.text);
  const nlohmann::json r = match_report(world)["result"];
  EXPECT_EQ(r["winner"], 1 - k);
  EXPECT_EQ(r["method"], "ko");
  EXPECT_EQ(r["round"], 1);
  EXPECT_NEAR(r["time_s"].get<double>(), over_at, 1e-9);
  EXPECT_TRUE(r["finished"].get<bool>());
  EXPECT_EQ(mt.bout.phase, BoutPhase::Over);
  EXPECT_EQ(world.boxers[k].ctl.state.state, BoxerState::Down);
  EXPECT_LT(mt.getups[mt.fighter[k].getup].up_at, 0.0);  // never up
}

TEST(MatchRules, ADownedRedBoxerNotUpAtTheCountOfTenLosesByKnockOut) { knock_out_at_ten(0); }
TEST(MatchRules, ADownedBlueBoxerNotUpAtTheCountOfTenLosesByKnockOut) { knock_out_at_ten(1); }

// Red put down toward blue: blue is sent to the neutral corner farthest from red (footwork_ai.h neutral_corner) and
// walks there (nobody is set anywhere: teleports stay 0); the count starts once blue is count_when_away from red.
// Bound: blue 0.5 m farther from red before red is up or 6 s have passed
// (measured 0.76 m: the walk's moves carry 0.25-0.3 m per 1-1.5 s, the first spent turning to face red).
TEST(MatchRules, AStandingOpponentWalksToANeutralCornerWhileTheOtherIsDown) {
  auto w = idle_match();
  ASSERT_TRUE(w);
  World& world = *w;
  Match& mt = *world.match;
  run(world, 1.0);
  ASSERT_TRUE(put_down(world, 0, toward_other(world, 0)));
  const double down_at = world.data.time;
  ASSERT_TRUE(mt.fighter[1].go_to_active);
  // The corner farthest from red among the ring's four (inset corner_inset).
  const Eigen::Vector2d red = world.data.x[world.boxers[0].bodies.body[0]].p.head<2>();
  const Eigen::Vector2d half = ring_half_size(world) - Eigen::Vector2d::Constant(mt.tuning.footwork.corner_inset);
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      EXPECT_LE((Eigen::Vector2d(sx * half.x(), sy * half.y()) - red).norm(), (mt.fighter[1].go_to - red).norm() + 1e-9);
  const double start = pelvis_distance(world);
  double farthest = start;
  while (world.data.time < down_at + 6.0 && world.boxers[0].ctl.state.state != BoxerState::Guard) {
    step_world(world);
    farthest = std::max(farthest, pelvis_distance(world));
  }
  std::printf("  blue from red: %.2f m at the knockdown, %.2f m at the farthest\n", start, farthest);
  EXPECT_GE(farthest - start, 0.5);
  EXPECT_EQ(mt.teleports, 0);
  ASSERT_FALSE(mt.getups.empty());
  const GetUp& g = mt.getups.front();
  if (g.count_from >= 0.0) {
    EXPECT_GE(g.count_from, down_at);
  }
}

// The count runs only while the standing boxer is count_when_away from the downed one: with that distance out of
// reach mid-count (as if blue came back at red), the count stops at its number, the banner says why and no knock-out
// comes however long it stops; with it back, the count goes on from where it stopped. Red is kept down (min_down_time
// past the count), so only the count can end the match.
TEST(MatchRules, TheCountStopsWhileTheStandingBoxerIsTooCloseAndGoesOnFromItsNumber) {
  auto w = idle_match();
  ASSERT_TRUE(w);
  World& world = *w;
  Match& mt = *world.match;
  mt.tuning.min_down_time = 4.0 * mt.tuning.count_seconds;
  run(world, 1.0);
  ASSERT_TRUE(put_down(world, 0, -toward_other(world, 0)));
  const GetUp& g = mt.getups[mt.fighter[0].getup];
  for (int i = 0; i < 20 * kTicksPerSecond && g.counted_ticks < 4 * kTicksPerSecond; ++i) step_world(world);
  ASSERT_EQ(g.counted_ticks, 4 * kTicksPerSecond) << "the count did not reach 4 s in 20 s";
  EXPECT_EQ(match_hud(world).banner, "RED DOWN   5");
  const double away = mt.tuning.count_when_away;
  mt.tuning.count_when_away = 1e3;
  run(world, mt.tuning.count_seconds + 1.0);
  EXPECT_FALSE(mt.over);
  EXPECT_EQ(g.counted_ticks, 4 * kTicksPerSecond);
  EXPECT_GE(g.paused_ticks, static_cast<int>(mt.tuning.count_seconds) * kTicksPerSecond);
  EXPECT_EQ(match_hud(world).banner, "RED DOWN   5   (count stopped: to the neutral corner)");
  mt.tuning.count_when_away = away;
  run(world, 2.0);
  EXPECT_FALSE(mt.over);
  EXPECT_EQ(match_hud(world).banner, "RED DOWN   7");
  run(world, 4.5);
  EXPECT_TRUE(mt.over);
  EXPECT_EQ(mt.bout.result.method, "ko");
  EXPECT_EQ(mt.bout.result.winner, 1);
  EXPECT_GE(g.count_distance_min, away);
  EXPECT_EQ(mt.teleports, 0);
}

// One round of 4 s: red jabs an idle blue twice (player commands at 2 s), blue throws nothing. At the bell the bout
// is over at once: the round's card (its punches, the fighters' own counts) and the judges' decision, which names red
// if a jab landed (every judge's measure is then red's alone) and is a draw if none did.
TEST(MatchRules, AtTheLastBellTheJudgesCardsDecideTheBout) {
  auto w = idle_match(4.0, 1, 0.95);  // at punching range: a jab can land
  ASSERT_TRUE(w);
  World& world = *w;
  Match& mt = *world.match;
  run(world, 2.0);
  for (int i = 0; i < 2; ++i) match_command(world, 0, FightCommand::Jab);
  while (world.data.time < mt.bout.round_seconds - 1e-6) {
    EXPECT_FALSE(mt.over);
    step_world(world);
  }
  step_world(world);
  ASSERT_TRUE(mt.over);
  EXPECT_GE(mt.fighter[0].thrown, 1);
  EXPECT_EQ(mt.fighter[1].thrown, 0);
  const int red = mt.fighter[0].landed;
  const nlohmann::json r = match_report(world);
  ASSERT_EQ(r["rounds"].size(), 1u);
  const nlohmann::json& card = r["rounds"][0];
  EXPECT_EQ(card["landed"][0], red);
  EXPECT_EQ(card["thrown"][0], mt.fighter[0].thrown);
  EXPECT_EQ(card["thrown"][1], 0);
  for (const auto& j : card["judges"]) EXPECT_EQ(j, red > 0 ? nlohmann::json({10, 9}) : nlohmann::json({10, 10}));
  EXPECT_EQ(r["result"]["method"], red > 0 ? "decision" : "draw");
  if (red > 0) {
    EXPECT_EQ(r["result"]["winner"], 0);
  }
  EXPECT_EQ(r["result"]["round"], 1);
  std::printf("round of 4 s: red landed %d of %d: %s\n", red, mt.fighter[0].thrown, mt.bout.result.text.c_str());
}

// The judges' rule on its own (judge_round): the round's winner by the judge's measure 10, the loser 9; even within
// even_share: 10-10; a knockdown costs the downed boxer a point, then both are raised until the better has 10.
TEST(BoutRules, AJudgeScoresTenPointMustFromTheLandedPunchesAndTheKnockdowns) {
  const BoutTuning t;
  std::vector<PunchEvent> ev;
  auto land = [&](int boxer, double at, double damage) {
    PunchEvent e;
    e.t = at, e.boxer = boxer, e.landed = true, e.damage = damage, e.impulse = 10.0 * damage;
    ev.push_back(e);
  };
  land(0, 1.0, 0.1), land(0, 2.0, 0.1), land(0, 3.0, 0.1), land(1, 4.0, 0.25);
  const std::array<int, 2> none{0, 0};
  EXPECT_EQ(judge_round(JudgeReads::Landed, ev, 0.0, 10.0, none, t), (std::array<int, 2>{10, 9}));  // 3 to 1
  EXPECT_EQ(judge_round(JudgeReads::Damage, ev, 0.0, 10.0, none, t), (std::array<int, 2>{10, 9}));  // 0.30 to 0.25
  EXPECT_EQ(judge_round(JudgeReads::Impulse, ev, 0.0, 10.0, none, t), (std::array<int, 2>{10, 9}));
  EXPECT_EQ(judge_round(JudgeReads::Landed, ev, 3.0, 10.0, none, t), (std::array<int, 2>{10, 10}));  // 1 to 1: even
  EXPECT_EQ(judge_round(JudgeReads::Landed, ev, 0.0, 2.5, none, t), (std::array<int, 2>{10, 9}));   // the window
  // A knockdown: the round's loser on punches who also went down 10-8; the winner on punches who went down 9-9 -> 10-10.
  EXPECT_EQ(judge_round(JudgeReads::Landed, ev, 0.0, 10.0, {0, 1}, t), (std::array<int, 2>{10, 8}));
  EXPECT_EQ(judge_round(JudgeReads::Landed, ev, 0.0, 10.0, {1, 0}, t), (std::array<int, 2>{10, 10}));
  EXPECT_EQ(judge_round(JudgeReads::Landed, ev, 0.0, 10.0, {0, 5}, t), (std::array<int, 2>{10, t.min_score}));
  // The decision: each judge's totals, then the boxer more judges name.
  RoundCard a, b;
  a.judges = {{{10, 9}, {10, 9}, {9, 10}}};
  b.judges = {{{10, 9}, {10, 9}, {10, 10}}};
  EXPECT_EQ(decide({a, b}), (std::array<int, 3>{0, 2, 1}));   // 20-18, 20-18, 19-20: red by a split decision
  b.judges = {{{9, 10}, {10, 9}, {10, 10}}};
  EXPECT_EQ(decide({a, b}), (std::array<int, 3>{-1, 1, 1}));  // 19-19, 20-18, 19-20: a split draw
  b.judges = {{{9, 10}, {9, 10}, {10, 10}}};
  EXPECT_EQ(decide({a, b}), (std::array<int, 3>{-1, 0, 1}));  // 19-19, 19-19, 19-20: one card is no majority (a draw)
}

// Three knockdowns of one boxer in one round end the bout at once: a technical knock-out (the counts' GetUps made as
// the referee makes them, the knockdowns counted by the match).
TEST(MatchRules, ThreeKnockdownsInARoundAreATechnicalKnockOut) {
  auto w = idle_match(180.0);
  ASSERT_TRUE(w);
  World& world = *w;
  Match& mt = *world.match;
  run(world, 1.0);
  mt.fighter[1].knockdowns = mt.bout.knockdowns0[1] + mt.bout.tuning.tko_knockdowns - 1;
  step_world(world);
  EXPECT_FALSE(mt.over);
  ++mt.fighter[1].knockdowns;
  step_world(world);
  ASSERT_TRUE(mt.over);
  const nlohmann::json r = match_report(world)["result"];
  EXPECT_EQ(r["winner"], 0);
  EXPECT_EQ(r["method"], "tko");
  EXPECT_EQ(r["round"], 1);
  EXPECT_EQ(mt.bout.result.text.rfind("RED WINS BY TKO IN ROUND 1", 0), 0u) << mt.bout.result.text;
}

// Between rounds: at the bell both boxers walk to two opposite corners (no punches), the HUD shows the rest's clock and
// the round's cards, and the next round starts after rest_seconds with each boxer given back rest_recovery of the
// consciousness it was missing.
TEST(MatchRules, BetweenRoundsTheBoxersRestInOppositeCornersAndRecover) {
  auto w = idle_match(3.0, 2);
  ASSERT_TRUE(w);
  World& world = *w;
  Match& mt = *world.match;
  mt.bout.tuning.rest_seconds = 12.0;
  while (mt.bout.phase == BoutPhase::Fighting) step_world(world);
  ASSERT_EQ(mt.bout.phase, BoutPhase::Rest);
  ASSERT_EQ(mt.bout.cards.size(), 1u);
  EXPECT_TRUE(match_hud(world).resting);
  EXPECT_EQ(match_clock_text(match_hud(world)), "REST   0:12");
  EXPECT_EQ(match_hud(world).banner.rfind("END OF ROUND 1", 0), 0u);
  // Opposite corners: the spots 2 x (half the ring less the inset) apart each way.
  const Eigen::Vector2d c0 = mt.bout.corner[0], c1 = mt.bout.corner[1];
  EXPECT_NEAR((c0 + c1).norm(), 0.0, 1e-12);
  for (int k = 0; k < 2; ++k) world.boxers[k].ctl.root_spring.set_consciousness(0.6);
  const int thrown = mt.fighter[0].thrown + mt.fighter[1].thrown;
  double closer[2] = {0.0, 0.0}, before[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) closer[k] = (world.data.x[world.boxers[k].bodies.body[0]].p.head<2>() - (k ? c1 : c0)).norm();
  while (mt.bout.phase == BoutPhase::Rest) {
    for (int k = 0; k < 2; ++k) before[k] = world.boxers[k].ctl.root_spring.consciousness();
    step_world(world);
  }
  EXPECT_EQ(mt.bout.round, 2);
  EXPECT_EQ(mt.fighter[0].thrown + mt.fighter[1].thrown, thrown);  // no punches in the rest
  for (int k = 0; k < 2; ++k) {
    const double now = (world.data.x[world.boxers[k].bodies.body[0]].p.head<2>() - (k ? c1 : c0)).norm();
    std::printf("boxer %d: %.2f m from its corner at the bell, %.2f m after the rest\n", k, closer[k], now);
    EXPECT_LT(now, closer[k] - 0.5);  // walked most of the way (a corner is ~2.2 m from a mark)
    // Half of what was missing at the rest's last tick given back (to the tick's own recovery, under 1e-3).
    EXPECT_NEAR(world.boxers[k].ctl.root_spring.consciousness(), before[k] + 0.5 * (1.0 - before[k]), 1e-3);
    EXPECT_LT(before[k], 0.9);
  }
}

// The HUD's clock: the round and the whole seconds left in it as m:ss, from the match time and --round-seconds.
TEST(MatchRules, TheHudShowsTheRoundAndTheTimeLeftAsMinutesAndSeconds) {
  auto w = idle_match(180.0);
  ASSERT_TRUE(w);
  World& world = *w;
  EXPECT_EQ(match_clock_text(match_hud(world)), "ROUND 1   3:00");
  run(world, 0.5);
  EXPECT_EQ(match_clock_text(match_hud(world)), "ROUND 1   2:59");  // 179.5 s left: whole seconds
  // Later in a match: the time set directly (the clock reads only the match time and the round's length).
  auto at = [&](double t) {
    world.data.time = t;
    return match_clock_text(match_hud(world));
  };
  EXPECT_EQ(at(61.25), "ROUND 1   1:58");
  EXPECT_EQ(at(170.0), "ROUND 1   0:10");
  EXPECT_EQ(at(179.99), "ROUND 1   0:00");
  // The round and its start are the bout's (bout.h): round 2 of 90 s rounds, begun at 150 s (after a minute's rest).
  Bout& bt = world.match->bout;
  bt.round_seconds = 90.0;  // --round-seconds 90
  EXPECT_EQ(at(30.0), "ROUND 1   1:00");
  bt.round = 2, bt.phase_from = 150.0;
  EXPECT_EQ(at(155.0), "ROUND 2   1:25");
  // No banner while both stand and the fight goes on.
  EXPECT_EQ(match_hud(world).banner, "");
}

}  // namespace
}  // namespace boxing
