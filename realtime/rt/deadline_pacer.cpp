#include "realtime/rt/deadline_pacer.hpp"

#include <time.h>

#include <algorithm>
#include <cerrno>

namespace cosmos {
namespace {

// Absolute sleep: a signal interrupting it just sleeps again towards the same deadline.
void sleep_until_ns(std::int64_t deadline_ns) noexcept {
  const timespec deadline = ns_to_timespec(deadline_ns);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) == EINTR) {
  }
}

}  // namespace

DeadlinePacer::DeadlinePacer(std::int64_t period_ns)
    : period_ns_(std::max<std::int64_t>(period_ns, 0)) {}

void DeadlinePacer::start(std::int64_t start_ns) noexcept {
  started_ = true;
  next_deadline_ns_ = start_ns;
  next_period_index_ = 0;
}

PacerTick DeadlinePacer::wait_next() noexcept {
  if (!started_) start();
  PacerTick tick;
  if (!paced()) {
    tick.period_index = next_period_index_++;
    tick.start_ns = monotonic_now_ns();
    tick.deadline_ns = tick.start_ns;
    return tick;
  }
  tick.period_index = next_period_index_;
  tick.deadline_ns = next_deadline_ns_;
  const std::int64_t now_ns = monotonic_now_ns();
  if (now_ns < next_deadline_ns_) {
    sleep_until_ns(next_deadline_ns_);
    tick.start_ns = monotonic_now_ns();
  } else {
    // Past the deadline: run now, and skip the grid points that also passed, so the next
    // deadline is the first one after now (see the header's policy). Before the first period
    // there was no work to overrun, only the time since start().
    tick.start_ns = now_ns;
    tick.overrun = next_period_index_ > 0;
    tick.skipped_periods = (now_ns - next_deadline_ns_) / period_ns_;
    if (tick.overrun) ++overruns_;
    skipped_periods_ += tick.skipped_periods;
  }
  tick.lateness_ns = std::max<std::int64_t>(tick.start_ns - tick.deadline_ns, 0);
  lateness_.record_ns(tick.lateness_ns);
  next_period_index_ += 1 + tick.skipped_periods;
  next_deadline_ns_ += (1 + tick.skipped_periods) * period_ns_;
  return tick;
}

void DeadlinePacer::reset_statistics() noexcept {
  overruns_ = 0;
  skipped_periods_ = 0;
  lateness_.reset();
}

}  // namespace cosmos
