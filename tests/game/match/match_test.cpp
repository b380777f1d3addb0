// The match (game/match/): punches are counted from the clips the AI asks for, land only through the solver's hit
// events (the striking glove on head or torso at speed; glove or arm = blocked), a knocked-down boxer gets up from the
// way it lies, and the same seed gives the same fight. The fight's behaviour is asserted over fixed seed ranges
// (seed_rate.h: seeds 1-N, each test's N and rate stated, the measurements in docs/decisions/test-bounds.md); a get-up
// and a rock are brought about directly (a scripted push, a lower rocking threshold) rather than waited for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

#include "engine/anim/motion_graph.h"
#include "game/interaction/interaction.h"
#include "game/match/body_parts.h"
#include "game/match/fighter_ai.h"
#include "game/match/footwork_metrics.h"
#include "game/match/punch_aim.h"
#include "game/seed_rate.h"
#include "game/match/match.h"
#include "game/person_strength.h"
#include "game/world.h"

namespace boxing {
namespace {

constexpr double kAtRange = 1.0;  // m, --start-apart for the tests of what happens at range

// The match scenario's world on `seed`, its MatchTuning changed by `tune` (nullptr when it cannot be built). The
// boxers start at fighting range (--start-apart 1.0): these tests are about punches, hits and get-ups, not the walk in
// from the ring's marks (StandingBoxersOutOfRangeWalkToEachOther).
std::unique_ptr<World> match_world(uint64_t seed, const std::function<void(MatchTuning&)>& tune) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.scenario = "match";
  o.seed = seed;
  o.start_apart = kAtRange;
  auto w = make_world(o);
  EXPECT_TRUE(w) << w.error();
  if (!w) return nullptr;
  if (tune) tune((*w)->match->tuning);
  return std::move(*w);
}

std::unique_ptr<World> run_match(uint64_t seed, double seconds, const std::function<void(MatchTuning&)>& tune = {}) {
  auto w = match_world(seed, tune);
  if (!w) return nullptr;
  for (int i = 0; i < static_cast<int>(seconds * 240); ++i) step_world(*w);
  return w;
}

// The rules every punch of a fight obeys (PunchesLandOnly...): "" when all do, otherwise which broke them.
std::string punches_obey_the_rules(const World& w) {
  const Match& m = *w.match;
  seed_rate::Why why;
  int thrown[2] = {0, 0}, landed[2] = {0, 0};
  for (size_t i = 0; i < m.events.size(); ++i) {
    const PunchEvent& e = m.events[i];
    const std::string at = e.punch + " at " + std::to_string(e.t) + " s";
    ++thrown[e.boxer];
    const bool resolving = m.fighter[e.boxer].landing == int(i);  // its impact window still open at the end
    if (e.landed) {
      ++landed[e.boxer];
      why.check(e.hit_part == "head" || e.hit_part == "torso", at + " landed on " + e.hit_part);
      why.check(e.speed >= m.tuning.land_speed, at + " landed slow");
      why.check(e.impulse > 0.0, at + " landed with no impulse");
      if (!resolving) {
        why.check(e.damage > 0.0, at + " landed with no damage");
      }
      why.check(!e.blocked, at + " landed and blocked");
    }
    if (e.blocked) {
      why.check(e.hit_part == "glove" || e.hit_part == "arm", at + " blocked by " + e.hit_part);
    }
    // The glove moved (a punch, not a pose), unless the other's punch landing as it started cut it short (the hit
    // reaction is forced over it).
    bool cut_short = false;
    for (const PunchEvent& o : m.events)
      cut_short = cut_short || (o.boxer != e.boxer && o.landed && o.t <= e.t && o.t > e.t - 0.6);
    if (e.t < w.data.time - 0.2 && !cut_short) {
      why.check(e.peak_speed > 0.5, at + ": the glove did not move");
    }
  }
  for (int k = 0; k < 2; ++k) {
    why.check(m.fighter[k].thrown == thrown[k] && m.fighter[k].landed == landed[k], "the counts disagree");
    why.check(thrown[k] >= 4, "boxer " + std::to_string(k) + " threw " + std::to_string(thrown[k]));  // the AI punches
  }
  why.check(landed[0] + landed[1] >= 3, std::to_string(landed[0] + landed[1]) + " landed");
  why.check(static_cast<int>(m.events.size()) > landed[0] + landed[1], "everything landed");  // not everything lands
  return why.str();
}

// Boxer k of the match pushed at its chest, `force` N for `duration` s, horizontally toward its opponent (toward > 0)
// or away from it (toward < 0), that direction turned by `turn` rad about the vertical.
void push_chest(World& w, int k, double toward, double force, double duration, double turn = 0.0) {
  Eigen::Vector3d d = w.data.x[w.boxers[1 - k].bodies.body[0]].p - w.data.x[w.boxers[k].bodies.body[0]].p;
  d.z() = 0.0;
  d = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()) * d;
  InputEvent push;
  push.kind = InputKind::Push;
  push.boxer = k;
  push.bone = "chest";
  push.vec = toward * force * d.normalized();
  push.duration = duration;
  interaction_submit(w, push);
}

