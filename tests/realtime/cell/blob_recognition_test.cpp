// Parts close together or touching on the belt: the simulated cell over gaps from 40 mm down
// to 0 (touching end to end) and pairs side by side across the belt. No part passes
// unreported: poses plus rejections equal the parts placed; and parts a few millimetres apart
// are identified (the tracker's shadow geometry keeps them apart, scene-level recognition
// takes touching ones apart). A leading piece that its successor's part explains is not
// recognized on its own.
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

// One seeded part through a fresh loop, to its completion: the loop's builder index.
int scan_one_part(ScanLoop& loop, const testing::RegressionRecognizer& world, std::uint64_t seed) {
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
  int index = -1;
  EXPECT_TRUE(loop.completed().try_pop(index));
  return index;
}

TEST_F(BlobRecognition, ALeadingPieceThatItsSuccessorsPartExplainsIsNotRecognized) {
  PartRecognitionContext context;
  context.recognizer = &world_->recognizer;
  context.model_base = &world_->base;
  context.catalog_index_of_base_part.assign(world_->base.parts.size(), -1);
  ScanLoop first{ScanLoopSettings{}};
  const cosmos::BlobRecognition alone =
      recognize_blob(first.builder(scan_one_part(first, *world_, 5)), context, 0);
  ASSERT_EQ(alone.parts.size(), 1U);
  ASSERT_EQ(alone.parts[0].pose.status, PoseStatus::kOk) << alone.parts[0].pose.reason;
  const std::vector<PartInLoop> successor{
      {alone.parts[0].result.part, alone.parts[0].result.T_scanner_part}};
  const std::size_t points = alone.points_loop_mm.size();
  // The same surface as the successor's part placed there, and a larger successor: a piece.
  ScanLoop second{ScanLoopSettings{}};
  const cosmos::BlobRecognition piece = recognize_blob_unless_explained(
      second.builder(scan_one_part(second, *world_, 5)), context, successor, points + 1, 0);
  ASSERT_EQ(piece.parts.size(), 1U);
  EXPECT_EQ(piece.parts[0].pose.status, PoseStatus::kRejected);
  EXPECT_EQ(piece.parts[0].pose.reason, "a piece of the part after it");
  EXPECT_EQ(piece.points_loop_mm.size(), points);
  // A successor no larger than the piece: the piece is recognized as any blob.
  ScanLoop third{ScanLoopSettings{}};
  const cosmos::BlobRecognition larger = recognize_blob_unless_explained(
      third.builder(scan_one_part(third, *world_, 5)), context, successor, points, 0);
  ASSERT_EQ(larger.parts.size(), 1U);
  EXPECT_EQ(larger.parts[0].pose.status, PoseStatus::kOk);
  EXPECT_EQ(larger.parts[0].result.part, alone.parts[0].result.part);
  // Nor is a part another part does not explain taken for a piece of it.
  const std::vector<PartInLoop> elsewhere{
      {successor[0].part, RigidTransform{Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 500)} *
                              successor[0].T_loop_part}};
  ScanLoop fourth{ScanLoopSettings{}};
  const cosmos::BlobRecognition own = recognize_blob_unless_explained(
      fourth.builder(scan_one_part(fourth, *world_, 5)), context, elsewhere, points + 1, 0);
  ASSERT_EQ(own.parts.size(), 1U);
  EXPECT_EQ(own.parts[0].pose.status, PoseStatus::kOk);
}

}  // namespace
}  // namespace cosmos
