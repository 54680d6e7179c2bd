#include "realtime/rt/latency_histogram.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace cosmos {
namespace {

constexpr int kExactBuckets = 256;  // values 0..255 ns, one bucket each
constexpr int kSubBucketBits = 7;   // 128 buckets per power of two above
constexpr int kSubBuckets = 1 << kSubBucketBits;
constexpr int kFirstOctave = 8;  // 2^8 = kExactBuckets
constexpr int kLastOctave = 62;  // the top power of two of a positive int64
constexpr int kBucketCount = kExactBuckets + (kLastOctave - kFirstOctave + 1) * kSubBuckets;

}  // namespace

LatencyHistogram::LatencyHistogram() : counts_(kBucketCount, 0) {}

int LatencyHistogram::bucket_index(std::int64_t value_ns) noexcept {
  if (value_ns < kExactBuckets) return static_cast<int>(value_ns);
  const auto value = static_cast<std::uint64_t>(value_ns);
  const int octave = std::bit_width(value) - 1;
  const int shift = octave - kSubBucketBits;
  const int sub_bucket = static_cast<int>(value >> shift) - kSubBuckets;
  return kExactBuckets + (octave - kFirstOctave) * kSubBuckets + sub_bucket;
}

std::int64_t LatencyHistogram::bucket_midpoint_ns(int index) noexcept {
  if (index < kExactBuckets) return index;
  const int octave = kFirstOctave + (index - kExactBuckets) / kSubBuckets;
  const int sub_bucket = (index - kExactBuckets) % kSubBuckets;
  const int shift = octave - kSubBucketBits;
  const std::uint64_t low = static_cast<std::uint64_t>(kSubBuckets + sub_bucket) << shift;
  return static_cast<std::int64_t>(low + (std::uint64_t{1} << shift) / 2);
}

void LatencyHistogram::record_ns(std::int64_t value_ns) noexcept {
  value_ns = std::max<std::int64_t>(value_ns, 0);
  ++counts_[bucket_index(value_ns)];
  if (count_ == 0 || value_ns < min_ns_) min_ns_ = value_ns;
  max_ns_ = std::max(max_ns_, value_ns);
  sum_ns_ += static_cast<double>(value_ns);
  ++count_;
}

void LatencyHistogram::reset() noexcept {
  std::fill(counts_.begin(), counts_.end(), 0);
  count_ = 0;
  min_ns_ = 0;
  max_ns_ = 0;
  sum_ns_ = 0.0;
}

double LatencyHistogram::mean_ns() const noexcept {
  return count_ > 0 ? sum_ns_ / static_cast<double>(count_) : 0.0;
}

std::int64_t LatencyHistogram::quantile_ns(double q) const noexcept {
  if (count_ == 0) return 0;
  if (!(q > 0.0)) return min_ns_;  // also NaN
  if (q >= 1.0) return max_ns_;
  const auto rank = std::max<std::int64_t>(
      1, static_cast<std::int64_t>(std::ceil(q * static_cast<double>(count_))));
  std::int64_t seen = 0;
  for (int index = 0; index < kBucketCount; ++index) {
    seen += counts_[index];
    if (seen >= rank) return std::clamp(bucket_midpoint_ns(index), min_ns_, max_ns_);
  }
  return max_ns_;
}

void LatencyHistogram::merge(const LatencyHistogram& other) noexcept {
  if (other.count_ == 0) return;
  for (int index = 0; index < kBucketCount; ++index) counts_[index] += other.counts_[index];
  min_ns_ = count_ > 0 ? std::min(min_ns_, other.min_ns_) : other.min_ns_;
  max_ns_ = std::max(max_ns_, other.max_ns_);
  sum_ns_ += other.sum_ns_;
  count_ += other.count_;
}

}  // namespace cosmos
