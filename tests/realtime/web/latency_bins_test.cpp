// The pose-latency histogram: each latency in the bin [previous edge, edge), the slow ones in
// the last, and its JSON listing every bin.
#include "realtime/web/latency_bins.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace cosmos {
namespace {

TEST(LatencyBins, PutsEachLatencyBelowItsUpperEdge) {
  LatencyBins bins;
  bins.add(0.4);   // [0, 1)
  bins.add(1.0);   // [1, 2): an edge belongs to the bin above
  bins.add(48.3);  // [20, 50)
  bins.add(50.0);  // [50, 100)
  bins.add(7200);  // beyond 5 s
  EXPECT_EQ(bins.count(0), 1);
  EXPECT_EQ(bins.count(1), 1);
  EXPECT_EQ(bins.count(5), 1);
  EXPECT_EQ(bins.count(6), 1);
  EXPECT_EQ(bins.count(LatencyBins::kBins - 1), 1);
  EXPECT_EQ(bins.total(), 5);
}

TEST(LatencyBins, CountsNegativeAndNanInTheFirstBin) {
  LatencyBins bins;
  bins.add(-3);
  bins.add(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(bins.count(0), 2);
}

TEST(LatencyBins, JsonListsEveryBinWithItsUpperEdge) {
  LatencyBins bins;
  bins.add(15);
  bins.add(16);
  const nlohmann::ordered_json json = bins.json();
  EXPECT_EQ(json.at("count"), 2);
  const auto& list = json.at("bins");
  ASSERT_EQ(list.size(), LatencyBins::kBins);
  EXPECT_DOUBLE_EQ(list[0].at("upper_ms").get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(list[4].at("upper_ms").get<double>(), 20.0);
  EXPECT_EQ(list[4].at("count"), 2);
  EXPECT_TRUE(list.back().at("upper_ms").is_null());
}

}  // namespace
}  // namespace cosmos
