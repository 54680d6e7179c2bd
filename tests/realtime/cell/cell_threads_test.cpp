// The cell's three threads (acquisition, recognizer, publisher) on a synthetic belt of domes,
// no simulator: every part the tracker completes is published as exactly one pose, paced at
// the line rate and unpaced with a slow recognizer, and the threads hand the profiles and
// poses over without losing one. Linked without the simulator, this is the test the
// ThreadSanitizer suite runs on the cell (scripts/check_sanitizers.sh).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>

#include "core/io/model_base_file.hpp"
#include "core/recognition/recognizer.hpp"
#include "realtime/cell/cell_runner.hpp"
#include "realtime/lcm/memory_publisher.hpp"
#include "realtime/rt/helper_threads.hpp"
#include "tests/regression_model_base.hpp"

namespace cosmos {
namespace {

// `parts` domes 12 mm high and 40 mm across, 100 profiles long, 250 profiles apart, on the
// default scanner's grid (640 samples 0.4 mm apart), then bare belt to let the last one end.
class DomeBeltSource final : public ScannerSource {
 public:
  explicit DomeBeltSource(int parts) : profiles_(parts * kPitch + kPitch) {}

  SourceStatus start() override { return SourceStatus::kOk; }
  void reserve(Profile& profile) const override { profile.reserve(kSamples); }
  SourceStatus next(Profile& out) noexcept override {
    if (emitted_ == profiles_) return SourceStatus::kEndOfStream;
    out.seq = static_cast<std::uint64_t>(emitted_);
    out.encoder_ticks = 4 * emitted_;
    out.t_us = 400 * emitted_;
    out.x0_mm = -127.8;
    out.dx_mm = 0.4;
    out.resize(kSamples);
    const int along = emitted_ % kPitch - kPitch / 2;  // rows from the dome's middle
    const double y = along / 50.0;
    for (int i = 0; i < kSamples; ++i) {
      const double x = out.x_mm(static_cast<std::size_t>(i)) / 20.0;
      const double r2 = x * x + y * y;
      out.z_mm[static_cast<std::size_t>(i)] =
          emitted_ < profiles_ - kPitch && r2 < 1 ? static_cast<float>(2 + 10 * (1 - r2)) : 0.0f;
    }
    ++emitted_;
    return SourceStatus::kOk;
  }
  void stop() noexcept override {}
  double mm_per_profile() const override { return 0.4; }
  std::string_view last_error() const noexcept override { return {}; }
  SourceHealth health() const noexcept override { return {}; }

  int profiles() const { return profiles_; }

 private:
  static constexpr int kSamples = 640;
  static constexpr int kPitch = 250;
  int profiles_;
  int emitted_ = 0;
};

class CellThreads : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    base_ = std::make_unique<ModelBase>(read_model_base(testing::regression_model_base()));
    // The search cut short: what is tested is the hand-over between the threads, and the
    // sanitizers' builds run the recognizer many times slower.
    RecognitionParameters search;
    search.in_plane_hypotheses = search.registered_hypotheses = 1;
    search.coarse_registration_iterations = 2;
    search.fine_registration_iterations = 1;
    search.searched_parts = 0;
    // The cell's helpers, so that a recognition's first views are verified on two threads.
    helpers_ = std::make_unique<HelperThreads>(CellThreadSettings{}.recognition_helpers);
    recognizer_ = std::make_unique<Recognizer>(*base_, CosmosParameters{}, search, helpers_.get());
  }
  static void TearDownTestSuite() {
    recognizer_.reset();
    helpers_.reset();
    base_.reset();
  }

  static PartRecognitionContext context(const ScanLoop& loop) {
    PartRecognitionContext context;
    context.recognizer = recognizer_.get();
    context.model_base = base_.get();
    context.catalog_index_of_base_part.assign(base_->parts.size(), -1);
    context.x0_loop_mm = loop.x0_loop_mm();
    return context;
  }

  // Each part seen has one pose, and no pose stands for a part not seen.
  static void expect_one_pose_per_part(const CellRunSummary& summary,
                                       const MemoryPublisher& publisher, int parts) {
    EXPECT_EQ(summary.parts_seen, parts);
    EXPECT_EQ(summary.poses_published, parts);
    ASSERT_EQ(publisher.poses.size(), static_cast<std::size_t>(parts));
    std::set<std::int64_t> seqs;
    for (const PartPose& pose : publisher.poses) seqs.insert(pose.part_seq);
    EXPECT_EQ(seqs.size(), static_cast<std::size_t>(parts));
    EXPECT_EQ(*seqs.begin(), 0);
    EXPECT_EQ(*seqs.rbegin(), parts - 1);
    ASSERT_FALSE(publisher.statuses.empty());
    EXPECT_EQ(publisher.statuses.back().parts_seen, parts);
  }

  static inline std::unique_ptr<ModelBase> base_;
  static inline std::unique_ptr<HelperThreads> helpers_;
  static inline std::unique_ptr<Recognizer> recognizer_;
};

TEST_F(CellThreads, UnpacedWithASlowRecognizerEveryPartIsPublishedOnce) {
  DomeBeltSource source(4);
  ScanLoopSettings loop_settings;
  loop_settings.wait_for_recognizer = true;
  ScanLoop loop(loop_settings);
  MemoryPublisher publisher;
  CellRunSettings settings;
  settings.paced = false;
  settings.recognizer_delay_ms = 20;
  settings.publishing.publish_profiles = true;
  settings.publishing.status_period_s = 0.01;
  settings.threads.profile_ring_slots = 16;  // the acquisition waits for the publisher
  const CellRunSummary summary = run_cell(source, loop, context(loop), publisher, settings);
  EXPECT_EQ(summary.profiles, source.profiles());
  EXPECT_EQ(summary.profiles_dropped, 0);
  EXPECT_EQ(static_cast<int>(publisher.profiles.size()), source.profiles());
  EXPECT_EQ(summary.parts_dropped, 0);
  expect_one_pose_per_part(summary, publisher, 4);
}

TEST_F(CellThreads, PacedEveryPartIsPublishedOnceDroppedOrNot) {
  DomeBeltSource source(3);
  ScanLoop loop(ScanLoopSettings{});
  MemoryPublisher publisher;
  CellRunSettings settings;
  settings.paced = true;
  settings.publishing.status_period_s = 0.01;
  const CellRunSummary summary = run_cell(source, loop, context(loop), publisher, settings);
  EXPECT_EQ(summary.profiles, source.profiles());
  expect_one_pose_per_part(summary, publisher, 3);
}

}  // namespace
}  // namespace cosmos
