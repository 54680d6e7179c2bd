// Determinism under perturbation: one recorded stream replayed again and again through the
// cell with the threads' timing disturbed (a seeded random recognizer delay per replay,
// random sleeps in the publisher, a random number of part builders, so parts land in
// builders that held other parts before, and of recognizer workers, so parts are recognized
// at once and end in any order; speculative recognition on in every other replay, so a part
// is recognized before its completion or at it) gives the same part_pose_t bytes every time: a
// pose depends on the rows of its part and on nothing else (times come from the data).
//
// 20 replays here; COSMOS_DETERMINISM_REPLAYS=100 for the longer run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <random>
#include <thread>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "realtime/lcm/profile_log_writer.hpp"
#include "realtime/sources/replay_source.hpp"
#include "realtime/sources/stream_checked_source.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

// Keeps the poses' bytes; sleeps a seeded random while before each message.
class JitteryPublisher final : public Publisher {
 public:
  explicit JitteryPublisher(std::uint64_t seed) : random_(seed) {}
  bool publish(const PartPose& pose) override {
    jitter();
    cosmos_lcm::part_pose_t message{};
    to_message(pose, message);
    std::vector<std::uint8_t> bytes;
    EXPECT_TRUE(encode_message(message, bytes));
    poses.push_back(std::move(bytes));
    return true;
  }
  bool publish(const CellStatus&) override {
    jitter();
    return true;
  }
  bool publish(const Profile&) override { return true; }

  std::vector<std::vector<std::uint8_t>> poses;

 private:
  void jitter() { std::this_thread::sleep_for(std::chrono::microseconds(random_() % 400)); }
  std::mt19937_64 random_;
};

int replay_count() {
  const char* text = std::getenv("COSMOS_DETERMINISM_REPLAYS");
  return text ? std::max(1, std::atoi(text)) : 20;
}

TEST(ReplayDeterminism, EveryReplayGivesTheSamePoseBytesWhateverTheTiming) {
  const ModelBase base = read_model_base(testing::regression_model_base());
  const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});
  const PartCatalog catalog =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
  const fs::path log_path =
      fs::temp_directory_path() / ("cosmos-determinism-" + std::to_string(::getpid()) + ".lcmlog");
  {
    SimulatedSourceSettings settings;
    settings.parts = 3;
    settings.seed = 13;
    SimulatedSource source(catalog, ScannerParameters{}, settings);
    ASSERT_EQ(source.start(), SourceStatus::kOk);
    std::vector<Profile> profiles;
    Profile slot;
    source.reserve(slot);
    while (source.next(slot) == SourceStatus::kOk) profiles.push_back(slot);
    ASSERT_NO_THROW(write_profile_log(log_path, profiles));
  }

  std::mt19937_64 perturbation(2026);
  std::vector<std::vector<std::uint8_t>> first;
  std::int64_t ahead = 0;
  const int replays = replay_count();
  for (int replay = 0; replay < replays; ++replay) {
    SCOPED_TRACE(replay);
    StreamCheckedSource source(std::make_unique<ReplaySource>(log_path),
                               ScannerParameters{}.encoder_ticks_per_profile);
    ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
    ScanLoopSettings loop_settings;
    loop_settings.wait_for_recognizer = true;
    loop_settings.parts.builders = 1 + static_cast<int>(perturbation() % 4);
    loop_settings.parts.speculative_recognition = replay % 2 == 1;
    ScanLoop loop(loop_settings);
    PartRecognitionContext context;
    context.recognizer = &recognizer;
    context.model_base = &base;
    context.mm_per_tick = ScannerParameters{}.encoder_mm_per_tick;
    context.x0_loop_mm = loop.x0_loop_mm();
    context.stream_faults = &source.faults();
    CellRunSettings settings;
    settings.paced = false;
    settings.deterministic_output = true;
    settings.publishing.status_period_s = 0.002;
    settings.recognizer_delay_ms = static_cast<int>(perturbation() % 4);
    settings.threads.recognizer_threads = 1 + static_cast<int>(perturbation() % 3);
    JitteryPublisher publisher(perturbation());
    const CellRunSummary summary = run_cell(source, loop, context, publisher, settings);
    ASSERT_TRUE(summary.source_error.empty()) << summary.source_error;
    ahead += summary.blobs_recognized_ahead;
    if (replay == 0) {
      first = publisher.poses;
      ASSERT_EQ(first.size(), 3u);
      continue;
    }
    ASSERT_EQ(publisher.poses.size(), first.size());
    for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(publisher.poses[i], first[i]) << i;
  }
  // Both ways were taken: blobs recognized ahead of their completion gave the same bytes.
  EXPECT_GT(ahead, 0);
  fs::remove(log_path);
}

}  // namespace
}  // namespace cosmos
