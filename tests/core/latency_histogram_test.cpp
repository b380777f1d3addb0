#include "engine/core/latency_histogram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace eng::core {
namespace {

// The exact percentile of the samples (nearest rank), for comparison.
double exact_percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const size_t rank = static_cast<size_t>(std::ceil(p / 100.0 * v.size()));
  return v[std::max<size_t>(rank, 1) - 1];
}

TEST(LatencyHistogram, PercentilesMatchSortedSamplesWithinOneBin) {
  std::mt19937 rng(7);
  std::lognormal_distribution<double> dist(std::log(60.0), 0.6);  // a QP's solve times: median 60 us, a long tail
  std::vector<double> samples;
  LatencyHistogram h;
  for (int i = 0; i < 20000; ++i) {
    const double us = dist(rng);
    samples.push_back(us);
    h.record(us);
  }
  for (double p : {50.0, 90.0, 95.0, 99.0}) {
    const double exact = exact_percentile(samples, p);
    const double width = exact < LatencyHistogram::kFineEndUs ? LatencyHistogram::kFineWidthUs
                                                               : LatencyHistogram::kCoarseWidthUs;
    EXPECT_GE(h.percentile(p), exact) << p;
    EXPECT_LE(h.percentile(p), exact + width) << p;
  }
  EXPECT_EQ(h.count(), 20000);
  EXPECT_DOUBLE_EQ(h.max_us(), *std::max_element(samples.begin(), samples.end()));
}

TEST(LatencyHistogram, OverflowReportsTheLargestSampleAndEmptyIsZero) {
  LatencyHistogram h;
  EXPECT_EQ(h.percentile(50), 0.0);
  h.record(5.0);
  h.record(50000.0);
  h.record(70000.0);
  EXPECT_DOUBLE_EQ(h.percentile(100), 70000.0);
  EXPECT_DOUBLE_EQ(h.percentile(10), 5.5);  // the upper edge of the sample's bin [5, 5.5)
}

}  // namespace
}  // namespace eng::core
