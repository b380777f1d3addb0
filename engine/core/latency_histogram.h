#pragma once
// Latency statistics without storing samples: a fixed histogram (no allocation after construction), for
// wall-clock costs measured inside the game loop (reports only; never fed back into the simulation).
// Bins are 0.5 us wide up to 1 ms, 10 us wide up to 20 ms, then one overflow bin; a percentile is the upper edge
// of the bin where the cumulative count crosses it (so it over-estimates by at most one bin width).
#include <array>
#include <cstdint>

namespace eng::core {

class LatencyHistogram {
 public:
  static constexpr double kFineWidthUs = 0.5, kFineEndUs = 1000.0;
  static constexpr double kCoarseWidthUs = 10.0, kCoarseEndUs = 20000.0;
  static constexpr int kFineBins = static_cast<int>(kFineEndUs / kFineWidthUs);
  static constexpr int kCoarseBins = static_cast<int>((kCoarseEndUs - kFineEndUs) / kCoarseWidthUs);
  static constexpr int kBins = kFineBins + kCoarseBins + 1;  // + overflow

  void record(double us);
  // The p-th percentile (p in [0, 100]) in microseconds; 0 when empty. The overflow bin reports the largest
  // sample seen.
  double percentile(double p) const;
  long count() const { return count_; }
  double max_us() const { return max_; }
  double mean_us() const { return count_ ? sum_ / count_ : 0.0; }

 private:
  std::array<uint32_t, kBins> bins_{};
  long count_ = 0;
  double sum_ = 0.0, max_ = 0.0;
};

}  // namespace eng::core
