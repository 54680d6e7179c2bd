// The twins' belt clock: frame k at the simulated source's t_us, frame k's tick exactly at
// its time, the ticks between frames evenly spaced and strictly increasing even when the
// line rate does not divide a second.
#include "sim/twins/simulated_belt_clock.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace cosmos {
namespace {

TEST(SimulatedBeltClock, FramesAndTicksShareOneTimeLine) {
  const ScannerParameters parameters;
  SimulatedBeltClock clock(parameters);
  EXPECT_EQ(clock.frame(), 0);
  EXPECT_EQ(clock.now_ns(), 0);
  EXPECT_EQ(clock.frame_time_ns(3), 1'200'000);
  EXPECT_EQ(clock.tick_time_ns(13), 1'300'000);  // 0.1 mm of belt at 1 m/s
  clock.advance_to_frame(250);
  EXPECT_EQ(clock.ticks_now(), 1000);
  EXPECT_EQ(clock.now_ns(), 100'000'000);
  EXPECT_EQ(clock.tick_time_ns(clock.ticks_now()), clock.now_ns());
  clock.rewind();
  EXPECT_EQ(clock.frame(), 0);
}

TEST(SimulatedBeltClock, OddLineRatesKeepTicksOnFramesAndInOrder) {
  ScannerParameters parameters;
  parameters.line_rate_hz = 2999.0;
  parameters.encoder_ticks_per_profile = 3;
  SimulatedBeltClock clock(parameters);
  for (std::int64_t k = 0; k < 5000; ++k) {
    ASSERT_EQ(clock.frame_time_ns(k), 1000 * parameters.time_us_of_profile(k));
    ASSERT_EQ(clock.tick_time_ns(clock.ticks_of_frame(k)), clock.frame_time_ns(k));
    for (std::int64_t tick = 3 * k; tick < 3 * k + 3; ++tick)
      ASSERT_LT(clock.tick_time_ns(tick), clock.tick_time_ns(tick + 1));
  }
  parameters.line_rate_hz = 0.0;
  EXPECT_THROW(SimulatedBeltClock{parameters}, std::invalid_argument);
}

}  // namespace
}  // namespace cosmos
