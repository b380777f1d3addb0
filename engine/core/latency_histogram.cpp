#include "engine/core/latency_histogram.h"

#include <algorithm>
#include <cmath>

namespace eng::core {

void LatencyHistogram::record(double us) {
  if (!(us >= 0.0)) us = 0.0;  // NaN / negative (a clock step) count as zero
  int bin;
  if (us < kFineEndUs) bin = static_cast<int>(us / kFineWidthUs);
  else if (us < kCoarseEndUs) bin = kFineBins + static_cast<int>((us - kFineEndUs) / kCoarseWidthUs);
  else bin = kBins - 1;
  bins_[std::min(bin, kBins - 1)] += 1;
  ++count_;
  sum_ += us;
  max_ = std::max(max_, us);
}

double LatencyHistogram::percentile(double p) const {
  if (count_ == 0) return 0.0;
  const double target = std::clamp(p, 0.0, 100.0) / 100.0 * count_;
  long cum = 0;
  for (int i = 0; i < kBins; ++i) {
    cum += bins_[i];
    if (cum >= target && bins_[i] > 0) {
      if (i == kBins - 1) return max_;
      const double upper = i < kFineBins ? (i + 1) * kFineWidthUs : kFineEndUs + (i - kFineBins + 1) * kCoarseWidthUs;
      return std::min(upper, max_);
    }
  }
  return max_;
}

}  // namespace eng::core
