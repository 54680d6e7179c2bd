#include "firmware_bridge/frame_sequence_tracker.hpp"

#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <cstdint>
#include <vector>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos {
namespace {

std::vector<std::uint64_t> indices_of(FrameSequenceTracker& tracker,
                                      const std::vector<std::uint32_t>& sequences) {
  std::vector<std::uint64_t> indices;
  for (const std::uint32_t s : sequences) indices.push_back(tracker.on_frame(s).frame_index);
  return indices;
}

TEST(FrameSequenceTracker, ConsecutiveFramesDropNothing) {
  FrameSequenceTracker tracker;
  EXPECT_EQ(indices_of(tracker, {10, 11, 12, 13}), (std::vector<std::uint64_t>{0, 1, 2, 3}));
  EXPECT_EQ(tracker.dropped_frames(), 0u);
  EXPECT_EQ(tracker.frames(), 4u);
}

TEST(FrameSequenceTracker, GapsCountTheMissingFrames) {
  FrameSequenceTracker tracker;
  tracker.on_frame(0);
  EXPECT_EQ(tracker.on_frame(1).dropped_before, 0u);
  const FrameSequenceResult after_gap = tracker.on_frame(5);
  EXPECT_EQ(after_gap.dropped_before, 3u);
  EXPECT_EQ(after_gap.frame_index, 5u);  // the index keeps the gap visible downstream
  EXPECT_EQ(tracker.on_frame(7).dropped_before, 1u);
  EXPECT_EQ(tracker.dropped_frames(), 4u);
}

TEST(FrameSequenceTracker, ThirtyTwoBitWrapIsNotAGap) {
  FrameSequenceTracker tracker;
  EXPECT_EQ(indices_of(tracker, {0xfffffffeu, 0xffffffffu, 0u, 1u}),
            (std::vector<std::uint64_t>{0, 1, 2, 3}));
  EXPECT_EQ(tracker.dropped_frames(), 0u);
  EXPECT_EQ(tracker.on_frame(4).dropped_before, 2u);
  // A gap across the wrap: 0xfffffffd → 2 skips 0xfffffffe, 0xffffffff, 0, 1.
  FrameSequenceTracker across;
  across.on_frame(0xfffffffdu);
  EXPECT_EQ(across.on_frame(2).dropped_before, 4u);
  EXPECT_EQ(across.sequence_resets(), 0u);
}

TEST(FrameSequenceTracker, RestartAfterStreamOnTakesANewReference) {
  FrameSequenceTracker tracker;
  indices_of(tracker, {100, 101, 102});
  tracker.restart();
  EXPECT_EQ(indices_of(tracker, {0, 1}), (std::vector<std::uint64_t>{3, 4}));
  EXPECT_EQ(tracker.dropped_frames(), 0u);
  EXPECT_EQ(tracker.sequence_resets(), 0u);
}

TEST(FrameSequenceTracker, BackwardJumpMidStreamIsAResetNotFourBillionDrops) {
  FrameSequenceTracker tracker;
  indices_of(tracker, {500, 501});
  const FrameSequenceResult jumped = tracker.on_frame(3);
  EXPECT_TRUE(jumped.sequence_reset);
  EXPECT_EQ(jumped.dropped_before, 0u);
  EXPECT_EQ(jumped.frame_index, 2u);
  EXPECT_EQ(tracker.on_frame(4).frame_index, 3u);
  EXPECT_EQ(tracker.on_frame(4).sequence_reset, true);  // a repeated number, too
  EXPECT_EQ(tracker.dropped_frames(), 0u);
  EXPECT_EQ(tracker.sequence_resets(), 2u);
}

TEST(KernelTimestamp, TimevalAndTimespecConvertExactly) {
  EXPECT_EQ(timeval_to_us(timeval{1, 500'000}), 1'500'000);
  EXPECT_EQ(timeval_to_us(timeval{86'400 * 365, 999'999}), 31'536'000'999'999);
  EXPECT_EQ(timespec_to_ns(timespec{3, 7}), 3'000'000'007);
  const timespec back = ns_to_timespec(12'345'678'901);
  EXPECT_EQ(back.tv_sec, 12);
  EXPECT_EQ(back.tv_nsec, 345'678'901);
}

TEST(KernelTimestamp, BufferFlagsSayWhichClockAndInstant) {
  const timeval t{2, 250};
  const FrameTimestamp monotonic_eof = decode_v4l2_timestamp(t, V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC);
  EXPECT_EQ(monotonic_eof.t_us, 2'000'250);
  EXPECT_EQ(monotonic_eof.clock, TimestampClock::kMonotonic);
  EXPECT_FALSE(monotonic_eof.start_of_exposure);
  const FrameTimestamp soe = decode_v4l2_timestamp(
      t, V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_SOE | V4L2_BUF_FLAG_DONE);
  EXPECT_TRUE(soe.start_of_exposure);
  EXPECT_EQ(decode_v4l2_timestamp(t, 0).clock, TimestampClock::kUnknown);
  EXPECT_EQ(decode_v4l2_timestamp(t, V4L2_BUF_FLAG_TIMESTAMP_COPY).clock, TimestampClock::kCopy);
}

}  // namespace
}  // namespace cosmos
