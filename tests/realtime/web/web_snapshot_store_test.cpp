// The web view's snapshot store: readers get the summary and every kept part once, then only
// what is new; parts stay while on the strip or among the recent poses; closing wakes a
// waiting reader; the documents of /api/status and /api/poses hold what was handed in.
#include "realtime/web/web_snapshot_store.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <limits>
#include <string>
#include <vector>

namespace cosmos {
namespace {

using std::chrono::milliseconds;

constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

// 0.4 m of strip: 1000 profiles of 0.4 mm.
WebViewSettings settings() {
  WebViewSettings settings;
  settings.belt_strip_m = 0.4;
  settings.recent_poses = 2;
  return settings;
}

BeltStripGeometry geometry() {
  return {.grid_mm = 0.4, .belt_columns = 40, .x0_loop_mm = -8.0, .decimation = 4};
}

PartRecognition part(std::int64_t seq, const std::string& name, std::int64_t last_profile,
                     bool with_image = true) {
  PartRecognition recognition;
  recognition.pose.part_seq = seq;
  recognition.pose.part_name = name;
  recognition.pose.status = PoseStatus::kOk;
  recognition.pose.latency_ms = 30.0 + static_cast<double>(seq);
  recognition.first_profile = last_profile - 7;
  recognition.last_profile = last_profile;
  if (with_image) {
    recognition.image = RangeImage(8, 8, 0.4, 0.4);
    recognition.image_first_profile = recognition.first_profile;
    recognition.image.origin_x_mm = -8.0 + 16 * 0.4;
    for (std::size_t i = 0; i < recognition.image.z_mm.size(); ++i)
      recognition.image.z_mm[i] = i % 3 == 0 ? kNone : 12.5f;
  }
  return recognition;
}

CellStatus scanning(std::int64_t profiles) {
  CellStatus status;
  status.state = CellState::kScanning;
  status.state_text = "scanning";
  status.profiles_acquired = profiles;
  return status;
}

std::vector<std::string> names_of(const WebUpdate& update) {
  std::vector<std::string> names;
  for (const auto& p : update.parts) names.push_back(p->pose.at("part_name"));
  return names;
}

TEST(WebSnapshotStore, ANewReaderGetsTheSummaryAndEveryKeptPartThenOnlyWhatIsNew) {
  WebSnapshotStore store(settings());
  store.set_geometry(geometry());
  store.update_status(scanning(100));
  store.add_part(part(0, "cow", 90));
  store.add_part(part(1, "elephant", 95));

  const WebUpdate first = store.wait_for_update({}, milliseconds(0));
  EXPECT_FALSE(first.closed);
  ASSERT_FALSE(first.summary_json.empty());
  EXPECT_EQ(names_of(first), (std::vector<std::string>{"cow", "elephant"}));
  const auto summary = nlohmann::json::parse(first.summary_json);
  EXPECT_EQ(summary.at("status").at("state"), "SCANNING");
  EXPECT_EQ(summary.at("pose_latency_ms").at("count"), 2);
  EXPECT_EQ(summary.at("belt").at("head_profile"), 99);
  EXPECT_EQ(summary.at("belt").at("width_px"), 10);
  EXPECT_EQ(summary.at("recent_poses"), 2);

  const WebUpdate idle = store.wait_for_update(first.cursor, milliseconds(5));
  EXPECT_TRUE(idle.summary_json.empty());
  EXPECT_TRUE(idle.parts.empty());

  store.add_part(part(2, "fandisk", 120));
  const WebUpdate next = store.wait_for_update(idle.cursor, milliseconds(0));
  EXPECT_EQ(names_of(next), std::vector<std::string>{"fandisk"});
  EXPECT_FALSE(next.summary_json.empty());  // the histogram changed
}

TEST(WebSnapshotStore, APartsEventCarriesItsPoseAndTile) {
  WebSnapshotStore store(settings());
  store.set_geometry(geometry());
  store.add_part(part(0, "cow", 90));
  store.add_part(part(1, "bunny", 95, false));
  const WebUpdate update = store.wait_for_update({}, milliseconds(0));
  ASSERT_EQ(update.parts.size(), 2u);
  const auto with_tile = nlohmann::json::parse(update.parts[0]->event_json);
  EXPECT_EQ(with_tile.at("pose").at("part_name"), "cow");
  EXPECT_EQ(with_tile.at("tile").at("last_profile"), 90);
  EXPECT_EQ(with_tile.at("tile").at("width_px"), 2);
  EXPECT_EQ(with_tile.at("tile").at("height_px"), 2);
  EXPECT_DOUBLE_EQ(with_tile.at("tile").at("z_max_mm").get<double>(), 12.5);
  EXPECT_EQ(with_tile.at("tile").at("levels_base64"), "/////w==");  // 4 pixels at the top
  EXPECT_TRUE(nlohmann::json::parse(update.parts[1]->event_json).at("tile").is_null());
}

TEST(WebSnapshotStore, KeepsPartsOnTheStripOrAmongTheRecentPoses) {
  WebSnapshotStore store(settings());
  store.set_geometry(geometry());
  store.add_part(part(0, "cow", 40));
  store.add_part(part(1, "elephant", 400));
  store.add_part(part(2, "fandisk", 900));
  store.add_part(part(3, "bunny", 1050));
  // Head 1050: all within 1000 profiles of it but the cow, which is not recent either.
  EXPECT_EQ(names_of(store.wait_for_update({}, milliseconds(0))),
            (std::vector<std::string>{"elephant", "fandisk", "bunny"}));
  store.update_status(scanning(2001));  // head 2000: the strip ends at 1000
  EXPECT_EQ(names_of(store.wait_for_update({}, milliseconds(0))),
            (std::vector<std::string>{"fandisk", "bunny"}));
  store.update_status(scanning(100000));
  EXPECT_EQ(store.wait_for_update({}, milliseconds(0)).parts.size(), 2u);  // recent_poses
}

TEST(WebSnapshotStore, PosesDocumentListsTheRecentPosesNewestFirst) {
  WebSnapshotStore store(settings());
  EXPECT_EQ(nlohmann::json::parse(store.poses_document()).at("poses").size(), 0u);
  store.add_part(part(0, "cow", 100));
  store.add_part(part(1, "elephant", 200));
  store.add_part(part(2, "fandisk", 300));
  const auto poses = nlohmann::json::parse(store.poses_document()).at("poses");
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[0].at("part_name"), "fandisk");
  EXPECT_EQ(poses[1].at("part_name"), "elephant");
  EXPECT_EQ(poses[0].at("last_profile"), 300);
}

TEST(WebSnapshotStore, StatusDocumentHasNoStatusBeforeTheFirst) {
  WebSnapshotStore store(settings());
  EXPECT_TRUE(nlohmann::json::parse(store.status_document()).at("status").is_null());
  CellStatus status = scanning(5);
  status.parts_rejected = 3;
  store.update_status(status);
  const auto document = nlohmann::json::parse(store.status_document());
  EXPECT_EQ(document.at("status").at("parts_rejected"), 3);
  EXPECT_EQ(document.at("status").at("profiles_acquired"), 5);
}

TEST(WebSnapshotStore, ClosingWakesAWaitingReader) {
  WebSnapshotStore store(settings());
  const WebCursor seen = store.wait_for_update({}, milliseconds(0)).cursor;
  // Without the wake-up the reader would sleep for its hour and the test time out.
  auto reader = std::async(std::launch::async,
                           [&] { return store.wait_for_update(seen, std::chrono::hours(1)); });
  store.close();
  const WebUpdate update = reader.get();
  EXPECT_TRUE(update.closed);
  EXPECT_TRUE(update.parts.empty());
}

}  // namespace
}  // namespace cosmos
