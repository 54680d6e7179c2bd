// vivid's 8-bit frame numbers unwrapped with the capture's clock, across the long silences of
// a cell that holds every buffer while it starts.
#include "tests/hil/capture_ticks.hpp"

#include <gtest/gtest.h>

namespace cosmos::hil {
namespace {

constexpr double kPeriodNs = 1e9 / 30.0;

std::int64_t time_of(std::int64_t sequence, double late_frames = 0.0) {
  return 5'000'000'000 + static_cast<std::int64_t>((sequence + late_frames) * kPeriodNs);
}

TEST(UnwrapSequence, FindsTheNumberTheEightBitsAndTheClockAgreeOn) {
  const std::int64_t t0 = time_of(0);
  for (const std::int64_t sequence : {0, 1, 255, 256, 257, 1000, 4097, 123456}) {
    EXPECT_EQ(unwrap_sequence(sequence & 0xff, time_of(sequence), t0, kPeriodNs), sequence);
    // vivid's thread runs up to a jiffy (a fraction of a frame) or several frames late.
    EXPECT_EQ(unwrap_sequence(sequence & 0xff, time_of(sequence, 0.4), t0, kPeriodNs), sequence);
    EXPECT_EQ(unwrap_sequence(sequence & 0xff, time_of(sequence, 60.0), t0, kPeriodNs), sequence);
  }
}

TEST(UnwrapSequence, ClockEarlyByLessThanHalfTheWrapStillFinds) {
  const std::int64_t t0 = time_of(0);
  EXPECT_EQ(unwrap_sequence(300 & 0xff, time_of(300, -100.0), t0, kPeriodNs), 300);
  EXPECT_EQ(unwrap_sequence(300 & 0xff, time_of(300, 100.0), t0, kPeriodNs), 300);
}

}  // namespace
}  // namespace cosmos::hil
