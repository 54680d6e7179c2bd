// Absolute-deadline pacing: deadlines stay on the start + k * period grid, periods never start
// early, overruns are counted (and the missed grid points skipped) when the work outlasts the
// period, and the unpaced mode never sleeps. No assertion depends on how fast or how loaded
// the machine is: sleeps never end early, so forced overruns are certain, and where overruns
// may or may not happen (tiny work) only their bookkeeping is checked, never their number.
#include "realtime/rt/deadline_pacer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <thread>

namespace cosmos {
namespace {

constexpr std::int64_t kMillisecondNs = 1'000'000;

TEST(DeadlinePacer, TinyWorkKeepsThePeriodOnTheGrid) {
  DeadlinePacer pacer(kMillisecondNs);
  const std::int64_t start_ns = monotonic_now_ns();
  pacer.start(start_ns);
  std::int64_t previous_index = -1, last_skipped = 0;
  std::int64_t overrun_ticks = 0, skipped_on_overruns = 0;
  volatile std::int64_t work = 0;
  for (int k = 0; k < 50; ++k) {
    const PacerTick tick = pacer.wait_next();
    overrun_ticks += tick.overrun ? 1 : 0;
    skipped_on_overruns += tick.skipped_periods;
    last_skipped = tick.skipped_periods;
    // The first tick may skip periods without an overrun: the time since start() passed
    // them, with no work to overrun (a descheduled test on a loaded machine).
    if (!tick.overrun && k > 0) {
      EXPECT_EQ(tick.skipped_periods, 0);
    }
    EXPECT_GT(tick.period_index, previous_index);
    previous_index = tick.period_index;
    EXPECT_EQ(tick.deadline_ns, start_ns + tick.period_index * kMillisecondNs);
    EXPECT_GE(tick.start_ns, tick.deadline_ns);  // absolute sleeps never return early
    EXPECT_EQ(tick.lateness_ns, tick.start_ns - tick.deadline_ns);
    for (int i = 0; i < 1000; ++i) work = work + i;
  }
  // However many overruns a loaded machine causes, each is counted once, with its skips.
  EXPECT_EQ(pacer.overruns(), overrun_ticks);
  EXPECT_EQ(pacer.skipped_periods(), skipped_on_overruns);
  // A tick runs at its own period; the periods it skips move the ticks after it.
  EXPECT_EQ(previous_index, 49 + pacer.skipped_periods() - last_skipped);
  EXPECT_EQ(pacer.lateness().count(), 50);
  EXPECT_GE(pacer.lateness().min_ns(), 0);
  // Whole run: at least the 49 periods after the first.
  EXPECT_GE(monotonic_now_ns() - start_ns, 49 * kMillisecondNs);
}

TEST(DeadlinePacer, WorkLongerThanThePeriodCountsOverrunsAndSkipsMissedPeriods) {
  DeadlinePacer pacer(kMillisecondNs);
  const std::int64_t start_ns = monotonic_now_ns();
  pacer.start(start_ns);
  constexpr int kPeriods = 10;
  int overrun_ticks = 0;
  for (int k = 0; k < kPeriods; ++k) {
    const PacerTick tick = pacer.wait_next();
    if (k == 0) {
      EXPECT_FALSE(tick.overrun);  // nothing ran before the first period
    } else {
      // 3 ms of work after a deadline at most 1 ms after the previous start: this deadline
      // passed at least 2 ms ago, with at least 2 further grid points.
      EXPECT_TRUE(tick.overrun);
      EXPECT_GE(tick.lateness_ns, 2 * kMillisecondNs);
      EXPECT_GE(tick.skipped_periods, 2);
    }
    overrun_ticks += tick.overrun ? 1 : 0;
    EXPECT_EQ(tick.deadline_ns, start_ns + tick.period_index * kMillisecondNs);
    // The phase is kept: the next deadline is on the grid and still ahead.
    EXPECT_EQ((pacer.next_deadline_ns() - start_ns) % kMillisecondNs, 0);
    EXPECT_GT(pacer.next_deadline_ns(), tick.start_ns);
    std::this_thread::sleep_for(std::chrono::milliseconds(3));
  }
  EXPECT_EQ(overrun_ticks, kPeriods - 1);
  EXPECT_EQ(pacer.overruns(), kPeriods - 1);
  EXPECT_GE(pacer.skipped_periods(), 2 * (kPeriods - 1));
  EXPECT_EQ(pacer.lateness().count(), kPeriods);
  EXPECT_GE(pacer.lateness().p50_ns(), 2 * kMillisecondNs * 255 / 256);  // bucket midpoint

  pacer.reset_statistics();
  EXPECT_EQ(pacer.overruns(), 0);
  EXPECT_EQ(pacer.skipped_periods(), 0);
  EXPECT_EQ(pacer.lateness().count(), 0);
}

TEST(DeadlinePacer, UnpacedNeverSleepsOrOverruns) {
  DeadlinePacer pacer(0);
  EXPECT_FALSE(pacer.paced());
  pacer.start();
  std::int64_t previous_start_ns = 0;
  for (int k = 0; k < 1000; ++k) {
    const PacerTick tick = pacer.wait_next();
    EXPECT_EQ(tick.period_index, k);
    EXPECT_FALSE(tick.overrun);
    EXPECT_EQ(tick.lateness_ns, 0);
    EXPECT_GE(tick.start_ns, previous_start_ns);
    previous_start_ns = tick.start_ns;
  }
  EXPECT_EQ(pacer.overruns(), 0);
  EXPECT_EQ(pacer.lateness().count(), 0);
  EXPECT_EQ(DeadlinePacer(-5).period_ns(), 0);
}

TEST(DeadlinePacer, FirstWaitWithoutStartBeginsNow) {
  DeadlinePacer pacer(kMillisecondNs);
  const std::int64_t before_ns = monotonic_now_ns();
  const PacerTick first = pacer.wait_next();
  EXPECT_EQ(first.period_index, 0);
  EXPECT_FALSE(first.overrun);
  EXPECT_GE(first.deadline_ns, before_ns);
  const PacerTick second = pacer.wait_next();
  EXPECT_EQ(second.deadline_ns, first.deadline_ns + kMillisecondNs);
  EXPECT_GE(second.start_ns, second.deadline_ns);
}

}  // namespace
}  // namespace cosmos
