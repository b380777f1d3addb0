// Bitwise determinism and allocation-free stepping.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <new>

#include "physics/physics_test_util.h"

// ---- allocation counter: replaced global operator new + wrapped malloc (see CMakeLists.txt) ----
namespace {
bool g_count_allocs = false;
long g_allocs = 0;
}  // namespace
extern "C" void* __real_malloc(size_t);
extern "C" void* __wrap_malloc(size_t n) {
  if (g_count_allocs) ++g_allocs;
  return __real_malloc(n);
}
void* operator new(std::size_t n) {
  if (g_count_allocs) ++g_allocs;
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  return p;
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace eng::physics;
using namespace eng::physics::test;

namespace {
// The step's every stage (contacts on a floor and a crate, limits, damping), without joint springs.
Model scene() { return humanoid_on_floor(0.0); }
void run(const Model& m, Data& d, int n) {
  for (int i = 0; i < n; ++i) {
    clear_applied(d);
    apply_force_at_point(m, d, 2, Vec3(std::sin(0.01 * i) * 30, 10, 0), d.com_world[2]);
    for (int k = 6; k < m.nv; ++k) d.tau[k] = 5 * std::sin(0.02 * i + k);
    step(m, d);
  }
}
}  // namespace

TEST(Determinism, StepWithPointSpringsAndContactEventsDoesNotAllocateOnceWarm) {
  const Model m = scene();
  Data d = make_data(m);
  d.q[2] = 1.0;
  for (int s = 0; s < 3; ++s) {
    PointSpring& ps = d.point_springs[2 * s];
    ps.active = true;
    ps.body = 1 + 4 * s;
    ps.local_point = Vec3(0.02, 0, -0.1);
    ps.target = Vec3(0.1 * s, 0.2, 1.1);
    ps.hertz = 4.0;
    ps.max_force = 200.0;
  }
  long events = 0;
  auto run_springs = [&](int n, int i0) {
    for (int i = i0; i < i0 + n; ++i) {
      d.point_springs[0].target.x() = 0.3 * std::sin(0.01 * i);
      d.point_springs[4].active = (i / 50) % 2 == 0;  // switched on and off
      run(m, d, 1);
      events += static_cast<long>(d.contact_begin.size() + d.contact_end.size() + d.hit_events.size());
    }
  };
  run_springs(300, 0);
  events = 0;
  g_allocs = 0;
  g_count_allocs = true;
  run_springs(300, 300);
  g_count_allocs = false;
  EXPECT_EQ(g_allocs, 0);
  EXPECT_GT(events, 0);  // the counted steps did produce contact events
  EXPECT_GT(d.point_springs[0].force.norm(), 0.0);
}

TEST(Determinism, TwoIdenticalRunsMatchBitForBit) {
  const Model m = scene();
  Data a = make_data(m), b = make_data(m);
  a.q[2] = b.q[2] = 1.0;
  run(m, a, 600);
  run(m, b, 600);
  ASSERT_EQ(a.q.size(), b.q.size());
  EXPECT_EQ(0, std::memcmp(a.q.data(), b.q.data(), sizeof(double) * a.q.size()));
  EXPECT_EQ(0, std::memcmp(a.v.data(), b.v.data(), sizeof(double) * a.v.size()));
  EXPECT_TRUE(a.q.allFinite());
}

TEST(Determinism, StepDoesNotAllocateOnceWarm) {
  const Model m = scene();
  Data d = make_data(m);
  d.q[2] = 1.0;
  run(m, d, 300);  // warm: contacts / pairs reached their working capacity
  g_allocs = 0;
  g_count_allocs = true;
  run(m, d, 300);
  g_count_allocs = false;
  EXPECT_EQ(g_allocs, 0);
  // the counter itself works
  g_count_allocs = true;
  {
    void* (*volatile fp)(size_t) = &std::malloc;  // what Eigen's dynamic storage calls
    std::free(fp(64));
  }
  g_count_allocs = false;
  EXPECT_EQ(g_allocs, 1);
  g_count_allocs = true;
  { std::vector<double> tmp(100); tmp[3] = 1; }
  g_count_allocs = false;
  EXPECT_GT(g_allocs, 0);
}
