// The web view wired into a running cell as `cosmos cell --http` wires it: a 3-part simulated
// cell (unpaced, every part recognized) publishes through the view's publisher and hands each
// pose to it; its /api/poses then lists exactly the poses the cell published, each part's
// /events entry carries a belt tile with the part's pixels, and /api/status holds the
// cell's last COSMOS_STATUS.
#include "realtime/web/web_view.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"
#include "tests/regression_model_base.hpp"

// Last: it pulls in <resolv.h>, whose `_res` macro breaks Eigen's headers included after it.
#include <httplib.h>

namespace cosmos {
namespace {

namespace fs = std::filesystem;

TEST(WebView, ShowsWhatTheRunningCellPublished) {
  const ModelBase base = read_model_base(testing::regression_model_base());
  const PartCatalog catalog =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
  const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});
  SimulatedSourceSettings source_settings;
  source_settings.parts = 3;
  source_settings.seed = 5;
  SimulatedSource source(catalog, ScannerParameters{}, source_settings);
  ASSERT_EQ(source.start(), SourceStatus::kOk);
  ScanLoopSettings loop_settings;
  loop_settings.wait_for_recognizer = true;
  ScanLoop loop(loop_settings);

  PartRecognitionContext context;
  context.recognizer = &recognizer;
  context.model_base = &base;
  context.catalog_index_of_base_part.assign(base.parts.size(), -1);
  context.x0_loop_mm = loop.x0_loop_mm();
  context.keep_part_image = true;
  CellRunSettings settings;
  settings.paced = false;

  WebView web(WebViewSettings{}, {"127.0.0.1", 0});
  web.set_belt(ConditioningParameters{}.grid_mm, loop.width(), loop.x0_loop_mm());
  MemoryPublisher published;
  int observed_with_image = 0;
  const CellRunSummary summary = run_cell(source, loop, context, web.publisher(published), settings,
                                          [&](const PartRecognition& part) {
                                            observed_with_image += part.image.count_valid() > 0;
                                            web.observe(part);
                                          });
  // A part cut by its own shadow is seen as two pieces and published as one pose.
  ASSERT_GE(summary.parts_seen, 3);
  ASSERT_EQ(published.poses.size(), 3u);
  EXPECT_EQ(observed_with_image, 3);
  ASSERT_FALSE(published.statuses.empty());

  httplib::Client http("127.0.0.1", web.port());
  const auto poses_reply = http.Get("/api/poses");
  ASSERT_TRUE(poses_reply);
  const auto poses = nlohmann::json::parse(poses_reply->body).at("poses");
  ASSERT_EQ(poses.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const PartPose& sent = published.poses[2 - i];  // the page's newest first
    EXPECT_EQ(poses[i].at("part_seq"), sent.part_seq);
    EXPECT_EQ(poses[i].at("part_name"), sent.part_name);
    EXPECT_EQ(poses[i].at("encoder_ticks"), sent.encoder_ticks);
    EXPECT_DOUBLE_EQ(poses[i].at("translation_mm")[1].get<double>(),
                     sent.translation_cell_part_mm.y());
  }

  const auto status_reply = http.Get("/api/status");
  ASSERT_TRUE(status_reply);
  const auto status = nlohmann::json::parse(status_reply->body);
  EXPECT_EQ(status.at("status").at("parts_seen"), summary.parts_seen);
  EXPECT_EQ(status.at("status").at("state"), "IDLE");
  EXPECT_EQ(status.at("status").at("profiles_acquired"), summary.profiles);
  EXPECT_EQ(status.at("pose_latency_ms").at("count"), 3);

  // Every kept part's event, from a new reader's replay, with a tile of the part's pixels.
  const WebUpdate replay = web.store().wait_for_update({}, std::chrono::milliseconds(0));
  ASSERT_EQ(replay.parts.size(), 3u);
  for (const auto& part : replay.parts) {
    const auto event = nlohmann::json::parse(part->event_json);
    const auto& tile = event.at("tile");
    ASSERT_TRUE(tile.is_object()) << part->event_json.substr(0, 200);
    EXPECT_GT(tile.at("width_px").get<int>(), 5);
    EXPECT_GT(tile.at("height_px").get<int>(), 5);
    EXPECT_GT(tile.at("z_max_mm").get<double>(), 1.0);
    EXPECT_GE(tile.at("top_px").get<double>(), 0.0);
    EXPECT_LE(tile.at("top_px").get<double>() + tile.at("height_px").get<int>(),
              status.at("belt").at("width_px").get<double>() + 1);
    // The tile holds the part's rows (a blob's tile is the whole blob).
    EXPECT_LE(tile.at("first_profile"), event.at("pose").at("first_profile"));
    EXPECT_GE(tile.at("last_profile"), event.at("pose").at("last_profile"));
    EXPECT_LT(tile.at("last_profile").get<int>() - tile.at("first_profile").get<int>(), 500);
  }
  web.stop();
}

}  // namespace
}  // namespace cosmos