// The fight's punches, seeds 1-3, 20 s each (a seed passes when every punch thrown obeys the rules below, each boxer
// throws at least 6, at least 3 land, not all of them, and no boxer falls without a hit).
// measured (seeds 1-10, the first 20 s of 30-s runs): 10-16 thrown a boxer, 4-10 landed, no fall without a hit. bound:
// every seed (the rules are the match's own bookkeeping, not a rate); 4 thrown a boxer (with the ring's footwork,
// measured 7-15: its moves hold the punches while the feet are up; with its quicker moves, 5-12 on seeds 1-3), 3
// landed, under the fewest measured.
TEST(Match, PunchesLandOnlyThroughTheStrikingGloveOnHeadOrTorsoAtSpeed) {
  const seed_rate::Rate r = seed_rate::over_seeds("match 20 s: the punches' bookkeeping", 1, 3, [](int seed) {
    auto w = run_match(seed, 20.0);
    if (!w) return std::string("no world");
    std::string why = punches_obey_the_rules(*w);
    std::printf("  seed %d: %d and %d thrown, %d landed\n", seed, w->match->fighter[0].thrown, w->match->fighter[1].thrown,
                w->match->fighter[0].landed + w->match->fighter[1].landed);
    for (int k = 0; k < 2; ++k)
      if (w->match->fighter[k].falls_without_hit != 0) why += "; boxer " + std::to_string(k) + " fell without a hit";
    return why;
  });
  EXPECT_TRUE(r.all());
}

// A boxer down gets up from the way it lies within the count, and is put back on its mark standing as it stood at the
// start (seed 5's red, a build of issue 15, got up turned away from blue, its feet crossed under it; placed with the
// desired pose's legs, reaching for those feet, it stood cross-legged, a foot 21 cm inside a crate, was lifted out,
// sank and fell 1 s later with no punch on it). The knockdown is brought about directly: boxer 0 shoved at the chest
// at 2 s, 1500 N x 0.25 s (5 m/s of com velocity: no balance step holds it) away from blue (it lies on its back) or
// toward him, turned 60 deg to pass beside him (straight at him red floored blue instead; turned, red lies on its
// front on seeds 2 and 3, on its back on 1), seeds 1-3: every one of the 6 must get up within the count, and both
// ways of lying (both get-up clips) must be among them (the fight's own knockdowns: 4 of 4 up within the count on
// seeds 1-10's first 30 s, 3.8-4.6 s down; docs/decisions/test-bounds.md). measured: down at 2.46-2.52 s, up
// 3.9-4.2 s later; lifted 0.000 m and the ankles 0.000 m off their marks at the reset (the start's stance put back).
TEST(Match, KnockedDownBoxerGetsUpFromTheWayItLiesWithinTheCount) {
  constexpr double kPastBlue = 1.047;  // rad, 60 deg
  int lying[2] = {0, 0};  // on its back, on its front
  const seed_rate::Rate r = seed_rate::over_seeds("match, boxer 0 shoved down both ways", 1, 3, [&](int seed) {
    seed_rate::Why why;
    for (const double toward : {-1.0, 1.0}) {
      const std::string way = toward < 0 ? "shoved back: " : "shoved forward: ";
      auto w = run_match(seed, 2.0);
      if (!w) return std::string("no world");
      World& world = *w;
      push_chest(world, 0, toward, 1500.0, 0.25, toward > 0 ? kPastBlue : 0.0);
      const Match& m = *world.match;
      const double count = m.tuning.count_seconds;
      while (world.data.time < 3.0 + count && (m.getups.empty() || m.getups.front().up_at < 0.0)) step_world(world);
      if (m.getups.empty()) {
        why.check(false, way + "not down");
        continue;
      }
      const GetUp& g = m.getups.front();
      std::printf("  seed %d, %s%s down at %.2f s, up at %.2f s, lying %s\n", seed, way.c_str(),
                  g.boxer == 0 ? "red" : "blue", g.down_at, g.up_at, g.lying.c_str());
      why.check(g.boxer == 0, way + "blue went down");
      why.check(g.lying == "back" || g.lying == "front", way + "lying '" + g.lying + "'");
      ++lying[g.lying == "front"];
      why.check(g.up_at >= 0.0 && g.up_at - g.down_at < count, way + "not up within the count");
      why.check(g.assist_time > 0.0 && g.assist_force_sq_dt > 0.0, way + "no root assist reported");
      why.check(m.teleports == 0, way + "set on a mark");
    }
    return why.str();
  });
  EXPECT_TRUE(r.all());
  // Both get-ups (getup_back, getup_front) among the 6.
  EXPECT_GE(lying[0], 1) << "none on its back";
  EXPECT_GE(lying[1], 1) << "none on its front";
}

// A knockdown brought about directly (as match_rules_test.cpp's put_down): both boxers handed to the (idle) player so
// no punch changes the situation, red (boxer 0) standing 1 s, then no consciousness left and 1500 N x 0.2 s at its
// chest away from blue (floors a boxer in guard: match_rules_test.cpp). Returns the world with red's GetUp open, or
// nullptr when it was not counted down within 4 s.
std::unique_ptr<World> red_put_down(uint64_t seed, const std::function<void(MatchTuning&)>& tune) {
  auto w = match_world(seed, tune);
  if (!w) return nullptr;
  World& world = *w;
  for (int k = 0; k < 2; ++k) {
    InputEvent e;
    e.kind = InputKind::Set;
    e.boxer = k;
    e.control = "player";
    interaction_submit(world, e);
  }
  for (int i = 0; i < 240; ++i) step_world(world);
  Eigen::Vector3d away = world.data.x[world.boxers[0].bodies.body[0]].p - world.data.x[world.boxers[1].bodies.body[0]].p;
  away.z() = 0.0;
  InputEvent out;
  out.kind = InputKind::Set;
  out.boxer = 0;
  out.consciousness = 0.0;
  interaction_submit(world, out);
  InputEvent push;
  push.kind = InputKind::Push;
  push.boxer = 0;
  push.bone = "chest";
  push.vec = 1500.0 * away.normalized();
  push.duration = 0.2;
  interaction_submit(world, push);
  for (int i = 0; i < 4 * 240 && world.match->fighter[0].getup < 0; ++i) step_world(world);
  if (world.match->fighter[0].getup < 0) return nullptr;
  return w;
}

