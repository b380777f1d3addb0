#pragma once
// The ground as the biped layer sees it: a height query, the support surface's height under a world point (x, y).
// A function pointer and its context (no allocation, no virtual call, any terrain behind it: the game's crates, a
// test's step function). The callable passed to of() must outlive the query.
namespace eng::control {

struct GroundHeight {
  const void* ctx = nullptr;
  double (*fn)(const void*, double, double) = nullptr;
  double operator()(double x, double y) const { return fn(ctx, x, y); }
  // From any callable `double f(double x, double y)` (a lambda, an object with operator()).
  template <class F>
  static GroundHeight of(const F& f) {
    return {&f, [](const void* c, double x, double y) -> double { return (*static_cast<const F*>(c))(x, y); }};
  }
};

}  // namespace eng::control
