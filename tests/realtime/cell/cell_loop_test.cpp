// The simulated cell's loop in process: catalog parts on the simulated conveyor → the
// real-time loop (conditioning, tracking, incremental COSMOS) → the recognizer worker →
// poses over LCM (memq://), checked against the simulator's ground truth. The stream replayed from
// an LCM log with the worker slowed down gives byte-identical poses, equal to those of the live
// run, as are those of a part its shadow cut into pieces; and the acquisition thread's
// per-profile work allocates nothing after warm-up.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <memory>
#include <sstream>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "realtime/lcm/pose_publisher.hpp"
#include "realtime/lcm/profile_log_writer.hpp"
#include "realtime/sources/replay_source.hpp"
#include "sim/evaluation/add_s_distance.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_source.hpp"
#include "tests/common/allocation_counter.hpp"
#include "tests/realtime/regression_recognizer.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

namespace fs = std::filesystem;

class CellLoop : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { world_ = std::make_unique<testing::RegressionRecognizer>(); }
  static void TearDownTestSuite() { world_.reset(); }

  static SimulatedSourceSettings sim_settings(int parts, std::uint64_t seed) {
    SimulatedSourceSettings settings;
    settings.parts = parts;
    settings.seed = seed;
    return settings;
  }

  static ScanLoopSettings loop_settings() {
    ScanLoopSettings settings;
    settings.wait_for_recognizer = true;  // unpaced: every part is recognized
    return settings;
  }

  static PartRecognitionContext context(const ScanLoop& loop) {
    PartRecognitionContext context;
    context.recognizer = &world_->recognizer;
    context.model_base = &world_->base;
    for (const ModelPart& part : world_->base.parts) {
      int index = -1;
      for (std::size_t c = 0; c < world_->catalog.parts.size(); ++c)
        if (world_->catalog.parts[c].name == part.name) index = static_cast<int>(c);
      context.catalog_index_of_base_part.push_back(index);
    }
    context.mm_per_tick = ScannerParameters{}.encoder_mm_per_tick;
    context.x0_loop_mm = loop.x0_loop_mm();
    return context;
  }

  static CellRunSettings unpaced(bool deterministic) {
    CellRunSettings settings;
    settings.paced = false;
    settings.deterministic_output = deterministic;
    return settings;
  }

  static std::vector<std::uint8_t> pose_bytes(const PartPose& pose) {
    cosmos_lcm::part_pose_t message{};
    to_message(pose, message);
    std::vector<std::uint8_t> bytes;
    EXPECT_TRUE(encode_message(message, bytes));
    return bytes;
  }

  static inline std::unique_ptr<testing::RegressionRecognizer> world_;
};

TEST_F(CellLoop, ReplayedStreamGivesByteIdenticalPosesWithASlowWorker) {
  const fs::path log_path =
      fs::temp_directory_path() / ("cosmos-cell-replay-" + std::to_string(::getpid()) + ".lcmlog");
  MemoryPublisher live;
  {
    SimulatedSource source(world_->catalog, ScannerParameters{}, sim_settings(4, 21));
    ASSERT_EQ(source.start(), SourceStatus::kOk);
    ScanLoop loop(loop_settings());
    CellRunSettings settings = unpaced(true);
    settings.publishing.publish_profiles = true;
    settings.threads.profile_ring_slots = 8;  // a publisher far behind must still lose no profile
    const CellRunSummary summary = run_cell(source, loop, context(loop), live, settings);
    ASSERT_EQ(summary.profiles_dropped, 0);
    ASSERT_EQ(static_cast<std::int64_t>(live.profiles.size()), summary.profiles);
    ASSERT_NO_THROW(write_profile_log(log_path, live.profiles));
  }
  ASSERT_EQ(live.poses.size(), 4u);

  std::vector<std::vector<std::uint8_t>> runs[2];
  for (int run = 0; run < 2; ++run) {
    ReplaySource source(log_path);
    ASSERT_EQ(source.start(), SourceStatus::kOk) << source.last_error();
    ScanLoop loop(loop_settings());
    MemoryPublisher replayed;
    CellRunSettings settings = unpaced(true);
    settings.recognizer_delay_ms = run == 1 ? 250 : 0;
    run_cell(source, loop, context(loop), replayed, settings);
    for (const PartPose& pose : replayed.poses) runs[run].push_back(pose_bytes(pose));
  }
  fs::remove(log_path);
  ASSERT_EQ(runs[0].size(), 4u);
  EXPECT_EQ(runs[0], runs[1]);
  for (std::size_t i = 0; i < live.poses.size(); ++i)
    EXPECT_EQ(runs[0][i], pose_bytes(live.poses[i])) << "pose " << i;
}