// Whether every geom of boxer k's two thighs collides with the rest of its own body (Geom::self_collide).
bool thighs_self_collide(const World& w, int k, bool* mixed) {
  const Boxer& b = w.boxers[k];
  int on = 0, n = 0;
  for (int leg = 0; leg < 2; ++leg) {
    const int bone = b.bones.leg[leg].thigh;
    for (int g = b.bodies.first_geom[bone]; g < b.bodies.first_geom[bone] + b.bodies.geom_count[bone]; ++g, ++n)
      on += w.model.geoms[g].self_collide;
  }
  *mixed = on != 0 && on != n;
  return on == n;
}

// A boxer getting up lets its thighs pass through each other (MatchTuning::getup_thighs_pass), as it passes through
// its opponent: colliding, a leg left behind the other caught on the other thigh and the boxer stood on one foot, held
// up by the root assist (match 80's red, down at 11.1 s; 5 of seeds 1-100 show that get-up, too rare for a range:
// docs/decisions/match-fight.md). The mechanism, on a knockdown brought about directly (red_put_down): with the pass
// on, the thighs' self-collision is off every tick of the get-up (BoxerState::GettingUp) and on again once red is up;
// with it off, it stays on throughout. Seeds 1-3, every seed required (the arena's seed is not what makes it pass).
TEST(Match, AGetUpsLegCannotCatchOnTheOtherThigh) {
  for (const bool pass : {true, false}) {
    const seed_rate::Rate r = seed_rate::over_seeds(
        std::string("a get-up's thighs, getup_thighs_pass ") + (pass ? "on" : "off"), 1, 3, [pass](int seed) {
          seed_rate::Why why;
          auto w = red_put_down(seed, [pass](MatchTuning& t) { t.getup_thighs_pass = pass; });
          if (!w) return std::string("red not counted down within 4 s of the push");
          World& world = *w;
          const Match& m = *world.match;
          bool mixed = false;
          why.check(thighs_self_collide(world, 0, &mixed), "thighs not self-colliding while down, before the get-up");
          int getting_up = 0, colliding_then = 0, mixed_ticks = 0, passing_after = 0;
          double overlap_at_switch = 1.0;  // the legs' overlap when they started colliding again (m)
          // The count's length: up or counted out by then.
          for (int i = 0; i < int(m.tuning.count_seconds * 240) && m.getups[0].up_at < 0.0 && !m.over; ++i) {
            step_world(world);
            if (world.boxers[0].ctl.state.state != BoxerState::GettingUp) continue;
            ++getting_up;
            const bool colliding = thighs_self_collide(world, 0, &mixed);
            if (colliding && colliding_then == 0) overlap_at_switch = legs_overlap(world, 0);
            if (!colliding && colliding_then > 0) ++passing_after;
            colliding_then += colliding;
            mixed_ticks += mixed;
          }
          const GetUp g = m.getups[0];
          why.check(getting_up > 0, "no get-up started");
          if (pass) why.check(g.up_at >= 0.0, "not up within the count");
          why.check(mixed_ticks == 0, "one thigh's geoms colliding, the other's not, on " + std::to_string(mixed_ticks) +
                                          " ticks");
          if (pass) {
            // Passing through each other while it rises; risen with the legs crossed, they collide again (and stay
            // so) to push apart before it is up: only at the end, and only with the legs through each other.
            why.check(passing_after == 0, "the legs passing again on " + std::to_string(passing_after) +
                                              " ticks after they collided");
            why.check(colliding_then < getting_up, "thighs self-colliding on every get-up tick");
            if (colliding_then > 0)
              why.check(overlap_at_switch > m.footwork_tuning.legs_through,
                        "the legs collided again while apart (" + std::to_string(overlap_at_switch) + " m)");
          } else
            why.check(colliding_then == getting_up, "thighs passing on " + std::to_string(getting_up - colliding_then) +
                                                        " get-up ticks with getup_thighs_pass off");
          if (g.up_at >= 0.0) {
            step_world(world);
            why.check(thighs_self_collide(world, 0, &mixed), "thighs not self-colliding once up");
          }
          return why.str();
        });
    EXPECT_TRUE(r.all());
  }
}

