// A recorded stream with an encoder glitch inside one part and lost profiles inside another,
// replayed through the stream checker: both parts are published as ERROR with the reason
// (never as an OK pose at y = -100 km, or one assembled from rows with a hole), the glitch
// and the gap are counted, and the part the faults missed keeps its pose bit for bit.
// A part's view cut out of its builder is segmented from the seeds the builder found row by
// row, into the CSMPs a search of the view itself gives.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
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

struct Replayed {
  std::vector<PartRecognition> parts;
  CellStatus status;
};

Replayed replay(const std::vector<Profile>& profiles, const Recognizer& recognizer,
                const ModelBase& base) {
  const fs::path log_path = fs::temp_directory_path() /
                            ("cosmos-replayed-faults-" + std::to_string(::getpid()) + ".lcmlog");
  write_profile_log(log_path, profiles);
  StreamCheckedSource source(std::make_unique<ReplaySource>(log_path),
                             ScannerParameters{}.encoder_ticks_per_profile);
  Replayed replayed;
  EXPECT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
  ScanLoopSettings loop_settings;
  loop_settings.wait_for_recognizer = true;
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
  MemoryPublisher publisher;
  const CellRunSummary summary =
      run_cell(source, loop, context, publisher, settings,
               [&](const PartRecognition& recognition) { replayed.parts.push_back(recognition); });
  EXPECT_TRUE(summary.source_error.empty()) << summary.source_error;
  replayed.status = summary.last_status;
  fs::remove(log_path);
  return replayed;
}

TEST(PartRecognition, APartSpanningAReplayedGlitchOrGapIsAnErrorNotAPose) {
  const ModelBase base = read_model_base(testing::regression_model_base());
  const Recognizer recognizer(base, CosmosParameters{}, RecognitionParameters{});
  const PartCatalog catalog =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
  SimulatedSourceSettings settings;
  settings.parts = 3;
  settings.seed = 13;
  SimulatedSource simulated(catalog, ScannerParameters{}, settings);
  ASSERT_EQ(simulated.start(), SourceStatus::kOk);
  std::vector<Profile> profiles;
  Profile slot;
  simulated.reserve(slot);
  while (simulated.next(slot) == SourceStatus::kOk) profiles.push_back(slot);

  const Replayed clean = replay(profiles, recognizer, base);
  ASSERT_EQ(clean.parts.size(), 3u);
  for (const PartRecognition& part : clean.parts)
    ASSERT_EQ(part.pose.status, PoseStatus::kOk) << part.pose.part_name << ": " << part.pose.reason;

  // Part 1's middle row reads 10^9 ticks low (100 km of belt); five rows of part 2 are lost.
  std::vector<Profile> faulty = profiles;
  const auto middle = [&](const PartRecognition& part) {
    return static_cast<std::size_t>((part.first_profile + part.last_profile) / 2);
  };
  faulty[middle(clean.parts[1])].encoder_ticks -= 1'000'000'000;
  const auto gap = faulty.begin() + static_cast<std::ptrdiff_t>(middle(clean.parts[2]));
  faulty.erase(gap, gap + 5);
  const Replayed replayed = replay(faulty, recognizer, base);

  ASSERT_EQ(replayed.parts.size(), 3u);
  EXPECT_EQ(replayed.parts[0].pose.status, PoseStatus::kOk);
  EXPECT_EQ(replayed.parts[0].pose.translation_cell_part_mm,
            clean.parts[0].pose.translation_cell_part_mm);
  EXPECT_EQ(replayed.parts[0].pose.score, clean.parts[0].pose.score);
  EXPECT_EQ(replayed.parts[1].pose.status, PoseStatus::kError);
  EXPECT_NE(replayed.parts[1].pose.reason.find("encoder jump"), std::string::npos)
      << replayed.parts[1].pose.reason;
  EXPECT_EQ(replayed.parts[2].pose.status, PoseStatus::kError);
  EXPECT_NE(replayed.parts[2].pose.reason.find("frames lost"), std::string::npos)
      << replayed.parts[2].pose.reason;
  EXPECT_EQ(replayed.status.encoder_errors, 2);  // into the glitch and out of it
  EXPECT_EQ(replayed.status.profiles_lost, 5);
  EXPECT_EQ(replayed.status.parts_recognized, 1);
  EXPECT_EQ(replayed.status.parts_rejected, 2);
}

struct ViewsSegmented {
  int views = 0;
  int from_rows = 0;  // segmented from the builder's seeds
  int different = 0;  // whose CSMPs differ from a search of the view
  int patches = 0;
};

// Eight simulated parts in pairs across the belt, `across_gap_mm` apart, through the scan
// loop; each completed part's view cut out and compared with segment_csmps of the view's own
// fields.
ViewsSegmented segment_views(std::uint64_t seed, double across_gap_mm) {
  SimulatedSourceSettings settings;
  settings.parts = 8;
  settings.seed = seed;
  settings.side_by_side = true;
  settings.across_gap_mm = across_gap_mm;
  const PartCatalog catalog =
      read_part_catalog(fs::path(COSMOS_SOURCE_DIR) / "config/parts-regression.yaml");
  SimulatedSource source(catalog, ScannerParameters{}, settings);
  EXPECT_EQ(source.start(), SourceStatus::kOk);
  ScanLoopSettings loop_settings;
  loop_settings.parts.speculative_recognition = false;
  ScanLoop loop(loop_settings);
  PartRecognitionContext context;
  context.x0_loop_mm = loop.x0_loop_mm();
  ViewsSegmented out;
  const auto drain = [&] {
    int index = -1;
    while (loop.completed().try_pop(index)) {
      PartBuilder& builder = loop.builder(index);
      builder.cosmos.finish();
      const PartView view = extract_part_view(builder.built(), context);
      const CsmpSegmentation searched =
          segment_csmps(view.analysis.frames, view.analysis.field, context.cosmos.segmentation);
      ++out.views;
      out.from_rows += view.seeds_from_rows ? 1 : 0;
      out.patches += searched.patch_count;
      out.different += searched.patch_count != view.analysis.segmentation.patch_count ||
                               searched.patch_of_pixel.values() !=
                                   view.analysis.segmentation.patch_of_pixel.values()
                           ? 1
                           : 0;
      loop.returned().try_push(index);
    }
  };
  Profile profile;
  source.reserve(profile);
  while (source.next(profile) == SourceStatus::kOk) {
    loop.process(profile);
    drain();
  }
  loop.flush();
  drain();
  return out;
}

TEST(PartRecognition, CatalogPartsSideBySideAreSegmentedFromTheirBuildersSeeds) {
  const ViewsSegmented segmented = segment_views(21, 12.0);
  EXPECT_EQ(segmented.views, 8);
  EXPECT_EQ(segmented.from_rows, 8);
  EXPECT_EQ(segmented.different, 0);
  EXPECT_GT(segmented.patches, 8 * 5);
}

TEST(PartRecognition, TouchingPartsTheTrackerMergedAreSegmentedFromTheirBuildersSeeds) {
  const ViewsSegmented segmented = segment_views(22, 0.0);
  EXPECT_GE(segmented.views, 4);
  EXPECT_EQ(segmented.from_rows, segmented.views);
  EXPECT_EQ(segmented.different, 0);
}

}  // namespace
}  // namespace cosmos
