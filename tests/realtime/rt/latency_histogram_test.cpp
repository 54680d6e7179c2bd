// The log-linear latency histogram: quantiles of known distributions within its documented
// 0.4 % bucket error, exact count, min and max, reset and merge.
#include "realtime/rt/latency_histogram.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

namespace cosmos {
namespace {

TEST(LatencyHistogram, EmptyReportsZeros) {
  const LatencyHistogram histogram;
  EXPECT_EQ(histogram.count(), 0);
  EXPECT_EQ(histogram.p50_ns(), 0);
  EXPECT_EQ(histogram.max_ns(), 0);
  EXPECT_EQ(histogram.min_ns(), 0);
  EXPECT_EQ(histogram.mean_ns(), 0.0);
}

TEST(LatencyHistogram, UniformOneToTenThousand) {
  LatencyHistogram histogram;
  for (std::int64_t value = 1; value <= 10000; ++value) histogram.record_ns(value);
  EXPECT_EQ(histogram.count(), 10000);
  EXPECT_EQ(histogram.min_ns(), 1);
  EXPECT_EQ(histogram.max_ns(), 10000);
  EXPECT_NEAR(histogram.mean_ns(), 5000.5, 1e-9);
  EXPECT_NEAR(static_cast<double>(histogram.p50_ns()), 5000.0, 5000.0 * 0.02);
  EXPECT_NEAR(static_cast<double>(histogram.p99_ns()), 9900.0, 9900.0 * 0.02);
  EXPECT_NEAR(static_cast<double>(histogram.p999_ns()), 9990.0, 9990.0 * 0.02);
  // The documented bound is tighter than the 2 % asked: half a bucket, 1/256 of the value.
  EXPECT_NEAR(static_cast<double>(histogram.p50_ns()), 5000.0, 5000.0 / 256 + 1);
  EXPECT_EQ(histogram.quantile_ns(0.0), 1);
  EXPECT_EQ(histogram.quantile_ns(1.0), 10000);
}

TEST(LatencyHistogram, SmallValuesAreExact) {
  LatencyHistogram histogram;
  for (std::int64_t value = 0; value < 200; ++value) histogram.record_ns(value);
  EXPECT_EQ(histogram.quantile_ns(0.5), 99);  // rank 100 of 0..199
  EXPECT_EQ(histogram.quantile_ns(0.25), 49);
}

TEST(LatencyHistogram, TailOfASkewedDistribution) {
  // 99 % of periods start 20 us late, 1 % are 5 ms late: p50 and p99 see the bulk, p99.9
  // and max the tail.
  LatencyHistogram histogram;
  for (int k = 0; k < 100000; ++k) histogram.record_ns(k % 100 == 0 ? 5'000'000 : 20'000);
  EXPECT_NEAR(static_cast<double>(histogram.p50_ns()), 20'000.0, 20'000.0 * 0.01);
  EXPECT_NEAR(static_cast<double>(histogram.p99_ns()), 20'000.0, 20'000.0 * 0.01);
  EXPECT_NEAR(static_cast<double>(histogram.p999_ns()), 5'000'000.0, 5'000'000.0 * 0.01);
  EXPECT_EQ(histogram.max_ns(), 5'000'000);
}

TEST(LatencyHistogram, ExtremesAndNegativeValues) {
  LatencyHistogram histogram;
  histogram.record_ns(-5);  // counted as 0
  histogram.record_ns(std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(histogram.count(), 2);
  EXPECT_EQ(histogram.min_ns(), 0);
  EXPECT_EQ(histogram.max_ns(), std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(histogram.quantile_ns(0.5), 0);
  // The top bucket's midpoint, within half a bucket (1/256) of the value.
  const double top = static_cast<double>(std::numeric_limits<std::int64_t>::max());
  EXPECT_NEAR(static_cast<double>(histogram.quantile_ns(0.99)), top, top / 256);
  EXPECT_EQ(histogram.quantile_ns(1.0), std::numeric_limits<std::int64_t>::max());
}

TEST(LatencyHistogram, ResetAndMerge) {
  LatencyHistogram low, high;
  for (std::int64_t value = 1; value <= 1000; ++value) low.record_ns(value);
  for (std::int64_t value = 1001; value <= 2000; ++value) high.record_ns(value);
  low.merge(high);
  EXPECT_EQ(low.count(), 2000);
  EXPECT_EQ(low.min_ns(), 1);
  EXPECT_EQ(low.max_ns(), 2000);
  EXPECT_NEAR(static_cast<double>(low.p50_ns()), 1000.0, 1000.0 / 256 + 1);
  low.reset();
  EXPECT_EQ(low.count(), 0);
  EXPECT_EQ(low.p99_ns(), 0);
  low.record_ns(300);
  EXPECT_EQ(low.min_ns(), 300);
  EXPECT_EQ(low.max_ns(), 300);
  EXPECT_EQ(low.p50_ns(), 300);  // the midpoint is clamped to the recorded range
}

}  // namespace
}  // namespace cosmos
