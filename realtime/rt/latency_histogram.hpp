#pragma once
// A histogram of latencies (or any non-negative durations) in nanoseconds, cheap enough to
// record into from the real-time loop: fixed storage allocated at construction, record() is
// a few integer operations and one increment.
//
// Buckets are log-linear, as in HdrHistogram: values below 256 ns have a bucket each (exact);
// above, every power-of-two range [2^k, 2^(k+1)) is split into 128 equal buckets, so a bucket
// is at most 1/128 of its values wide. Quantiles report the bucket's midpoint (clamped to the
// recorded min and max), within 0.4 % of a recorded value of that rank. Every int64 value has
// a bucket (7,296 of them, 57 KiB), so nothing is ever clamped; min, max, count and sum are
// kept exactly.
//
// Not thread-safe: one thread records; others read only through the owner's hand-off (e.g.
// a copy made by the recording thread between periods).
#include <cstdint>
#include <vector>

namespace cosmos {

class LatencyHistogram {
 public:
  LatencyHistogram();

  // Negative values (a clock stepping back, a caller's subtraction) count as 0.
  void record_ns(std::int64_t value_ns) noexcept;
  void reset() noexcept;

  std::int64_t count() const noexcept { return count_; }
  // 0 when empty.
  std::int64_t min_ns() const noexcept { return count_ > 0 ? min_ns_ : 0; }
  std::int64_t max_ns() const noexcept { return max_ns_; }
  double mean_ns() const noexcept;

  // The value at quantile q in [0, 1]: the smallest bucket holding at least ceil(q * count)
  // of the values; 0 when empty. q = 0 gives min, q = 1 gives max.
  std::int64_t quantile_ns(double q) const noexcept;
  std::int64_t p50_ns() const noexcept { return quantile_ns(0.5); }
  std::int64_t p99_ns() const noexcept { return quantile_ns(0.99); }
  std::int64_t p999_ns() const noexcept { return quantile_ns(0.999); }

  // Adds another histogram's values (e.g. per-thread histograms gathered for a report).
  void merge(const LatencyHistogram& other) noexcept;

 private:
  static int bucket_index(std::int64_t value_ns) noexcept;
  static std::int64_t bucket_midpoint_ns(int index) noexcept;

  std::vector<std::int64_t> counts_;
  std::int64_t count_ = 0;
  std::int64_t min_ns_ = 0;
  std::int64_t max_ns_ = 0;
  // Sum for the mean; doubles, since int64 sums of long durations could overflow.
  double sum_ns_ = 0.0;
};

}  // namespace cosmos
