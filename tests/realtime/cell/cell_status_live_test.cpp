// COSMOS_STATUS while the cell runs: a scanner source that loses frames, stalls past its
// watchdog and reports encoder and GPIO faults has every one of them counted on the status
// the publisher sends, FAULT with the reason while the stall lasts, and the loop goes on
// when frames come back. A profile on a grid no scanner has is counted as refused; a source
// that fails is FAULT with its reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include "realtime/cell/cell_runner.hpp"
#include "realtime/cell/cell_state_rule.hpp"
#include "realtime/lcm/memory_publisher.hpp"

namespace cosmos {
namespace {

// Keeps every status and says when one reported the camera stall.
class WatchingPublisher final : public Publisher {
 public:
  bool publish(const PartPose& pose) override { return memory.publish(pose); }
  bool publish(const Profile& profile) override { return memory.publish(profile); }
  bool publish(const CellStatus& status) override {
    if (status.state == CellState::kFault && status.state_text.rfind(kCameraStallReason, 0) == 0)
      saw_fault.store(true);
    return memory.publish(status);
  }

  MemoryPublisher memory;
  std::atomic<bool> saw_fault{false};
};

// Empty belt profiles; after `stall_after` of them the camera stalls (kTimeout) until the
// publisher has sent a FAULT status, then frames resume. Faults accumulate in its health.
class StallingSource final : public ScannerSource {
 public:
  StallingSource(const std::atomic<bool>& fault_published, int profiles, int stall_after)
      : fault_published_(fault_published), profiles_(profiles), stall_after_(stall_after) {}

  SourceStatus start() override { return SourceStatus::kOk; }
  void reserve(Profile& profile) const override { profile.reserve(kWidth); }
  SourceStatus next(Profile& out) noexcept override {
    if (emitted_ == stall_after_ && !fault_published_.load() && waited_ms_ < kMaxStallMs) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      ++waited_ms_;
      ++health_.camera_timeouts;
      return SourceStatus::kTimeout;
    }
    if (emitted_ == profiles_) return SourceStatus::kEndOfStream;
    out.seq = static_cast<std::uint64_t>(emitted_);
    out.encoder_ticks = 4 * emitted_;
    out.t_us = 400 * emitted_;
    out.x0_mm = -160.0;
    out.dx_mm = emitted_ == 5 ? 0.0 : 0.5;  // one profile no scanner could have sent
    out.resize(kWidth);
    if (emitted_ == 7) out.z_mm[kWidth / 2] = 50.0f;  // above a pitched loop's reach
    ++emitted_;
    return SourceStatus::kOk;
  }
  void stop() noexcept override {}
  double mm_per_profile() const override { return 0.4; }
  std::string_view last_error() const noexcept override { return {}; }
  SourceHealth health() const noexcept override { return health_; }

  SourceHealth health_{.profiles_lost = 3,
                       .encoder_errors = 2,
                       .encoder_reversals = 1,
                       .gpio_edges_lost = 4,
                       .photo_eye_bounces = 6};
  int waited_ms_ = 0;

 private:
  static constexpr std::size_t kWidth = 640;
  static constexpr int kMaxStallMs = 20'000;  // a hung publisher fails the test, not CI
  const std::atomic<bool>& fault_published_;
  int profiles_;
  int stall_after_;
  int emitted_ = 0;
};

TEST(CellStatusLive, SourceFaultsAreCountedLiveAndTheStallIsAFaultThatEnds) {
  WatchingPublisher publisher;
  StallingSource source(publisher.saw_fault, 40, 20);
  ScanLoopSettings pitched;
  pitched.conditioning.sheet_pitch_deg = 1.0;
  pitched.conditioning.max_height_mm = 20.0;
  ScanLoop loop(pitched);
  CellRunSettings settings;
  settings.paced = false;
  settings.publishing.status_period_s = 0.001;
  const CellRunSummary summary =
      run_cell(source, loop, PartRecognitionContext{}, publisher, settings);

  ASSERT_TRUE(publisher.saw_fault.load()) << "no FAULT status within the stall";
  EXPECT_LT(source.waited_ms_, 20'000);
  const std::vector<CellStatus>& statuses = publisher.memory.statuses;
  // The stall's FAULT names the stall first, then any total that grew with it
  // (cell_state_rule.hpp).
  const auto fault = std::find_if(statuses.begin(), statuses.end(), [](const CellStatus& s) {
    return s.state == CellState::kFault && s.state_text.rfind(kCameraStallReason, 0) == 0;
  });
  ASSERT_NE(fault, statuses.end());
  EXPECT_GE(fault->camera_timeouts, 1);  // counted while it lasts, not only at the end
  EXPECT_EQ(fault->gpio_edges_lost, 4);

  // The frames after the stall were processed, and the last status holds every total.
  const CellStatus& last = summary.last_status;
  EXPECT_EQ(last.state, CellState::kIdle);
  EXPECT_EQ(last.profiles_acquired, 40);
  EXPECT_EQ(last.profiles_refused, 1);
  EXPECT_EQ(last.samples_too_high, 2);  // the 0.5 mm sample is nearest to two 0.4 mm cells
  EXPECT_EQ(last.profiles_lost, 3);
  EXPECT_EQ(last.profiles_dropped, 3);
  EXPECT_EQ(last.camera_timeouts, source.waited_ms_);
  EXPECT_EQ(last.encoder_errors, 2);
  EXPECT_EQ(last.encoder_reversals, 1);
  EXPECT_EQ(last.gpio_edges_lost, 4);
  EXPECT_EQ(last.photo_eye_bounces, 6);
  EXPECT_EQ(last.parts_seen, 0);
  EXPECT_EQ(summary.profiles_dropped, 3);
  EXPECT_EQ(statuses.back().camera_timeouts, last.camera_timeouts);
}

// Fails at its first next() as a camera that went away does.
class FailingSource final : public ScannerSource {
 public:
  SourceStatus start() override { return SourceStatus::kOk; }
  void reserve(Profile& profile) const override { profile.reserve(8); }
  SourceStatus next(Profile&) noexcept override { return SourceStatus::kError; }
  void stop() noexcept override {}
  double mm_per_profile() const override { return 0.4; }
  std::string_view last_error() const noexcept override {
    return "/dev/video0: VIDIOC_DQBUF: No such device";
  }
  SourceHealth health() const noexcept override { return {}; }
};

TEST(CellStatusLive, ASourceFailureIsAFaultThatSaysWhy) {
  MemoryPublisher publisher;
  FailingSource source;
  ScanLoop loop(ScanLoopSettings{});
  CellRunSettings settings;
  settings.paced = false;
  const CellRunSummary summary =
      run_cell(source, loop, PartRecognitionContext{}, publisher, settings);
  EXPECT_EQ(summary.source_error, "/dev/video0: VIDIOC_DQBUF: No such device");
  EXPECT_EQ(summary.last_status.state, CellState::kFault);
  EXPECT_EQ(summary.last_status.state_text,
            "the scanner source failed: /dev/video0: VIDIOC_DQBUF: No such device");
}

}  // namespace
}  // namespace cosmos
