// Parts close together or touching on the belt: the simulated cell over gaps from 40 mm down
// to 0 (touching end to end) and pairs side by side across the belt. No part passes
// unreported: poses plus rejections equal the parts placed; and parts a few millimetres apart
// are identified (the tracker's shadow geometry keeps them apart, scene-level recognition
// takes touching ones apart). A part its shadow cut into pieces is recognized from them all as
// one.
#include "realtime/cell/blob_recognition.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <set>
#include <sstream>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"
#include "tests/realtime/regression_recognizer.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class BlobRecognition : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { world_ = std::make_unique<testing::RegressionRecognizer>(); }
  static void TearDownTestSuite() { world_.reset(); }

  struct Outcome {
    std::size_t placed = 0;
    std::size_t reports = 0;  // poses and rejections published
    int identified = 0;       // OK, the true part (by position among the blob's parts)
    int wrong = 0;            // OK, another part
    int rejected = 0;         // REJECTED or ERROR, each with a reason
    int without_reason = 0;
    int repeated = 0;  // OK poses of a placed part that had one already
    std::string text;
  };

  static Outcome run(const SimulatedSourceSettings& settings) {
    SimulatedSource source(world_->catalog, ScannerParameters{}, settings);
    EXPECT_EQ(source.start(), SourceStatus::kOk);
    ScanLoopSettings loop_settings;
    loop_settings.wait_for_recognizer = true;
    ScanLoop loop(loop_settings);
    PartRecognitionContext context;
    context.recognizer = &world_->recognizer;
    context.model_base = &world_->base;
    context.catalog_index_of_base_part.assign(world_->base.parts.size(), -1);
    context.mm_per_tick = ScannerParameters{}.encoder_mm_per_tick;
    context.x0_loop_mm = loop.x0_loop_mm();
    MemoryPublisher publisher;
    CellRunSettings run_settings;
    run_settings.paced = false;
    std::vector<PartRecognition> recognitions;
    run_cell(source, loop, context, publisher, run_settings,
             [&](const PartRecognition& recognition) { recognitions.push_back(recognition); });
    Outcome outcome;
    outcome.placed = source.placed_parts().size();
    outcome.reports = publisher.poses.size();
    std::ostringstream text;
    std::set<const PlacedSimPart*> posed;
    for (const PartRecognition& recognition : recognitions) {
      const PartPose& pose = recognition.pose;
      const RigidTransform T_belt_part =
          belt_pose_of(pose, RigidTransform::identity(), context.mm_per_tick);
      const PlacedSimPart* truth = source.conveyor().placed_part_at(
          T_belt_part.translation_mm, recognition.first_profile, recognition.last_profile);
      text << " [" << to_string(pose.status) << " " << pose.part_name << " truth "
           << (truth ? truth->name : "-") << " " << pose.reason << "]";
      if (pose.status != PoseStatus::kOk) {
        ++outcome.rejected;
        outcome.without_reason += pose.reason.empty() ? 1 : 0;
      } else if (truth && pose.part_name == truth->name) {
        ++outcome.identified;
        outcome.repeated += posed.insert(truth).second ? 0 : 1;
      } else {
        ++outcome.wrong;
      }
    }
    outcome.text = text.str();
    return outcome;
  }

  static SimulatedSourceSettings settings(int parts, double gap_mm, std::uint64_t seed) {
    SimulatedSourceSettings settings;
    settings.parts = parts;
    settings.part_gap_mm = gap_mm;
    settings.seed = seed;
    return settings;
  }

  static inline std::unique_ptr<testing::RegressionRecognizer> world_;
};

TEST_F(BlobRecognition, EveryPlacedPartIsReportedAtEveryGap) {
  for (const double gap_mm : {0.0, 2.0, 5.0, 10.0, 20.0, 30.0, 40.0}) {
    const Outcome outcome = run(settings(4, gap_mm, 7));
    EXPECT_EQ(outcome.reports, outcome.placed) << "gap " << gap_mm << " mm:" << outcome.text;
    EXPECT_EQ(outcome.without_reason, 0) << "gap " << gap_mm << " mm:" << outcome.text;
  }
}

TEST_F(BlobRecognition, PartsAFewMillimetresApartAreIdentified) {
  SimulatedSourceSettings spaced = settings(8, 5.0, 11);
  spaced.part_gap_max_mm = 30.0;
  const Outcome outcome = run(spaced);
  EXPECT_EQ(outcome.reports, outcome.placed) << outcome.text;
  EXPECT_GE(outcome.identified, 7) << outcome.text;
  EXPECT_EQ(outcome.wrong, 0) << outcome.text;
}

TEST_F(BlobRecognition, PairsTouchingSideBySideAreTakenApart) {
  SimulatedSourceSettings pairs = settings(4, 40.0, 14);
  pairs.side_by_side = true;
  const Outcome outcome = run(pairs);
  EXPECT_EQ(outcome.reports, outcome.placed) << outcome.text;
  EXPECT_GE(outcome.identified, 3) << outcome.text;
  EXPECT_EQ(outcome.wrong, 0) << outcome.text;
}

