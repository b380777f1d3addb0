// bench_game: the game's world step (physics + control) per stage for one boxer (push, graph-walk) and two (stand,
// match), the balance QP against the PD balance layer in the same run, and the balance QP's own solve on the inputs
// of a settled stance.
// Run with scripts/bench (or build-bench/bench_game). Timings are thread CPU time per 240 Hz tick.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <memory>
#include <vector>

#include "engine/physics/dynamics.h"
#include "engine/physics/step.h"
#include "game/cli.h"
#include "game/world.h"

namespace {

double thread_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

std::unique_ptr<boxing::World> make(const char* scenario, const char* balance) {
  boxing::Options o;
  o.headless = true;
  o.seed = 1;
  o.balance = balance;
  auto parsed = boxing::parse_cli({"--scenario", scenario});  // the CLI's scenario id and defaults
  if (!parsed) std::exit(1);
  o.scenario = parsed->scenario;
  o.scenario_id = parsed->scenario_id;
  auto w = boxing::make_world(o);
  if (!w) {
    std::fprintf(stderr, "bench_game: %s\n", w.error().c_str());
    std::exit(1);
  }
  for (int i = 0; i < 240; ++i) boxing::step_world(**w);  // settle 1 s (not timed)
  return std::move(*w);
}
std::unique_ptr<boxing::World> stand_world(const char* balance) { return make("stand", balance); }

// One 240 Hz tick of the world step (control + physics) and its split by stage (step_world's own profile, wall
// time; the report's tick_profile_ms, docs/decisions/tick-stages.md): step1 (kinematics, collision, rows, M, c),
// control (pose sources, servos, balance controllers), step2 (dynamics, constraint solve, integration), sense (foot
// contacts, metrics), and the finer stages: physics (collision, dynamics, solver, integration), control (graph, pose,
// stepping, servo, qp) summed over the boxers; qp_solve_us: the balance QP's median solve (boxer 0).
// profile = false: the stages unprofiled (the overhead of the profile is the difference to the same case profiled).
void BM_Tick(benchmark::State& state, const char* scenario, const char* balance, bool profile) {
  auto w = make(scenario, balance);
  w->profile_stages = profile;
  constexpr int kTicks = 480;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    for (int i = 0; i < kTicks; ++i) boxing::step_world(*w);
    state.SetIterationTime((thread_seconds() - t0) / kTicks);
  }
  state.counters["boxers"] = double(w->boxers.size());
  const nlohmann::json r = boxing::world_report(*w)["tick_profile_ms"];
  for (const auto& [stage, ms] : r.items()) state.counters[stage + "_us"] = 1e3 * ms.get<double>();
  if (w->boxers[0].uses_qp())
    state.counters["qp_solve_median_us"] = std::get<boxing::QpBalance>(w->boxers[0].ctl.balance).solve_us.percentile(50);
  state.counters["fell"] = w->boxers[0].metrics.fell;
}
#define TICK(name, scenario, balance, profile)                                                      \
  BENCHMARK_CAPTURE(BM_Tick, name, scenario, balance, profile)->Iterations(3)->UseManualTime()->Unit( \
      benchmark::kMicrosecond)
TICK(push_qp, "push", "qp", true);  // one boxer standing (the push scenario without a push: boxer 0 alone)
TICK(stand_qp, "stand", "qp", true);  // two boxers standing
TICK(stand_pd, "stand", "pd", true);
TICK(walk_qp, "graph-walk", "qp", true);  // one boxer walking the motion graph
TICK(match_qp, "match", "qp", true);      // two boxers fighting
TICK(stand_qp_unprofiled, "stand", "qp", false);
#undef TICK

// The balance QP's solve alone, on boxer 0's inputs after 1 s of standing (the same call boxer_control makes).
void BM_BalanceQpSolve(benchmark::State& state) {
  auto w = stand_world("qp");
  boxing::QpBalance& q = std::get<boxing::QpBalance>(w->boxers[0].ctl.balance);
  const eng::control::BalanceQpInput in = q.in;
  eng::physics::step1(w->model, w->data);  // the M and c the solve reads, at this state
  constexpr int kSolves = 200;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    for (int i = 0; i < kSolves; ++i) eng::control::balance_qp_solve(w->model, w->data, in, q.params, q.ws, q.out);
    state.SetIterationTime((thread_seconds() - t0) / kSolves);
  }
  state.counters["contacts"] = double(in.contacts.size());
  state.counters["dofs"] = double(in.dof_end - in.dof_begin);
}
BENCHMARK(BM_BalanceQpSolve)->Iterations(5)->UseManualTime()->Unit(benchmark::kMicrosecond);

// What the balance QP rebuilt per boxer before the step's halves were shared: CRBA + bias forces of the whole model.
void BM_MassMatrixAndBias(benchmark::State& state) {
  auto w = stand_world("qp");
  eng::physics::MatX M(w->model.nv, w->model.nv);
  eng::physics::VecX c(w->model.nv);
  constexpr int kReps = 200;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    for (int i = 0; i < kReps; ++i) eng::physics::crba(w->model, w->data, M), eng::physics::bias_forces(w->model, w->data, c);
    state.SetIterationTime((thread_seconds() - t0) / kReps);
  }
  state.counters["nv"] = w->model.nv;
}
BENCHMARK(BM_MassMatrixAndBias)->Iterations(5)->UseManualTime()->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
