#pragma once
// The web view's histogram of pose latency (the tracker closed the part -> its pose
// published, PartPose::latency_ms): fixed 1-2-5 bins from 1 ms to 5 s and one beyond, so the
// page's bars keep their meaning as counts grow and a slow part stands out.
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>

namespace cosmos {

class LatencyBins {
 public:
  static constexpr std::array<double, 12> kUpperEdgesMs = {1,   2,   5,   10,   20,   50,
                                                           100, 200, 500, 1000, 2000, 5000};
  static constexpr std::size_t kBins = kUpperEdgesMs.size() + 1;

  void add(double latency_ms);
  std::int64_t count(std::size_t bin) const { return counts_[bin]; }
  std::int64_t total() const { return total_; }

  // {"count": n, "bins": [{"upper_ms": 1, "count": c}, ..., {"upper_ms": null, "count": c}]}.
  nlohmann::ordered_json json() const;

 private:
  std::array<std::int64_t, kBins> counts_{};
  std::int64_t total_ = 0;
};

}  // namespace cosmos
