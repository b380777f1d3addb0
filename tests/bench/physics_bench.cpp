// Humanoid step cost: our engine (eng::physics::step) vs MuJoCo 2.2.2 (mj_step) on the same model
// (/usr/share/mujoco/model/humanoid/humanoid.xml, 27 DoF, converted by humanoid_from_mujoco.h), same start
// (MuJoCo's qpos0: standing, torso at 1.5 m, feet just above the floor; it drops and collapses onto the
// floor), 2000 steps per iteration.
//
//   bench_physics                       Google Benchmark table (all cases, fixed iteration counts)
//   bench_physics --json FILE [...]     same run, plus FILE = {"ours_humanoid_step_us", ...} (best iteration)
//   bench_physics --profile[=N]         per-stage timing of our step, N humanoids (default 1; no framework)
//   bench_physics --check               conversion check vs MuJoCo: body poses, M, bias forces at random states
//
// Not a ctest test (slow); run it with scripts/bench.
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <algorithm>
#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/physics/data.h"
#include "engine/physics/dynamics.h"
#include "engine/physics/model.h"
#include "engine/physics/step.h"
#include "tests/support/humanoid_from_mujoco.h"
#include "tests/support/mujoco_crosscheck.h"

namespace {

using namespace eng::physics;
using Clock = std::chrono::steady_clock;

constexpr int kSteps = 2000;
constexpr double kSpacing = 1.5;  // m between humanoids in the scaling cases
constexpr double kGameDt = 1.0 / 240.0;

// ---------------------------------------------------------------------------------------------- MuJoCo
struct Mj {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  int torso = -1, pelvis = -1;
  Mj() {
    char err[1000] = {0};
    m = mj_loadXML(BOXING_HUMANOID_XML, nullptr, err, sizeof(err));
    if (!m) throw std::runtime_error(std::string("mj_loadXML: ") + err);
    d = mj_makeData(m);
    torso = mj_name2id(m, mjOBJ_BODY, "torso");
    pelvis = mj_name2id(m, mjOBJ_BODY, "pelvis");
  }
  ~Mj() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  double body_z(int b) {
    mj_kinematics(m, d);
    return d->xpos[3 * b + 2];
  }
  bool finite() const {
    for (int i = 0; i < m->nq; ++i)
      if (!std::isfinite(d->qpos[i])) return false;
    for (int i = 0; i < m->nv; ++i)
      if (!std::isfinite(d->qvel[i])) return false;
    return true;
  }
};

Mj& mj() {
  static Mj h;
  return h;
}

// ------------------------------------------------------------------------------------------------ ours
struct Ours {
  Model model;
  std::vector<std::vector<bench::MappedBody>> maps;  // per humanoid, per MuJoCo body id
  Data d;
  double raise = 0.0;  // applied to every free root's start height (0 unless qpos0 penetrates)