TEST_F(CellLoop, APartItsShadowCutIntoPiecesGivesTheSamePoseWhateverTheWorkersTiming) {
  // Seed 67 places a part that comes in pieces, the first too small to be a part alone: the
  // pieces are one group, recognized once all have completed (or ahead of the last one's
  // completion), from the tracker's links alone, so a slow worker changes nothing.
  std::vector<std::vector<std::uint8_t>> runs[2];
  for (int run = 0; run < 2; ++run) {
    SimulatedSource source(world_->catalog, ScannerParameters{}, sim_settings(1, 67));
    ASSERT_EQ(source.start(), SourceStatus::kOk);
    ScanLoop loop(loop_settings());
    MemoryPublisher publisher;
    CellRunSettings settings = unpaced(true);
    settings.recognizer_delay_ms = run == 1 ? 250 : 0;
    const CellRunSummary summary = run_cell(source, loop, context(loop), publisher, settings);
    EXPECT_EQ(summary.blob_groups_recognized, 1) << "run " << run;
    ASSERT_EQ(publisher.poses.size(), 1u) << "run " << run;
    EXPECT_EQ(publisher.poses[0].status, PoseStatus::kOk) << publisher.poses[0].reason;
    EXPECT_EQ(publisher.poses[0].part_name, source.placed_parts().front().name);
    for (const PartPose& pose : publisher.poses) runs[run].push_back(pose_bytes(pose));
  }
  EXPECT_EQ(runs[0], runs[1]);
}

// Collects what arrives on the cell's channels of an in-process memq:// LCM.
struct MemqSubscriber {
  std::vector<PartPose> poses;
  std::vector<CellStatus> statuses;
  void on_pose(const lcm::ReceiveBuffer* buffer, const std::string&,
               const cosmos_lcm::part_pose_t* message) {
    (void)buffer;
    poses.emplace_back();
    from_message(*message, poses.back());
  }
  void on_status(const lcm::ReceiveBuffer* buffer, const std::string&,
                 const cosmos_lcm::cell_status_t* message) {
    (void)buffer;
    statuses.emplace_back();
    from_message(*message, statuses.back());
  }
};

RigidPose rigid(const RigidTransform& T) { return {T.rotation, T.translation_mm}; }

