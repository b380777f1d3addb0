// Defence you can see and AI levels that differ (issue 65 items 2 and 4). The defences are measured on the simulated
// bodies (game/match/defence_metrics.h), in fights: both boxers' AIs defend every punch they see (the style's
// defence set to 1 after the draw), so a short fight has many of each. The figures and the commands behind the bounds
// are in docs/decisions/defence-motions.md and docs/decisions/ai-levels.md.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "game/match/fighter_ai.h"
#include "game/match/match.h"
#include "game/world.h"
#include "game/seed_rate.h"

namespace boxing {
namespace {

// The match's world on `seed`, both AIs at `levels`, defending every punch seen when `defend_all` (then started at
// fighting range, --start-apart 1; else from the ring's marks, as `build/boxing --scenario match` starts).
std::unique_ptr<World> fight(uint64_t seed, double seconds, bool defend_all, std::array<std::string, 2> levels,
                             double round_seconds = 180.0, int rounds = 3) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.scenario = "match";
  o.seed = seed;
  if (defend_all) o.start_apart = 1.0;
  o.ai = levels;
  o.round_seconds = round_seconds;
  o.rounds = rounds;
  o.rest_seconds = 2.0;
  auto w = make_world(o);
  EXPECT_TRUE(w) << w.error();
  if (!w) return nullptr;
  if (defend_all)
    for (auto& f : (*w)->match->fighter) f.ai.style.defence = 1.0;
  for (int i = 0; i < static_cast<int>(seconds * 240) && !(*w)->match->over; ++i) step_world(**w);
  return std::move(*w);
}

// Seeds 1-4, 60 s each, every punch seen defended: the defences played out, by clip, and the punches by their target
// and the defence they met ("head/block_high", "torso/none": thrown, landed). Run once for the tests below.
struct Measured {
  std::map<std::string, std::vector<DefenceMotion>> whole;
  std::map<std::string, std::array<int, 2>> into;
};

const Measured& measured() {
  static const Measured m = [] {
    Measured r;
    for (int seed = 1; seed <= 4; ++seed) {
      auto w = fight(seed, 60.0, true, {"normal", "normal"});
      if (!w) continue;
      for (const DefenceMotion& d : w->match->defences)
        if (d.whole) r.whole[d.clip].push_back(d);
      for (const PunchEvent& e : w->match->events) {
        auto& n = r.into[e.target + "/" + (e.defence.empty() ? std::string("none") : e.defence)];
        ++n[0];
        n[1] += e.landed ? 1 : 0;
      }
    }
    for (const auto& [clip, v] : r.whole) std::printf("  %s: %zu played out\n", clip.c_str(), v.size());
    return r;
  }();
  return m;
}

// The share of `v` whose value (get) reaches `at_least`.
template <class Get>
double share(const std::vector<DefenceMotion>& v, double at_least, Get get) {
  int n = 0;
  for (const DefenceMotion& d : v) n += get(d) >= at_least ? 1 : 0;
  return v.empty() ? 0.0 : static_cast<double>(n) / v.size();
}

// Slips move the simulated head 15 cm or more off the line to the opponent, to the slip's side, and the duck drops it
// 20 cm or more (issue 65), in most of those played out. measured (the fights of seeds 1-10, normal and the levels'
// bouts, docs/decisions/defence-motions.md): slip_left 36 of 46 (0.78), slip_right 44 of 52 (0.85), duck 17 of 23
// (0.74); here (seeds 1-4) 0.83, 1.00, 0.88. bound 0.6: under the least measured, with room for this test's small
// sample (a hit or the feet's balance steps may take a slip's lean).
TEST(Defence, SlipsAndDucksMoveTheSimulatedHeadAsFarAsTheIssueSays) {
  const Measured& m = measured();
  for (const char* slip : {"slip_left", "slip_right"}) {
    const auto it = m.whole.find(slip);
    ASSERT_NE(it, m.whole.end()) << "no " << slip << " played out";
    ASSERT_GE(it->second.size(), 3u) << slip;
    const double s = share(it->second, 0.15, [](const DefenceMotion& d) { return d.side_m; });
    std::printf("  %s: %.2f of %zu moved the head 15 cm or more off the line\n", slip, s, it->second.size());
    EXPECT_GE(s, 0.6) << slip;
  }
  const auto duck = m.whole.find("duck");
  ASSERT_NE(duck, m.whole.end()) << "no duck played out";
  ASSERT_GE(duck->second.size(), 3u);
  const double s = share(duck->second, 0.20, [](const DefenceMotion& d) { return d.drop_m; });
  std::printf("  duck: %.2f of %zu dropped the head 20 cm or more\n", s, duck->second.size());
  EXPECT_GE(s, 0.6);
}

// The blocks put the gloves where they say: block_high's both gloves above the head's centre at the fullest, block_low's
// both below the chest's centre, in at least half of those played out. measured (fights of seeds 1-10, normal and
// the levels' bouts, 75 and 104 played out): 0.71 and 0.66; bound 0.5: this test's sample is small (a hit or a
// punch of its own cuts a block short of its fullest).
TEST(Defence, BlocksPutTheGlovesOverTheHeadOrOverTheBody) {
  const Measured& m = measured();
  const auto hi = m.whole.find("block_high"), lo = m.whole.find("block_low");
  ASSERT_NE(hi, m.whole.end());
  ASSERT_NE(lo, m.whole.end());
  const double up = share(hi->second, 0.0, [](const DefenceMotion& d) { return d.gloves_above_head_m; });
  const double down = share(lo->second, 0.0, [](const DefenceMotion& d) { return d.gloves_below_chest_m; });
  std::printf("  gloves above the head: %.2f of %zu high blocks; below the chest: %.2f of %zu low blocks\n", up,
              hi->second.size(), down, lo->second.size());
  EXPECT_GE(up, 0.5);
  EXPECT_GE(down, 0.5);
}

// A punch to the head into a high block lands less often than one to the head into no defence (the share landed, the
// same fights). The low block against the body's punches is not asserted: measured, it does not lower what lands
// (docs/decisions/defence-motions.md, "What falls short").
TEST(Defence, AHighBlockLowersWhatLandsOnTheHead) {
  const Measured& m = measured();
  const auto block = m.into.find("head/block_high"), none = m.into.find("head/none");
  ASSERT_NE(block, m.into.end());
  ASSERT_NE(none, m.into.end());
  ASSERT_GE(block->second[0], 5) << "too few punches met a block to say";
  const double on_block = static_cast<double>(block->second[1]) / block->second[0];
  const double open = static_cast<double>(none->second[1]) / none->second[0];
  std::printf("  to the head: %d of %d landed into a high block (%.2f), %d of %d into none (%.2f)\n", block->second[1],
              block->second[0], on_block, none->second[1], none->second[0], open);
  EXPECT_LT(on_block, open);
}

TEST(AiLevels, NormalLeavesTheTuningAsItIsAndEasyAndHardDiffer) {
  const FighterAiTuning base;
  FighterAiTuning n = base, e = base, h = base;
  ASSERT_TRUE(apply_ai_level(n, "normal"));
  ASSERT_TRUE(apply_ai_level(e, "easy"));
  ASSERT_TRUE(apply_ai_level(h, "hard"));
  EXPECT_FALSE(apply_ai_level(n, "brutal"));
  EXPECT_EQ(n.attack_rate_max, base.attack_rate_max);
  EXPECT_EQ(n.counter_chance, base.counter_chance);
  EXPECT_EQ(n.exit_scale, base.exit_scale);
  EXPECT_GT(e.reaction_min, base.reaction_min);  // easy: slower, defends less, stays in range, no counters
  EXPECT_LT(e.defence_max, base.defence_max);
  EXPECT_LT(e.exit_scale, base.exit_scale);
  EXPECT_EQ(e.counter_chance, 0.0);
  EXPECT_LT(h.reaction_min, base.reaction_min);  // hard: quicker, defends more, counters, busier
  EXPECT_GT(h.defence_max, base.defence_max);
  EXPECT_GT(h.counter_chance, 0.0);
  EXPECT_GT(h.attack_rate_max, base.attack_rate_max);
}

// Hard beats easy (issue 65: at least 8 of 10 seeds, both colours). Here seeds 1-2 each way, the bout as measured
// (3 rounds of 60 s, 2 s rests: `build/boxing --headless --scenario match --ai hard,easy --rounds 3 --round-seconds 60
// --rest-seconds 2 --seconds 200 --seed N`), CI's time; the full measurement, seeds 1-10 each way, is in
// docs/decisions/ai-levels.md (hard won 20 of 20). A seed passes when the hard boxer wins (decision or KO). measured
// here: won all 4 on points, landed 24-17, 28-13 as red, 33-12, 32-13 as blue; bound: all 4.
TEST(AiLevels, HardBeatsEasyInBothColours) {
  constexpr int kRounds = 3;
  constexpr double kRoundS = 60.0;
  for (int hard = 0; hard < 2; ++hard) {
    const seed_rate::Rate r = seed_rate::over_seeds(hard == 0 ? "hard red v easy blue" : "easy red v hard blue", 1, 2,
                                                    [&](int seed) {
      std::array<std::string, 2> lv = {"easy", "easy"};
      lv[hard] = "hard";
      auto w = fight(seed, kRounds * kRoundS + 10.0, false, lv, kRoundS, kRounds);
      if (!w) return std::string("no world");
      const int winner = w->match->bout.result.winner;
      std::printf("  seed %d: winner %d (hard is %d), landed %d / %d\n", seed, winner, hard,
                  w->match->fighter[0].landed, w->match->fighter[1].landed);
      return w->match->over && winner == hard ? std::string() : "the hard boxer did not win";
    });
    EXPECT_TRUE(r.all());
  }
}

}  // namespace
}  // namespace boxing