TEST_F(BlobRecognition, EveryPartOfSideBySidePairsIsReportedOnce) {
  // Seeded scenes of four pairs: a part nearly hidden by its taller neighbour, a part whose
  // piece the tracker hands on with its neighbour's blob, a neighbour that joins a blob in
  // the very row the blob completes, surface a part leaves unexplained beside it.
  for (const std::uint64_t seed : {3u, 4u, 10u, 39u}) {
    SimulatedSourceSettings pairs = settings(8, 40.0, seed);
    pairs.side_by_side = true;
    const Outcome outcome = run(pairs);
    EXPECT_EQ(outcome.reports, outcome.placed) << "seed " << seed << ":" << outcome.text;
    EXPECT_EQ(outcome.identified, 8) << "seed " << seed << ":" << outcome.text;
    EXPECT_EQ(outcome.repeated, 0) << "seed " << seed << ":" << outcome.text;
  }
}

TEST_F(BlobRecognition, PartsTouchingEndToEndGetOnePoseEach) {
  // Groups of three touching end to end: what is left of a part once its explained surface
  // is taken away must not come out as the same part again.
  SimulatedSourceSettings groups = settings(12, 40.0, 11);
  groups.group_size = 3;
  const Outcome outcome = run(groups);
  EXPECT_EQ(outcome.repeated, 0) << outcome.text;
  EXPECT_GE(outcome.identified, 11) << outcome.text;
  EXPECT_EQ(outcome.wrong, 0) << outcome.text;
}

// One seeded part through a fresh loop, to its end: the builders of the blobs it came in, in
// the order they completed.
std::vector<int> scan_one_part(ScanLoop& loop, const testing::RegressionRecognizer& world,
                               std::uint64_t seed, std::string& name) {
  SimulatedSourceSettings one;
  one.parts = 1;
  one.seed = seed;
  SimulatedSource source(world.catalog, ScannerParameters{}, one);
  EXPECT_EQ(source.start(), SourceStatus::kOk);
  Profile profile;
  source.reserve(profile);
  SpeculativePart ahead;
  while (source.next(profile) == SourceStatus::kOk) {
    loop.process(profile);
    while (loop.speculative().try_pop(ahead)) loop.speculated().try_push(ahead.builder);
  }
  loop.flush();
  name = source.placed_parts().front().name;
  std::vector<int> blobs;
  for (int index = -1; loop.completed().try_pop(index);) blobs.push_back(index);
  return blobs;
}

TEST_F(BlobRecognition, APartItsShadowCutIntoPiecesIsRecognizedFromThemAllAsOne) {
  PartRecognitionContext context;
  context.recognizer = &world_->recognizer;
  context.model_base = &world_->base;
  context.catalog_index_of_base_part.assign(world_->base.parts.size(), -1);
  int groups = 0;
  for (std::uint64_t seed = 1; seed <= 40 && groups == 0; ++seed) {
    ScanLoop loop{ScanLoopSettings{}};
    std::string name;
    const std::vector<int> blobs = scan_one_part(loop, *world_, seed, name);
    if (blobs.size() < 2) continue;
    // The tracker kept the pieces apart, each linked softly to the one before.
    std::vector<PartBuilder*> pieces;
    for (const int blob : blobs) pieces.push_back(&loop.builder(blob));
    for (std::size_t k = 1; k < pieces.size(); ++k) {
      ASSERT_GE(pieces[k]->soft_link_of, 0) << "seed " << seed;
      ASSERT_TRUE(pieces[k - 1]->owns(pieces[k]->soft_link_of)) << "seed " << seed;
      ASSERT_TRUE(pieces[k - 1]->has_soft_successor) << "seed " << seed;
    }
    ++groups;
    const cosmos::BlobRecognition group = recognize_blob_group(pieces, context, 0);
    ASSERT_EQ(group.parts.size(), 1U) << "seed " << seed << " " << name;
    const PartRecognition& part = group.parts[0];
    EXPECT_EQ(part.pose.status, PoseStatus::kOk) << "seed " << seed << " " << part.pose.reason;
    EXPECT_EQ(part.pose.part_name, name) << "seed " << seed;
    // Its rows run over every piece's, and its pose holds at the last one's last row.
    EXPECT_EQ(part.first_profile, pieces.front()->first_profile) << "seed " << seed;
    EXPECT_EQ(part.pose.encoder_ticks, pieces.back()->built().last_data_encoder_ticks);
    // Its view holds every piece's pixels, and nothing else.
    std::size_t piece_pixels = 0;
    for (PartBuilder* piece : pieces)
      piece_pixels += extract_part_view(piece->built(), context).image.count_valid();
    EXPECT_EQ(group.image.count_valid(), piece_pixels) << "seed " << seed;
  }
  EXPECT_EQ(groups, 1) << "no part in 40 seeded scans came in pieces";
}

}  // namespace
}  // namespace cosmos
