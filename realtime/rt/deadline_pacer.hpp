#pragma once
// Paces a loop at a fixed period with absolute deadlines on CLOCK_MONOTONIC
// (clock_nanosleep with TIMER_ABSTIME): period k starts at start + k * period whatever the
// work and wake-up delays of earlier periods, so delays never accumulate into drift.
//
// Overrun policy: when wait_next() is called at or after the deadline it would wait for, the
// previous period's work ran long. The pacer does not sleep, counts one overrun, and starts
// this period (the one whose deadline passed first) at once, its lateness being how late the
// work made it; later deadlines that had also passed by then are skipped (counted in
// skipped_periods) and the next deadline is the first one of the original grid after now.
// Skipping keeps the phase (deadlines stay on the grid) and never bursts to catch up, which
// would feed an overload with more work; a source that must account for every period (e.g. an
// encoder position) reads PacerTick::skipped_periods. An overloaded cell drops and counts
// work rather than stall: a late profile is worth less than the next one on time.
//
// Lateness (start time minus deadline) of every paced period, overruns included, goes into a
// LatencyHistogram: the jitter of the loop's start times. Period 0 is the unpaced mode for
// tests and batch runs: wait_next() never sleeps, never overruns and records nothing.
#include <cstdint>

// monotonic_now_ns(): CLOCK_MONOTONIC in ns, the clock of every deadline and of the frame and
// encoder time stamps, so pacing and acquisition times compare directly.
#include "firmware_bridge/kernel_timestamp.hpp"
#include "realtime/rt/latency_histogram.hpp"

namespace cosmos {

struct PacerTick {
  std::int64_t period_index = 0;  // counts grid periods from start(), skipped ones included
  std::int64_t deadline_ns = 0;   // when this period was due (monotonic clock)
  std::int64_t start_ns = 0;      // when wait_next() returned
  std::int64_t lateness_ns = 0;   // start - deadline, >= 0
  // On an overrun: the later deadlines that had passed by start_ns too, dropped; the next
  // period_index is period_index + 1 + skipped_periods.
  std::int64_t skipped_periods = 0;
  bool overrun = false;  // the previous work ran past this period's deadline
};

class DeadlinePacer {
 public:
  // period_ns > 0 paces; 0 is unpaced. Negative periods count as 0.
  explicit DeadlinePacer(std::int64_t period_ns);

  // The first deadline is start_ns itself: the first wait_next() returns at once and is never
  // an overrun (no work preceded it).
  void start(std::int64_t start_ns) noexcept;
  void start() noexcept { start(monotonic_now_ns()); }

  // Sleeps until the next deadline (not when already past it) and reports the period. Without
  // an earlier start(), the first call starts the pacer at the current time.
  PacerTick wait_next() noexcept;

  std::int64_t period_ns() const noexcept { return period_ns_; }
  bool paced() const noexcept { return period_ns_ > 0; }
  std::int64_t overruns() const noexcept { return overruns_; }
  std::int64_t skipped_periods() const noexcept { return skipped_periods_; }
  std::int64_t next_deadline_ns() const noexcept { return next_deadline_ns_; }
  const LatencyHistogram& lateness() const noexcept { return lateness_; }
  // Clears the counters and the histogram (e.g. after each status report); the phase stays.
  void reset_statistics() noexcept;

 private:
  std::int64_t period_ns_;
  bool started_ = false;
  std::int64_t next_deadline_ns_ = 0;
  std::int64_t next_period_index_ = 0;
  std::int64_t overruns_ = 0;
  std::int64_t skipped_periods_ = 0;
  LatencyHistogram lateness_;
};

}  // namespace cosmos