  Ours(int n, double dt) {
    maps = bench::convert_mujoco_model(mj().m, model, n, kSpacing);
    model.dt = dt;
    // default capacity 512 would drop contacts beyond ~25 lying humanoids (about 19 contacts each)
    model.solver.max_contacts = std::max(model.solver.max_contacts, 64 * n);
    d = make_data(model);
    raise = std::max(0.0, -lowest_geom_z() + 1e-3);
  }
  // lowest point of the dynamic geoms at the start pose (before any step)
  double lowest_geom_z() {
    forward_kinematics(model, d);
    double zmin = std::numeric_limits<double>::infinity();
    for (const Geom& g : model.geoms) {
      if (g.body == 0) continue;
      const Pose X = d.x[g.body] * g.local;
      double z = X.p.z();
      if (g.shape.type == ShapeType::Capsule) z -= g.shape.half_length * std::abs(X.R(2, 2));
      if (g.shape.type == ShapeType::Box) z -= (X.R.row(2).cwiseAbs() * g.shape.half_extents)(0);
      zmin = std::min(zmin, z - g.shape.radius);
    }
    return zmin;
  }
  void reset() {
    d = make_data(model);
    if (raise > 0.0)
      for (const Body& b : model.bodies)
        if (b.joint == JointType::Free) d.q[b.q_index + 2] += raise;
  }
  double body_z(int humanoid, int mj_body) {
    forward_kinematics(model, d);
    const bench::MappedBody& mb = maps[humanoid][mj_body];
    return d.x[mb.body].apply(mb.offset).z();
  }
  bool finite() const { return d.q.allFinite() && d.v.allFinite(); }
};

// ------------------------------------------------------------------------------------------- results
// Filled by the benchmarks (best iteration), written by --json.
std::map<std::string, double> g_us;       // key -> us per step (best iteration)
std::map<std::string, double> g_height;   // "ours"/"mujoco" torso z after kSteps
std::map<std::string, double> g_pelvis;   // "ours"/"mujoco" pelvis z after kSteps
std::map<std::string, bool> g_finite;

// Timings use the thread's CPU clock: the dev/CI boxes are shared (2 cores, parallel builds), and wall time
// there measures the neighbours as much as the step. The wall time is kept as a counter (wall_us_per_step).
double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
struct Timer {
  double cpu0 = thread_cpu_seconds();
  Clock::time_point wall0 = Clock::now();
  double cpu() const { return thread_cpu_seconds() - cpu0; }
  double wall() const { return std::chrono::duration<double>(Clock::now() - wall0).count(); }
};

void BM_MujocoHumanoidStep(benchmark::State& state) {
  Mj& h = mj();
  double best = 1e30, total = 0, wall = 0, ncon = 0, nefc = 0;
  for (auto _ : state) {
    mj_resetData(h.m, h.d);
    const Timer timer;
    for (int s = 0; s < kSteps; ++s) {
      mj_step(h.m, h.d);
      ncon += h.d->ncon;
      nefc += h.d->nefc;
    }
    const double t = timer.cpu();
    wall += timer.wall();
    state.SetIterationTime(t);
    best = std::min(best, t);
    total += t;
  }
  state.counters["us_per_step"] = 1e6 * total / (double(state.iterations()) * kSteps);
  state.counters["best_us_per_step"] = 1e6 * best / kSteps;
  state.counters["wall_us_per_step"] = 1e6 * wall / (double(state.iterations()) * kSteps);
  state.counters["torso_z"] = h.body_z(h.torso);
  // world z of the torso's forward (x) and left (y) axes: |x_z| ~ 1 lying on front/back, |y_z| ~ 1 on a side
  state.counters["torso_x_z"] = h.d->xmat[9 * h.torso + 6];
  state.counters["torso_y_z"] = h.d->xmat[9 * h.torso + 7];
  state.counters["pelvis_z"] = h.body_z(h.pelvis);
  state.counters["ncon_end"] = h.d->ncon;
  state.counters["mean_contacts"] = ncon / (double(state.iterations()) * kSteps);
  state.counters["mean_rows"] = nefc / (double(state.iterations()) * kSteps);
  g_us["mujoco"] = 1e6 * best / kSteps;
  g_height["mujoco"] = h.body_z(h.torso);
  g_pelvis["mujoco"] = h.body_z(h.pelvis);
  g_finite["mujoco"] = h.finite();
}

void ours_bench(benchmark::State& state, int n, double dt, const std::string& key) {
  Ours o(n, dt);
  double best = 1e30, total = 0, wall = 0, ncon = 0, nrows = 0;
  for (auto _ : state) {
    o.reset();
    const Timer timer;
    for (int s = 0; s < kSteps; ++s) {
      step(o.model, o.d);
      ncon += double(o.d.contacts.size());
      nrows += double(o.d.rows.size());
    }
    const double t = timer.cpu();
    wall += timer.wall();
    state.SetIterationTime(t);
    best = std::min(best, t);
    total += t;
  }
  const double us = 1e6 * total / (double(state.iterations()) * kSteps);
  state.counters["us_per_step"] = us;
  state.counters["us_per_humanoid"] = us / n;
  state.counters["best_us_per_step"] = 1e6 * best / kSteps;
  state.counters["wall_us_per_step"] = 1e6 * wall / (double(state.iterations()) * kSteps);
  state.counters["contacts_end"] = double(o.d.contacts.size());
  state.counters["mean_contacts"] = ncon / (double(state.iterations()) * kSteps);
  state.counters["mean_rows"] = nrows / (double(state.iterations()) * kSteps);
  state.counters["nv"] = o.model.nv;
  const double torso = o.body_z(0, mj().torso), pelvis = o.body_z(0, mj().pelvis);
  state.counters["torso_z"] = torso;
  const Mat3& Rt = o.d.x[o.maps[0][mj().torso].body].R;
  state.counters["torso_x_z"] = Rt(2, 0);
  state.counters["torso_y_z"] = Rt(2, 1);
  state.counters["pelvis_z"] = pelvis;
  state.counters["finite"] = o.finite() ? 1 : 0;
  g_us[key] = 1e6 * best / kSteps;
  if (key == "ours") {
    g_height["ours"] = torso;
    g_pelvis["ours"] = pelvis;
  }
  g_finite[key] = o.finite();
}

void BM_OursHumanoidStep(benchmark::State& state) { ours_bench(state, 1, mj().m->opt.timestep, "ours"); }
void BM_OursHumanoidStepGameDt(benchmark::State& state) { ours_bench(state, 1, kGameDt, "ours_game_dt"); }
void BM_OursHumanoidsScaling(benchmark::State& state) {
  const int n = int(state.range(0));
  ours_bench(state, n, mj().m->opt.timestep, "scaling_" + std::to_string(n));
}

BENCHMARK(BM_MujocoHumanoidStep)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursHumanoidStep)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursHumanoidStepGameDt)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursHumanoidsScaling)->Arg(2)->Arg(8)->Iterations(2)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OursHumanoidsScaling)->Arg(32)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------------------------------------- JSON
std::string num(const std::map<std::string, double>& m, const std::string& k) {
  auto it = m.find(k);
  if (it == m.end() || !std::isfinite(it->second)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.4f", it->second);
  return buf;
}

bool write_json(const char* path) {
  std::map<std::string, double> r = g_us;
  if (r.count("ours") && r.count("mujoco")) r["ratio"] = r["ours"] / r["mujoco"];
  if (r.count("ours")) r["scaling_1"] = r["ours"];
  bool finite = !g_finite.empty();
  for (const auto& [k, ok] : g_finite) finite = finite && ok;
  FILE* f = std::fopen(path, "w");
  if (!f) return false;
  std::fprintf(f, "{\n  \"ours_humanoid_step_us\": %s,\n  \"mujoco_humanoid_step_us\": %s,\n  \"ratio\": %s,\n",
               num(r, "ours").c_str(), num(r, "mujoco").c_str(), num(r, "ratio").c_str());
  std::fprintf(f, "  \"ours_game_dt_step_us\": %s,\n", num(r, "ours_game_dt").c_str());
  std::fprintf(f, "  \"scaling\": {\"1\": %s, \"2\": %s, \"8\": %s, \"32\": %s},\n", num(r, "scaling_1").c_str(),
               num(r, "scaling_2").c_str(), num(r, "scaling_8").c_str(), num(r, "scaling_32").c_str());
  std::fprintf(f, "  \"final_torso_height\": {\"ours\": %s, \"mujoco\": %s},\n", num(g_height, "ours").c_str(),
               num(g_height, "mujoco").c_str());
  std::fprintf(f, "  \"final_pelvis_height\": {\"ours\": %s, \"mujoco\": %s},\n", num(g_pelvis, "ours").c_str(),
               num(g_pelvis, "mujoco").c_str());
  std::fprintf(f, "  \"all_finite\": %s,\n  \"steps\": %d,\n  \"scaling_spacing_m\": %.2f\n}\n",
               finite ? "true" : "false", kSteps, kSpacing);
  std::fclose(f);
  return true;
}

void print_sanity() {
  std::printf("sanity after %d steps (dt %.4g): torso z ours %s m / MuJoCo %s m, pelvis z ours %s m / MuJoCo %s m\n",
              kSteps, mj().m->opt.timestep, num(g_height, "ours").c_str(), num(g_height, "mujoco").c_str(),
              num(g_pelvis, "ours").c_str(), num(g_pelvis, "mujoco").c_str());
  for (const auto& [k, ok] : g_finite)
    if (!ok) std::printf("sanity: NaN/Inf in state of case %s\n", k.c_str());
}

// ------------------------------------------------------------------------------------------- profile
// Per-stage wall time of our step (the same stage sequence as step() in engine/physics/step.cpp).
int profile_mode(int n) {
  Ours o(n, mj().m->opt.timestep);
  const char* names[7] = {"forward_kinematics", "collide", "compute_constraints", "passive_forces",
                          "forward_dynamics", "solve_constraints", "integrate"};
  double t[7] = {0};
  double rows = 0, contacts = 0;
  const int reps = n > 8 ? 1 : 3;
  for (int r = 0; r < reps; ++r) {
    o.reset();
    for (int s = 0; s < kSteps; ++s) {
      Model& m = o.model;
      Data& d = o.d;
      double t0 = thread_cpu_seconds();
      auto lap = [&](int i) {
        const double t1 = thread_cpu_seconds();
        t[i] += t1 - t0;
        t0 = t1;
      };
      forward_kinematics(m, d); lap(0);
      collide(m, d); lap(1);
      compute_constraints(m, d); lap(2);
      passive_forces(m, d); lap(3);
      forward_dynamics(m, d); lap(4);
      solve_constraints(m, d); lap(5);
      integrate(m, d); lap(6);
      rows += double(d.rows.size());
      contacts += double(d.contacts.size());
    }
  }
  const double steps = double(reps) * kSteps;
  double total = 0;
  for (double x : t) total += x;
  std::printf("profile (thread CPU time): %d humanoid(s), nv %d, %d steps x %d, mean contacts %.1f, mean rows %.1f, solver %d iterations\n",
              n, o.model.nv, kSteps, reps, contacts / steps, rows / steps, o.model.solver.iterations);
  for (int i = 0; i < 7; ++i)
    std::printf("  %-22s %8.2f us/step  %5.1f %%\n", names[i], 1e6 * t[i] / steps, 100.0 * t[i] / total);
  std::printf("  %-22s %8.2f us/step\n", "total", 1e6 * total / steps);
  return 0;
}


// --------------------------------------------------------------------------------------------- check
// Conversion check (tests/support/mujoco_crosscheck.h; the same comparison is the ctest test
// tests/physics/mujoco_crosscheck_test.cpp): at 20 random states every MuJoCo body pose, geom pose, the joint-space
// inertia (+ armature) and the bias forces must agree with ours. Prints the largest differences; returns 1 if any is
// large.
int check_mode() {
  Mj& h = mj();
  const bench::CrossCheck x = bench::crosscheck_mujoco(h.m, 20);
  if (!x.same_layout()) {
    std::printf("check: nq/nv differ: ours %d/%d, MuJoCo %d/%d\n", x.nq, x.nv, x.mj_nq, x.mj_nv);
    return 1;
  }
  Ours o(1, h.m->opt.timestep);
  const int nv = h.m->nv;
  unsigned seed = 54321;
  auto rnd = [&]() {  // uniform [-1, 1), fixed LCG for reproducibility
    seed = seed * 1664525u + 1013904223u;
    return double(seed >> 8) / double(1u << 23) - 1.0;
  };
  // pre-contact trajectory from qpos0 with random rates (feet 0.2 m above the floor, no contact for the
  // first ~0.1 s): both integrate the same free flight with springs and damping (MuJoCo: Euler with
  // implicit damping; ours: implicit damping and springs), so q should agree up to the O(dt) integrator differences (informative, not checked).
  mj_resetData(h.m, h.d);
  o.reset();
  for (int i = 0; i < nv; ++i) h.d->qvel[i] = o.d.v[i] = 0.5 * rnd();  // same random joint rates
  const int pre_steps = 20;
  for (int s = 0; s < pre_steps; ++s) {
    mj_step(h.m, h.d);
    step(o.model, o.d);
  }
  double dq = 0;
  for (int i = 0; i < h.m->nq; ++i) dq = std::max(dq, std::abs(o.d.q[i] - h.d->qpos[i]));
  std::printf("check: %d pre-contact steps from qpos0: max |q ours - q MuJoCo| %.2e (contacts: ours %zu, MuJoCo %d)\n",
              pre_steps, dq, o.d.contacts.size(), h.d->ncon);
  const bool ok = x.body_pos < 1e-9 && x.body_rot < 1e-9 && x.geom_pose < 1e-9 && x.M < 1e-9 * x.M_max &&
                  x.bias < 1e-8 * x.bias_max;
  std::printf("check (%d random states, nq %d nv %d): max |body pos diff| %.2e m, max |R diff| %.2e, "
              "max geom pose diff %.2e, max |M diff| %.2e (max |M| %.2f), max |bias diff| %.2e (max |bias| %.2f): %s\n",
              x.states, h.m->nq, nv, x.body_pos, x.body_rot, x.geom_pose, x.M, x.M_max, x.bias, x.bias_max,
              ok ? "OK" : "MISMATCH");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  // our own flags, removed before benchmark::Initialize
  const char* json = nullptr;
  int profile = 0;
  bool check = false;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (i > 0 && std::strcmp(argv[i], "--json") == 0 && i + 1 < argc) {
      json = argv[++i];
    } else if (i > 0 && std::strcmp(argv[i], "--check") == 0) {
      check = true;
    } else if (i > 0 && std::strncmp(argv[i], "--profile", 9) == 0) {
      profile = (argv[i][9] == '=') ? std::atoi(argv[i] + 10) : 1;
    } else {
      args.push_back(argv[i]);
    }
  }
  if (check) return check_mode();
  if (profile > 0) return profile_mode(profile);
  int n = int(args.size());
  args.push_back(nullptr);
  benchmark::Initialize(&n, args.data());
  if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  print_sanity();
  if (json && !write_json(json)) {
    std::fprintf(stderr, "bench_physics: cannot write %s\n", json);
    return 1;
  }
  return 0;
}
