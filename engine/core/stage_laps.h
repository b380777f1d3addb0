#pragma once
// Per-stage wall time of a pipeline (a physics step, a boxer's control tick), as laps: each lap() adds the time since
// the previous lap (or the start) to one field of a Times struct of doubles (milliseconds, summed over calls; the
// caller resets). Consecutive laps partition the pipeline, so the stages add up to its whole time exactly.
// Off (a null Times): no clock is read, each lap() is one branch. Reporting only: nothing may read the times back
// into a simulation (the same seed gives the same frames bit for bit, with or without profiling).
#include <chrono>

namespace eng::core {

template <class Times>
class StageLaps {
 public:
  using clock = std::chrono::steady_clock;
  explicit StageLaps(Times* times) : times_(times) {
    if (times_) last_ = clock::now();
  }
  // The time since the last lap goes to `field`.
  void lap(double Times::*field) {
    if (!times_) return;
    const clock::time_point now = clock::now();
    times_->*field += std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
  }

 private:
  Times* times_;
  clock::time_point last_{};
};

}  // namespace eng::core