TEST_F(CellLoop, TwentySimulatedPartsArrivePublishedOverLcmWithTheirTruePoses) {
  SimulatedSource source(world_->catalog, ScannerParameters{}, sim_settings(20, 7));
  ASSERT_EQ(source.start(), SourceStatus::kOk);
  LcmPublisher publisher("memq://");
  MemqSubscriber received;
  publisher.lcm().subscribe(kPoseChannel, &MemqSubscriber::on_pose, &received);
  publisher.lcm().subscribe(kStatusChannel, &MemqSubscriber::on_status, &received);
  ScanLoop loop(loop_settings());
  const CellRunSummary summary = run_cell(source, loop, context(loop), publisher, unpaced(false));
  while (publisher.lcm().handleTimeout(0) > 0) {
  }
  EXPECT_EQ(summary.parts_seen, 20);
  EXPECT_EQ(summary.parts_dropped, 0);
  ASSERT_EQ(received.poses.size(), 20u);
  ASSERT_FALSE(received.statuses.empty());
  EXPECT_EQ(received.statuses.back().parts_seen, 20);

  std::map<std::string, std::unique_ptr<AddSDistance>> add_s;
  std::map<std::string, double> diameter_mm;
  for (const ModelPart& part : world_->base.parts) {
    const PartEntry& entry = world_->catalog.at(part.name);
    const TriangleMesh mesh = load_mesh(entry.mesh_path, entry.size_mm);
    std::vector<Eigen::Vector3d> points_mm;
    for (const auto& vertex : mesh.vertices) points_mm.push_back(vertex.cast<double>());
    add_s[part.name] = std::make_unique<AddSDistance>(points_mm);
    diameter_mm[part.name] = part.diameter_mm;
  }
  int right = 0;
  std::ostringstream wrong;  // a miss is allowed: say which
  for (const PartPose& pose : received.poses) {
    ASSERT_GE(pose.part_seq, 0);
    ASSERT_LT(pose.part_seq, 20);
    const PlacedSimPart& truth = source.placed_parts()[static_cast<std::size_t>(pose.part_seq)];
    if (pose.status != PoseStatus::kOk || pose.part_name != truth.name) {
      wrong << "; part " << pose.part_seq << " (" << truth.name << "): " << to_string(pose.status)
            << " " << pose.part_name << " " << pose.reason;
      continue;
    }
    const RigidTransform T_belt_part =
        belt_pose_of(pose, RigidTransform::identity(), ScannerParameters{}.encoder_mm_per_tick);
    const RigidTransform T_true{truth.T_belt_part.rotation(), truth.T_belt_part.translation()};
    const double error_mm = add_s.at(truth.name)->add_s_mm(rigid(T_true), rigid(T_belt_part));
    if (error_mm < 0.1 * diameter_mm.at(truth.name)) {
      ++right;
    } else {
      wrong << "; part " << pose.part_seq << " (" << truth.name << "): ADD-S " << error_mm
            << " mm of diameter " << diameter_mm.at(truth.name) << " mm";
    }
  }
  EXPECT_GE(right, 19) << wrong.str();
  if (right < 20) std::cout << "the part missed" << wrong.str() << "\n";
}

TEST_F(CellLoop, ProcessingAProfileAllocatesNothingAfterWarmUp) {
  SimulatedSource source(world_->catalog, ScannerParameters{}, sim_settings(2, 3));
  ASSERT_EQ(source.start(), SourceStatus::kOk);
  ScanLoopSettings settings = loop_settings();
  settings.wait_for_recognizer = false;
  settings.parts.builders = 2;
  ScanLoop loop(settings);
  Profile profile;
  source.reserve(profile);
  // Warm-up: the first part passes, so every buffer has seen a part.
  const std::int64_t warm_up = source.placed_parts()[0].last_profile + 10;
  for (std::int64_t k = 0; k <= warm_up; ++k) {
    ASSERT_EQ(source.next(profile), SourceStatus::kOk);
    loop.process(profile);
  }
  // The recognizer's side, outside the count: builders given back, speculation declined.
  const auto answer = [&loop] {
    int returned = -1;
    while (loop.completed().try_pop(returned)) loop.returned().try_push(returned);
    SpeculativePart ahead;
    while (loop.speculative().try_pop(ahead)) loop.speculated().try_push(ahead.builder);
  };
  answer();
  std::uint64_t allocations = 0;
  std::int64_t processed = 0;
  while (source.next(profile) == SourceStatus::kOk) {
    const std::uint64_t before = test::allocations_on_this_thread();
    loop.process(profile);
    allocations += test::allocations_on_this_thread() - before;
    ++processed;
    answer();
  }
  EXPECT_GT(processed, 100);
  EXPECT_EQ(loop.counters().parts_seen, 2);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace cosmos
