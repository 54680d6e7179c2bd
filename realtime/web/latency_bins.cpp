#include "realtime/web/latency_bins.hpp"

#include <algorithm>

namespace cosmos {

void LatencyBins::add(double latency_ms) {
  // Bin i holds [edge(i-1), edge(i)); NaN and negatives (a clock stepping back) go to the
  // first.
  const auto edge = latency_ms >= 0
                        ? std::upper_bound(kUpperEdgesMs.begin(), kUpperEdgesMs.end(), latency_ms)
                        : kUpperEdgesMs.begin();
  ++counts_[static_cast<std::size_t>(edge - kUpperEdgesMs.begin())];
  ++total_;
}

nlohmann::ordered_json LatencyBins::json() const {
  nlohmann::ordered_json bins = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < kBins; ++i) {
    bins.push_back({{"upper_ms", i < kUpperEdgesMs.size() ? nlohmann::ordered_json(kUpperEdgesMs[i])
                                                          : nlohmann::ordered_json(nullptr)},
                    {"count", counts_[i]}});
  }
  return {{"count", total_}, {"bins", bins}};
}

}  // namespace cosmos
