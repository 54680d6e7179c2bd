// COSMOS_STATUS as the web view's JSON: every CellStatus field under its own name with its
// value (every total of visit_totals among them), the state as cell_status_t's name.
#include "realtime/web/status_json.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace cosmos {
namespace {

CellStatus distinct_status() {
  CellStatus status;
  status.utime_us = 1'700'000'000'123;
  status.state = CellState::kFault;
  status.state_text = "the scanner source failed";
  std::int64_t value = 100;
  CellStatus::visit_totals(
      status, [&value](const char*, std::int64_t& total, const char*) { total = value++; });
  status.profiles_acquired = 2;
  status.profiles_dropped = 3;
  status.deadline_overruns = 4;
  status.profile_time_p50_us = 5.5;
  status.profile_time_p99_us = 6.5;
  status.profile_time_max_us = 7.5;
  status.parts_seen = 8;
  status.parts_recognized = 9;
  status.parts_rejected = 10;
  status.recognition_queue_depth = 11;
  status.publish_queue_depth = 12;
  return status;
}

TEST(StatusJson, CarriesEveryFieldWithItsValue) {
  const nlohmann::ordered_json json = status_json(distinct_status());
  EXPECT_EQ(json.at("utime_us").get<std::int64_t>(), 1'700'000'000'123);
  EXPECT_EQ(json.at("state"), "FAULT");
  EXPECT_EQ(json.at("state_text"), "the scanner source failed");
  EXPECT_EQ(json.at("profiles_acquired"), 2);
  EXPECT_EQ(json.at("profiles_dropped"), 3);
  EXPECT_EQ(json.at("deadline_overruns"), 4);
  EXPECT_DOUBLE_EQ(json.at("profile_time_p50_us").get<double>(), 5.5);
  EXPECT_DOUBLE_EQ(json.at("profile_time_p99_us").get<double>(), 6.5);
  EXPECT_DOUBLE_EQ(json.at("profile_time_max_us").get<double>(), 7.5);
  EXPECT_EQ(json.at("parts_seen"), 8);
  EXPECT_EQ(json.at("parts_recognized"), 9);
  EXPECT_EQ(json.at("parts_rejected"), 10);
  EXPECT_EQ(json.at("recognition_queue_depth"), 11);
  EXPECT_EQ(json.at("publish_queue_depth"), 12);
  const CellStatus sent = distinct_status();
  CellStatus::visit_totals(sent, [&json](const char* name, std::int64_t total, const char*) {
    EXPECT_EQ(json.at(name), total) << name;
  });
  std::size_t totals = 0;
  const CellStatus empty;
  CellStatus::visit_totals(empty, [&totals](const char*, std::int64_t, const char*) { ++totals; });
  EXPECT_EQ(json.size(), 3u + totals + 5u);
}

TEST(StatusJson, KeepsTheFieldsInDeclarationOrder) {
  // The page lists the counters in this order.
  const nlohmann::ordered_json json = status_json(distinct_status());
  std::vector<std::string> keys;
  for (const auto& [key, value] : json.items()) keys.push_back(key);
  EXPECT_EQ(keys.front(), "utime_us");
  EXPECT_EQ(keys[3], "profiles_acquired");
  EXPECT_EQ(keys.back(), "publish_queue_depth");
}

TEST(StatusJson, NamesEveryState) {
  CellStatus status;
  status.state = CellState::kScanning;
  EXPECT_EQ(status_json(status).at("state"), "SCANNING");
  status.state = CellState::kIdle;
  EXPECT_EQ(status_json(status).at("state"), "IDLE");
  status.state = static_cast<CellState>(7);
  EXPECT_EQ(status_json(status).at("state"), "UNKNOWN");
}

}  // namespace
}  // namespace cosmos