// A stand-up that does not end is given up and started again from the ground (MatchTuning::stand_up_give_up: match
// 80's red, its leg caught behind the other thigh, sank back after 8 s of it, rose again and was up). Brought about
// directly: red floored (red_put_down) with the give-up at 1 s, shorter than any get-up (getup_back / getup_front play
// longer than that before guard), so the first stand-up is given up; then the give-up is set back to its default
// (8 s) and the retry must bring red up within the count. Seeds 1-3, every seed required (the give-up is a timer: the
// arena's seed is not what makes it pass).
TEST(Match, AStandUpThatDoesNotEndIsGivenUpAndStartedAgain) {
  const double give_up = MatchTuning{}.stand_up_give_up;
  const seed_rate::Rate r = seed_rate::over_seeds("a stand-up given up at 1 s, then the default", 1, 3, [&](int seed) {
    seed_rate::Why why;
    auto w = red_put_down(seed, [](MatchTuning& t) { t.stand_up_give_up = 1.0; });
    if (!w) return std::string("red not counted down within 4 s of the push");
    World& world = *w;
    Match& m = *world.match;
    double gave_up_at = -1.0;
    for (int i = 0; i < int(m.tuning.count_seconds * 240) && m.getups[0].up_at < 0.0 && !m.over; ++i) {
      step_world(world);
      if (gave_up_at < 0.0 && m.getups[0].retries >= 1) {
        gave_up_at = world.data.time;
        why.check(world.boxers[0].ctl.state.state == BoxerState::Down, "not down after the give-up");
        m.tuning.stand_up_give_up = give_up;
      }
    }
    const GetUp g = m.getups[0];
    why.check(gave_up_at >= 0.0, "the 1 s stand-up was never given up");
    why.check(g.retries >= 1, "no retry");
    why.check(g.up_at >= 0.0, "not up within the count after " + std::to_string(g.retries) + " retries");
    why.check(world.boxers[0].ctl.state.state == BoxerState::Guard, "not in guard at the end");
    const auto report = match_report(world)["getups"];
    why.check(!report.empty() && report[0]["stand_up_retries"].get<int>() == g.retries,
              "the report's stand_up_retries differs from the GetUp's");
    std::printf("  seed %d: down at %.2f s, given up at %.2f s, up at %.2f s, %d retries\n", seed, g.down_at,
                gave_up_at, g.up_at, g.retries);
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

// The fight's balance steps (balance_step.h, on in the match): a shove its root assist cannot hold in place, 900 N x
// 0.2 s at boxer 0's chest to either side at 5 s into the fight, seeds 1-8 (16 shoves), down within 2.5 s. The steps
// are the fight's own: none is taken in place. The force: of the two measured on the 64 shoves of
// docs/decisions/com-acceleration-in-support.md (seeds 1-8, both boxers, +-x and +-y), 800 N floors 14 in place and
// 4 with the steps, too few in place for 16 shoves to tell the two apart (3 of 8 on seeds 1-4); 900 N floors about a
// third in place (22-23 of 64) and 12-15 with the steps. measured on the 16 here: 10 down in
// place, 5 with the steps. bound: with the
// steps at most three quarters of those in place (the 64 shoves' ratio is 12-15 / 22-23, 0.55-0.65; three quarters
// leaves a shove or two of the 16 to move), and at least 4 balance steps taken (18
// measured).
TEST(MatchSteps, AShoveTheRootAssistCannotHoldIsCaughtByBalanceSteps) {
  int down[2] = {0, 0}, steps[2] = {0, 0};
  for (int stepping = 0; stepping < 2; ++stepping)
    for (uint64_t seed = 1; seed <= 8; ++seed)
      for (double side : {1.0, -1.0}) {
        Options o;
        o.headless = true;
        o.scenario_id = Scenario::Match;
        o.scenario = "match";
        o.seed = seed;
        o.stepping = stepping ? "on" : "off";
        auto made = make_world(o);
        ASSERT_TRUE(made) << made.error();
        World& w = **made;
        for (int i = 0; i < 5 * 240; ++i) step_world(w);
        InputEvent push;
        push.kind = InputKind::Push;
        push.boxer = 0;
        push.bone = "chest";
        push.vec = Eigen::Vector3d(0.0, 900.0 * side, 0.0);
        push.duration = 0.2;
        interaction_submit(w, push);
        for (int i = 0; i < int(2.5 * 240); ++i) step_world(w);
        bool went_down = false;
        for (const GetUp& g : w.match->getups) went_down = went_down || (g.boxer == 0 && g.down_at >= 5.0);
        down[stepping] += went_down;
        steps[stepping] += w.boxers[0].metrics.balance_steps;
        std::printf("[seed_rate] shove %s, seed %d, %s: %s, %d balance steps\n", stepping ? "with the steps" : "in place",
                    int(seed), side > 0 ? "+y" : "-y", went_down ? "down" : "up", w.boxers[0].metrics.balance_steps);
      }
  EXPECT_EQ(steps[0], 0);
  EXPECT_GE(steps[1], 4);
  std::printf("shoves that put boxer 0 down: %d of 16 with the steps, %d in place\n", down[1], down[0]);
  EXPECT_LE(4 * down[1], 3 * down[0]) << "with the steps " << down[1] << " of 16 down, in place " << down[0];
  EXPECT_GE(down[0], 4) << "in place too few go down to show anything";
}

// A hard hit short of a knockdown rocks the boxer back (MatchTuning::rock_damage): the stagger clip, two steps back,
// and the rocked boxer stays up; with rocking off the same hits play hit_head / hit_body in place. At the built
// threshold (0.25) rocks are rare (8 of the 77 hits landed in seeds 1-10's first 20 s), so the test lowers it to
// 0.15 (28 of those 77): what is tested is what a rock does, not how often one comes. Seeds 1-4, 12 s, rocking at
// 0.15 and off; every hit of 0.15 or more: how far the hit boxer's pelvis went away from the thrower (the most within
// 1.5 s of the hit). The bound: the stagger's clip carries
// the pelvis 0.24 m back, hit_head 0.03 m: rocked back is more than half the stagger's, 0.12 m. (Seed 34's rock at
// 0.25, and seed 18's before BalanceQpTuning::com_acc_in_support, were the hand-picked runs this replaces.)
// measured: rocked, 0.21, 0.19, 0.29, 0.02 m back (3 of 4; seed 3's at 1.93 s stayed), none down; off, 0.00-0.08 m
// (5 of 5). bounds: rocked back on at least half, in place on at least 80%: one hit of four or five may move. The AI's
// footwork is off here (its moves carry the pelvis 0.3 m whatever the hit did).
struct HardHit {
  int seed = 0, boxer = 0;
  double t = 0.0, damage = 0.0, back = 0.0;  // s, damage, m: the most it went away from the thrower within 1.5 s
  bool rocked = false, down = false;  // down: a knockdown of that boxer within 2 s of the hit
};

// s of fight per seed: 30 (12 before the ring's footwork).
constexpr double kHardHitSeconds = 30.0;

std::vector<HardHit> hard_hits(int seed, double rock, double at_least) {
  // The AI's footwork off (FootworkAiTuning::on): a move carries the pelvis 0.3 m whatever the hit did.
  auto w = run_match(seed, 0.0, [rock](MatchTuning& t) { t.rock_damage = rock, t.footwork.on = false; });
  if (!w) return {};
  World& world = *w;
  const Match& m = *world.match;
  const auto pelvis = [&](int k) { return Eigen::Vector2d(world.data.x[world.boxers[k].bodies.body[0]].p.head<2>()); };
  // Each landed punch (an event is logged when thrown and marked landed at its first touch), from the step it lands:
  // where the hit boxer stood and which way is away from the thrower; then, for 1.5 s, the most it went that way.
  struct Seen { size_t event; double t; Eigen::Vector2d from, away; double back = -1e9; };
  std::vector<Seen> seen;
  std::vector<bool> registered;
  while (world.data.time < kHardHitSeconds) {
    step_world(world);
    registered.resize(m.events.size(), false);
    for (size_t i = 0; i < m.events.size(); ++i) {
      const PunchEvent& e = m.events[i];
      if (registered[i] || !e.landed) continue;
      registered[i] = true;
      const int k = 1 - e.boxer;
      seen.push_back({i, world.data.time, pelvis(k), (pelvis(k) - pelvis(e.boxer)).normalized()});
    }
    for (Seen& h : seen) {
      if (world.data.time > h.t + 1.5) continue;
      h.back = std::max(h.back, (pelvis(1 - m.events[h.event].boxer) - h.from).dot(h.away));
    }
  }
  // Damage and rocking of each, read at the end (its impact window long closed).
  std::vector<HardHit> hard;
  for (const Seen& s : seen) {
    const PunchEvent& e = m.events[s.event];
    if (s.t > kHardHitSeconds - 1.5 || e.damage < at_least) continue;
    HardHit h;
    h.seed = seed, h.boxer = 1 - e.boxer, h.t = s.t, h.damage = e.damage, h.back = s.back;
    h.rocked = rock > 0.0 && e.damage >= rock;
    for (const GetUp& g : m.getups) h.down = h.down || (g.boxer == h.boxer && g.down_at >= h.t && g.down_at < h.t + 2.0);
    hard.push_back(h);
  }
  return hard;
}

TEST(Match, AHardHitRocksTheBoxerBack) {
  constexpr double kRock = 0.15, kBack = 0.12;  // damage; m, half the stagger clip's 0.24 m
  std::vector<HardHit> rocked, in_place;
  for (int seed = 1; seed <= 4; ++seed) {
    for (const HardHit& h : hard_hits(seed, kRock, kRock)) rocked.push_back(h);
    for (const HardHit& h : hard_hits(seed, 0.0, kRock)) in_place.push_back(h);
  }
  const auto count = [](const char* what, const std::vector<HardHit>& v, const std::function<bool(const HardHit&)>& ok) {
    int n = 0;
    std::string failed;
    for (const HardHit& h : v) {
      std::printf("[seed_rate] %s: seed %d, boxer %d hit at %.2f s, damage %.2f: %.2f m back%s%s\n", what, h.seed, h.boxer,
                  h.t, h.damage, h.back, h.rocked ? ", rocked" : "", h.down ? ", down" : "");
      if (ok(h)) ++n;
      else failed += "\n  seed " + std::to_string(h.seed) + ", hit at " + std::to_string(h.t) + " s: " +
                     std::to_string(h.back) + " m back" + (h.down ? ", down" : "");
    }
    return std::make_pair(n, failed);
  };
  const auto [back, back_failed] =
      count("rocking at 0.15", rocked, [&](const HardHit& h) { return h.rocked && h.back > kBack && !h.down; });
  const auto [still, still_failed] = count("rocking off", in_place, [&](const HardHit& h) { return h.back < kBack; });
  ASSERT_GE(rocked.size(), 4u) << "too few hard hits to show anything";
  ASSERT_GE(in_place.size(), 4u) << "too few hard hits to show anything";
  // With the AI's footwork off (as before the ring): rocked, 6 of 6 went back past kBack; off, 14 of 15 in place.
  EXPECT_GE(2 * back, int(rocked.size())) << back << " of " << rocked.size() << " rocked back:" << back_failed;
  EXPECT_GE(10 * still, 8 * int(in_place.size())) << still << " of " << in_place.size() << " in place:" << still_failed;
}


// The AI throws more of what lands on this opponent: with the lead hook blocked 20 times in 20 and the jab landing 10
// of 20, the hook's share of the picks falls from a seventh to a fiftieth, the jab's rises by half.
TEST(FighterAi, ThrowsMoreOfWhatLands) {
  const auto shares = [](bool history) {
    FighterAi ai;
    ai.rng = Rng(7);
    ai.style.punch_weight = {1, 1, 1, 1, 1, 1, 1};
    if (history) {
      ai.thrown_of[punch_index("lead_hook")] = 20;
      ai.thrown_of[punch_index("jab")] = 20, ai.landed_of[punch_index("jab")] = 10;
    }
    std::array<int, kPunchClips.size()> n{};
    for (int i = 0; i < 20000; ++i) ++n[punch_index(pick_punch(ai))];
    return n;
  };
  const auto before = shares(false), after = shares(true);
  const int hook = punch_index("lead_hook"), jab = punch_index("jab");
  EXPECT_NEAR(before[hook] / 20000.0, 1.0 / 7.0, 0.01);  // the favourites alone: uniform here
  // Weights (landed + 1) / (thrown + 3): the hook 1/23, the jab 11/23, the five others 1/3 each.
  const double total = 1.0 / 23 + 11.0 / 23 + 5.0 / 3;
  EXPECT_NEAR(after[hook] / 20000.0, (1.0 / 23) / total, 0.005);  // 0.020, a seventh of 0.143
  EXPECT_NEAR(after[jab] / 20000.0, (11.0 / 23) / total, 0.01);   // 0.218
  EXPECT_EQ(punch_index("guard"), -1);
}

TEST(Match, SameSeedGivesTheSameFight) {
  auto a = run_match(2, 12.0), b = run_match(2, 12.0);  // any seed (determinism): the second
  ASSERT_TRUE(a && b);
  EXPECT_EQ(match_report(*a).dump(), match_report(*b).dump());
  EXPECT_FALSE(a->match->events.empty());
}

// A player's boxer (--player) takes no AI decision: with no keys pressed it throws nothing while the AI's does, and
// a command (what a key sends) is taken by the motion graph.
TEST(Match, StandingBoxersOutOfRangeWalkToEachOther) {
  // Nobody brings them together: from the marks 2.8 m apart and whenever they part, the AI's footwork walks them into
  // range. Seeds 1-2, 45 s each, every seed required. Bound: the walk in from the marks (2.8 m less reach, at a move's
  // 0.3 m per 1-1.5 s: 6-9 s; measured 11.7 and 13.8 s with the moves spent turning), 16 s; and more than 15 punches
  // thrown in the 45 s (measured 20 and 24).
  const seed_rate::Rate r = seed_rate::over_seeds("match 45 s: standing apart", 1, 2, [](int seed) {
    Options o;
    o.headless = true;
    o.scenario_id = Scenario::Match;
    o.seed = seed;
    auto w = make_world(o);
    if (!w) return w.error();
    World& world = **w;
    const auto standing = [&](int k) {
      const BoxerState s = world.boxers[k].ctl.state.state;
      return s == BoxerState::Guard || s == BoxerState::Stunned;
    };
    double apart = 0.0, longest = 0.0;
    for (int i = 0; i < 45 * 240; ++i) {
      step_world(world);
      const bool both_out = standing(0) && standing(1) && !in_range(world, 0) && !in_range(world, 1);
      apart = both_out ? apart + 1.0 / 240.0 : 0.0;
      longest = std::max(longest, apart);
    }
    std::printf("  seed %d: longest both standing out of range %.2f s, %d thrown\n", seed, longest,
                world.match->fighter[0].thrown + world.match->fighter[1].thrown);
    seed_rate::Why why;
    why.check(longest <= 16.0, "apart " + std::to_string(longest) + " s");
    why.check(world.match->teleports == 0, "set on a mark");
    why.check(world.match->fighter[0].thrown + world.match->fighter[1].thrown > 15, "the fight stopped");  // goes on
    return why.str();
  });
  EXPECT_TRUE(r.all());
}

TEST(Match, PlayersBoxerPunchesOnlyOnCommand) {
  Options o;
  o.headless = true;
  o.scenario_id = Scenario::Match;
  o.seed = 3;  // any seed (the commands are scripted): the third
  o.player = 0;
  o.start_apart = kAtRange;
  auto w = make_world(o);
  ASSERT_TRUE(w) << w.error();
  World& world = **w;
  for (int i = 0; i < 8 * 240; ++i) step_world(world);
  EXPECT_EQ(world.match->fighter[0].thrown, 0);
  EXPECT_GT(world.match->fighter[1].thrown, 0);
  match_command(world, 0, FightCommand::Cross);
  for (int i = 0; i < 3 * 240 && world.match->fighter[0].commands_taken == 0; ++i) step_world(world);
  for (int i = 0; i < 240; ++i) step_world(world);
  EXPECT_EQ(world.match->fighter[0].commands_taken, 1);
  EXPECT_EQ(world.match->fighter[0].thrown, 1);
  int red_crosses = 0;
  for (const PunchEvent& e : world.match->events) red_crosses += e.boxer == 0 && e.punch == "cross";
  EXPECT_EQ(red_crosses, 1);
  // Keys pressed faster than the punches play are buffered and thrown in order, none lost.
  for (FightCommand c : {FightCommand::Jab, FightCommand::Cross, FightCommand::Jab}) match_command(world, 0, c);
  EXPECT_EQ(world.match->fighter[0].input.queued, 3);
  for (int i = 0; i < 6 * 240 && world.match->fighter[0].input.queued > 0; ++i) step_world(world);
  for (int i = 0; i < 240; ++i) step_world(world);
  EXPECT_EQ(world.match->fighter[0].commands_taken, 4);
  std::vector<std::string> red;
  for (const PunchEvent& e : world.match->events)
    if (e.boxer == 0) red.push_back(e.punch);
  EXPECT_EQ(red, (std::vector<std::string>{"cross", "jab", "cross", "jab"}));
}

// The instant replay's ring keeps the newest frames in time order, each frame's coordinates as recorded.
TEST(ReplayBuffer, KeepsTheNewestFramesInOrder) {
  ReplayBuffer rb;
  rb.init(240, 3);
  Eigen::VectorXd q(3);
  for (int f = 0; f < 300; ++f) {
    q << f, 2.0 * f, -f;
    rb.record(q, f / 60.0);
  }
  ASSERT_EQ(rb.count(), 240);
  EXPECT_DOUBLE_EQ(rb.time(0), 60 / 60.0);
  EXPECT_DOUBLE_EQ(rb.time(239), 299 / 60.0);
  for (int i = 0; i < 240; ++i) {
    EXPECT_EQ(rb.q(i)[0], 60.0 + i);
    EXPECT_EQ(rb.q(i)[1], 2.0 * (60 + i));
  }
  EXPECT_EQ(rb.at_or_before(100.5 / 60.0), 40);
  EXPECT_EQ(rb.at_or_before(0.0), 0);  // older than anything kept: the oldest
}

// The match records one frame per 60 Hz display frame for the replay.
TEST(Match, RecordsTheLastSecondsForTheReplay) {
  auto w = run_match(1, 6.0);  // any seed: the first
  ASSERT_TRUE(w);
  const ReplayBuffer& rb = w->match->replay;
  ASSERT_EQ(rb.count(), static_cast<int>(kReplaySeconds * 60));
  EXPECT_NEAR(rb.time(rb.count() - 1), w->data.time, 1e-9);
  EXPECT_NEAR(rb.time(rb.count() - 1) - rb.time(0), kReplaySeconds - 1.0 / 60.0, 1e-9);
  for (int k = 0; k < rb.nq(); ++k) EXPECT_EQ(rb.q(rb.count() - 1)[k], w->data.q[k]);
}

TEST(PunchAim, WeightRisesToOneAtImpactAndFallsBackOverTheRetraction) {
  const double impact = 0.14, duration = 0.4;
  EXPECT_EQ(aim_weight(0.0, impact, duration), 0.0);
  EXPECT_DOUBLE_EQ(aim_weight(impact, impact, duration), 1.0);
  EXPECT_EQ(aim_weight(impact + 0.6 * (duration - impact), impact, duration), 0.0);
  double last = -1.0;
  for (double t = 0.0; t <= impact; t += 0.01) {
    EXPECT_GE(aim_weight(t, impact, duration), last);
    last = aim_weight(t, impact, duration);
  }
  EXPECT_EQ(aim_weight(0.1, -1.0, duration), 0.0);  // a clip without an impact frame is not aimed
}

TEST(PunchAim, StrikeIsOnFromAQuarterOfTheWayToImpactUntilShortlyAfter) {
  const double impact = 0.14, follow = 0.03;
  EXPECT_EQ(strike_weight(0.0, impact, follow), 0.0);
  EXPECT_EQ(strike_weight(0.25 * impact, impact, follow), 0.0);
  EXPECT_DOUBLE_EQ(strike_weight(0.6 * impact, impact, follow), 1.0);
  EXPECT_DOUBLE_EQ(strike_weight(impact + follow, impact, follow), 1.0);
  EXPECT_EQ(strike_weight(impact + follow + 1e-3, impact, follow), 0.0);  // the clip retracts the arm
  EXPECT_EQ(strike_weight(0.1, -1.0, follow), 0.0);
}

// The strike task (PunchAim::strike) against the same fight without it: the landed punches' fist speed at contact is
// in the range of real punches (a jab about 5.6 m/s, Walilko 2005), and the glove's peak speed over every punch thrown
// (a larger sample than the landed ones) is well above what the bent pose and the stiffer arm alone gave.
double median_of(const Match& m, bool landed_only, double PunchEvent::*field) {
  std::vector<double> v;
  for (const PunchEvent& e : m.events)
    if ((e.landed || !landed_only) && e.peak_speed > 0.0) v.push_back(e.*field);
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Seeds 1-4, 20 s each, with the strike task and without it (the bent pose and the stiffer arm alone). A seed passes
// when its landed punches' median fist speed is at least 5.6 m/s (Walilko 2005's jab: the bound is the real punch's
// speed, not a measured one) and its median glove peak over every punch thrown rose by more than 0.5 m/s. (On seeds
// 1-6 over 60 s it rose by 0.44, 1.88, 2.23, 1.17, 1.55 and 1.26 m/s: the hand-picked seed 2 stood in for them.)
// measured (seeds 1-4): median fist speed 7.4-8.3 m/s, the peak up by 1.2-2.1 m/s, 5-10 landed; bound 3 of 4: one
// seed of four may move with a last-bit difference between machines.
TEST(Match, StrikeTaskBringsTheFistInAtARealPunchsSpeed) {
  const seed_rate::Rate r = seed_rate::over_seeds("match 20 s, strike task on / off", 1, 4, [](int seed) {
    auto on = run_match(seed, 20.0);
    auto off = run_match(seed, 20.0, [](MatchTuning& t) { t.strike_speed = 0.0; t.punch_arm_gain = 1.8; });
    if (!on || !off) return std::string("no world");
    const double fist = median_of(*on->match, true, &PunchEvent::fist_speed);
    const double peak_on = median_of(*on->match, false, &PunchEvent::peak_speed);
    const double peak_off = median_of(*off->match, false, &PunchEvent::peak_speed);
    int landed = 0;
    for (const MatchFighter& f : on->match->fighter) landed += f.landed;
    std::printf("  seed %d: landed %d, median fist speed %.2f m/s, median peak %.2f m/s (strike) %.2f (none)\n", seed,
                landed, fist, peak_on, peak_off);
    seed_rate::Why why;
    why.check(fist >= 5.6, "median landed fist speed " + std::to_string(fist) + " m/s");
    why.check(peak_on > peak_off + 0.5, "median peak " + std::to_string(peak_on) + " vs " + std::to_string(peak_off));
    why.check(landed >= 3, std::to_string(landed) + " landed");
    return why.str();
  });
  EXPECT_TRUE(r.at_least(3));
}

TEST(BodyParts, TheBoxersBonesMapToTheirParts) {
  EXPECT_EQ(boxer_body_part("glove_l"), BodyPart::Glove);
  EXPECT_EQ(boxer_body_part("head"), BodyPart::Head);
  EXPECT_EQ(boxer_body_part("chest"), BodyPart::Torso);
  EXPECT_EQ(boxer_body_part("forearm_r"), BodyPart::Arm);
  EXPECT_EQ(boxer_body_part("shank_l"), BodyPart::Leg);
  EXPECT_EQ(boxer_body_part("tail"), BodyPart::None);
}

TEST(FighterAi, StylesAreSeededAndWithinTheirRanges) {
  Rng a(7), b(7), c(8);
  const FighterStyle sa = draw_fighter_style(a), sb = draw_fighter_style(b), sc = draw_fighter_style(c);
  EXPECT_EQ(sa.attack_rate, sb.attack_rate);
  EXPECT_EQ(sa.punch_weight, sb.punch_weight);
  EXPECT_NE(sa.attack_rate, sc.attack_rate);
  for (const FighterStyle& s : {sa, sc}) {
    EXPECT_GE(s.attack_rate, 1.0);
    EXPECT_LE(s.attack_rate, 1.6);
    EXPECT_GE(s.defence, 0.25);
    EXPECT_LE(s.defence, 0.55);
    EXPECT_GE(s.reaction_s, 0.18);
    EXPECT_LE(s.reaction_s, 0.26);
  }
}

// The report's `getups` (game/getup_metrics.h) against the match's own bookkeeping: red put down (red_put_down) and
// left to get up. The record opens and closes on the ticks the match's own GetUp does, its lift force and root
// torque integrate to what the match summed over the stand-up (the same quantities, kept twice: they agree to
// round-off), its phases run down -> the get-up clip for how it lies -> up in time order, and the body parts that bore
// weight include more than the feet (it lay on the crates).
TEST(GetUpMetrics, AMatchGetUpIsRecordedAsTheMatchCountsIt) {
  auto w = red_put_down(1, {});
  ASSERT_TRUE(w) << "red not down";
  World& world = *w;
  const Match& mt = *world.match;
  for (int i = 0; i < 20 * 240 && (mt.getups.empty() || mt.getups[0].up_at < 0.0); ++i) step_world(world);
  ASSERT_EQ(mt.getups.size(), 1u);
  const GetUp& g = mt.getups[0];
  ASSERT_GE(g.up_at, 0.0) << "red not up in 20 s";
  ASSERT_EQ(world.getups.records.size(), 1u);
  const GetUpRecord& r = world.getups.records[0];
  EXPECT_EQ(r.boxer, 0);
  EXPECT_NEAR(r.down_at, g.down_at, 1.0 / 240.0 + 1e-9);
  EXPECT_NEAR(r.up_at, g.up_at, 1.0 / 240.0 + 1e-9);
  EXPECT_EQ(r.lying, g.lying);
  EXPECT_NEAR(r.lift_force_sq_dt, g.assist_force_sq_dt, 1e-9 * (1.0 + g.assist_force_sq_dt));
  EXPECT_GT(r.lift_force_peak, 0.0);  // today's stand-up is carried (issue 63)
  EXPECT_GE(r.root_torque_sq_dt, g.assist_sq_dt * (1.0 - 1e-9));
  ASSERT_GE(r.phases.size(), 3u);
  EXPECT_EQ(r.phases.front().first, "down");
  EXPECT_EQ(r.phases.back().first, "up");
  EXPECT_NE(std::find_if(r.phases.begin(), r.phases.end(),
                         [&](const auto& p) { return p.first == "getup_" + g.lying; }),
            r.phases.end());
  for (size_t i = 1; i < r.phases.size(); ++i) EXPECT_GE(r.phases[i].second, r.phases[i - 1].second);
  const auto& names = world.boxer_desc.skeleton.name;
  double off_feet = 0.0;
  for (size_t bone = 0; bone < names.size(); ++bone) {
    EXPECT_LE(r.support_s[bone], r.time + 1e-9) << names[bone];
    if (names[bone] != "foot_l" && names[bone] != "foot_r") off_feet += r.support_s[bone];
  }
  EXPECT_GT(off_feet, 0.5);
  const nlohmann::json report = getups_report(world);
  ASSERT_EQ(report.size(), 1u);
  EXPECT_NEAR(report[0]["lift_force_rms_n"].get<double>(), std::sqrt(r.lift_force_sq_dt / r.time), 1e-9);
  // Each joint's peak against a person's strength (person_strength.h): the fraction is the one over the other.
  ASSERT_EQ(report[0]["joint_torque_peak_fraction"].size(), std::size(kPersonStrength));
  for (size_t bone = 1; bone < names.size(); ++bone) {
    if (person_strength(names[bone]) <= 0.0) continue;  // welded (the gloves)
    const double limit = report[0]["joint_torque_limit_nm"][names[bone]].get<double>();
    EXPECT_EQ(limit, person_strength(names[bone]));
    EXPECT_NEAR(report[0]["joint_torque_peak_fraction"][names[bone]].get<double>(), r.torque_peak[bone] / limit, 1e-12);
  }
  EXPECT_GT(r.torque_peak[world.boxer_desc.skeleton.find("thigh_r")], 0.0);
}

}  // namespace
}  // namespace boxing
