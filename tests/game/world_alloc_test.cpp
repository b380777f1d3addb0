// The world step allocates nothing once warm: physics, a boxer's control (servo, balance QP, steps), its pose source
// and motion-graph walker (issue 14: no allocation per tick). The match's events (a punch thrown, a hit, a forced
// clip) allocate when they happen, not per tick; the graph walk is the per-tick path without them. Counts operator new and malloc
// (Eigen's dynamic storage) with the linker's --wrap=malloc (tests/game/CMakeLists.txt). BOXING_ALLOC_TRACE=1
// prints the call stacks of the first N allocations, to find them.
#include <execinfo.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <new>

#include "game/audio/game_audio.h"
#include "game/scenario.h"
#include "game/world.h"
#include "test_paths.h"

namespace {
bool g_count = false;
long g_allocs = 0;
int g_traced = 0;

void note_alloc() {
  if (!g_count) return;
  ++g_allocs;
  static const bool trace = std::getenv("BOXING_ALLOC_TRACE") != nullptr;
  static const int limit = trace ? std::atoi(std::getenv("BOXING_ALLOC_TRACE")) : 0;
  if (trace && g_traced < limit) {
    g_count = false;  // backtrace itself may allocate
    ++g_traced;
    void* frames[24];
    const int n = backtrace(frames, 24);
    std::fprintf(stderr, "---- allocation %d\n", g_traced);
    backtrace_symbols_fd(frames, n, 2);
    g_count = true;
  }
}
}  // namespace

extern "C" void* __real_malloc(size_t);
extern "C" void* __wrap_malloc(size_t n) {
  note_alloc();
  return __real_malloc(n);
}
void* operator new(std::size_t n) {
  note_alloc();
  void* p = __real_malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  return p;
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace boxing {
namespace {

Options headless_scenario(Scenario id, uint64_t seed) {
  Options o;
  o.headless = true;
  o.scenario_id = id;
  o.scenario = scenario_name(id);
  o.seed = seed;
  return o;
}

TEST(WorldAlloc, GraphWalkStepAllocatesNothingOnceWarm) {
  const Options o = headless_scenario(Scenario::GraphWalk, 3);
  auto w = make_world(o);
  ASSERT_TRUE(w) << w.error();
  World& world = **w;
  // Warm: 8 s of the match (every workspace, contact list and walker buffer reaches its working size).
  for (int i = 0; i < 8 * 240; ++i) step_world(world);
  g_allocs = 0;
  g_count = true;
  for (int i = 0; i < 8 * 240; ++i) step_world(world);
  g_count = false;
  EXPECT_EQ(g_allocs, 0) << "allocations in 8 s of a boxer on a graph walk (BOXING_ALLOC_TRACE=N prints the stacks of the first N)";
  EXPECT_FALSE(world.boxers[0].metrics.fell);  // the measured stretch was the normal fight, not a body lying still
}

// A push's recovery (a balance step: its landing re-planned and searched for a foothold every tick of the swing's
// first 40%, or 60% while the push observer reads the push) allocates nothing once a first recovery has warmed it:
// not even where the second recovery touches down on more contact points than the first (seed 4: the contact lists
// grew past their warm-up size, 9 allocations, before they were given their capacity at construction).
TEST(WorldAlloc, PushRecoveryWithBalanceStepsAllocatesNothingOnceWarm) {
  // Seeds 2 and 3: both pushes are caught by steps (on seeds 1, 4, 6 and 8 the second push, from the stance the first
  // recovery left, floors the boxer or is held without a step: chaos, not allocation; a fall allocates as the event
  // it is).
  for (uint64_t seed : {2u, 3u}) {
    SCOPED_TRACE(seed);
    Options o = headless_scenario(Scenario::Push, seed);
    o.push_dir_deg = 270.0;  // to the right: a crossing step
    o.push_force = 300.0;
    o.push_duration = 0.2;
    o.push_at = 2.0;
    auto w = make_world(o);
    ASSERT_TRUE(w) << w.error();
    World& world = **w;
    for (int i = 0; i < 10 * 240; ++i) step_world(world);  // the first push and its recovery
    const int warm_steps = world.boxers[0].metrics.balance_steps;
    ASSERT_GT(warm_steps, 0);
    world.options.push_at = 10.5;  // the same push again, counted
    g_allocs = 0;
    g_count = true;
    for (int i = 0; i < 6 * 240; ++i) step_world(world);
    g_count = false;
    EXPECT_EQ(g_allocs, 0) << "allocations in a push's recovery (BOXING_ALLOC_TRACE=N prints the stacks of the first N)";
    EXPECT_GT(world.boxers[0].metrics.balance_steps, warm_steps);  // the counted stretch took balance steps
    EXPECT_FALSE(world.boxers[0].metrics.fell);
  }
}

// The sound (game/audio/): each frame's events played and the mix rendered, to a WAV, allocates nothing once warm (a
// fixed voice pool, the crowd's excitations in a reserved list, the WAV's conversion buffer grown once). The match's
// own events allocate as they happen (a punch's record), so only the sound's update is counted, over 8 s of a fight
// after 8 s of warm-up (seed 1: punches, slaps, steps and the crowd in both stretches).
TEST(WorldAlloc, TheSoundsMixAllocatesNothingOnceWarm) {
  Options o = headless_scenario(Scenario::Match, 1);
  o.start_apart = 1.0;
  auto w = make_world(o);
  ASSERT_TRUE(w) << w.error();
  World& world = **w;
  auto audio = make_game_audio({std::string(BOXING_BINARY_DIR) + "/alloc_test.wav", false, {}});
  ASSERT_TRUE(audio) << audio.error();
  long counted = 0, events = 0;
  for (int frame = 0; frame < 16 * 60; ++frame) {
    for (int s = 0; s < kStepsPerFrame; ++s) step_world(world);
    if (frame == 8 * 60) g_allocs = 0, events = (*audio)->mixer.stats.started;
    g_count = frame >= 8 * 60;
    ASSERT_TRUE(game_audio_update(**audio, world));
    g_count = false;
    counted = g_allocs;
  }
  EXPECT_EQ(counted, 0) << "allocations in the sound's update (BOXING_ALLOC_TRACE=N prints the stacks of the first N)";
  EXPECT_GT((*audio)->mixer.stats.started - events, 10) << "the counted stretch played sounds";
}

}  // namespace
}  // namespace boxing
