// bench_game: the game's world step (physics + control) for two boxers standing, balance QP against the PD
// balance layer in the same run, and the balance QP's own solve on the inputs of a settled stance.
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
// time): step1 (kinematics, collision, rows, M, c), control (pose sources, servos, balance controllers), step2
// (dynamics, constraint solve, integration), sense (foot contacts, metrics); qp_solve: the balance QP's median.
void BM_Tick(benchmark::State& state, const char* scenario, const char* balance) {
  auto w = make(scenario, balance);
  constexpr int kTicks = 480;
  for (auto _ : state) {
    const double t0 = thread_seconds();
    for (int i = 0; i < kTicks; ++i) boxing::step_world(*w);
    state.SetIterationTime((thread_seconds() - t0) / kTicks);
  }
  const double n = static_cast<double>(w->steps);
  state.counters["boxers"] = double(w->boxers.size());
  state.counters["step1_us"] = 1e3 * w->profile.step1_ms / n;
  state.counters["control_us"] = 1e3 * w->profile.control_ms / n;
  state.counters["step2_us"] = 1e3 * w->profile.step2_ms / n;
  state.counters["sense_us"] = 1e3 * w->profile.sense_ms / n;
  if (w->boxers[0].uses_qp())
    state.counters["qp_solve_us"] = std::get<boxing::QpBalance>(w->boxers[0].ctl.balance).solve_us.percentile(50);
  state.counters["fell"] = w->boxers[0].metrics.fell;
}
BENCHMARK_CAPTURE(BM_Tick, stand_qp, "stand", "qp")->Iterations(3)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tick, stand_pd, "stand", "pd")->Iterations(3)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tick, walk_qp, "graph-walk", "qp")->Iterations(3)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Tick, match_qp, "match", "qp")->Iterations(3)->UseManualTime()->Unit(benchmark::kMicrosecond);

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
