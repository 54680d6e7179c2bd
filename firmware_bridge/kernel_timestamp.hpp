#pragma once
// Kernel time stamps → integer time. V4L2 stamps a buffer with a struct timeval plus flags
// saying which clock and which instant (end of frame or start of exposure); a GPIO line event
// carries a struct timespec. The pipeline keeps integer µs (Profile::t_us) and ns (edges),
// converted exactly, so frames and encoder edges from the same CLOCK_MONOTONIC can be
// matched without rounding.
#include <sys/time.h>

#include <cstdint>
#include <ctime>

namespace cosmos {

constexpr std::int64_t timeval_to_us(std::int64_t seconds, std::int64_t microseconds) noexcept {
  return seconds * 1'000'000 + microseconds;
}
inline std::int64_t timeval_to_us(const timeval& t) noexcept {
  return timeval_to_us(t.tv_sec, t.tv_usec);
}

constexpr std::int64_t timespec_to_ns(std::int64_t seconds, std::int64_t nanoseconds) noexcept {
  return seconds * 1'000'000'000 + nanoseconds;
}
inline std::int64_t timespec_to_ns(const timespec& t) noexcept {
  return timespec_to_ns(t.tv_sec, t.tv_nsec);
}

timespec ns_to_timespec(std::int64_t t_ns) noexcept;

// CLOCK_MONOTONIC now, ns: the clock V4L2 buffers (TIMESTAMP_MONOTONIC) and GPIO line events
// (kernel ≥ 5.7) are stamped with.
std::int64_t monotonic_now_ns() noexcept;

enum class TimestampClock : std::uint8_t {
  kMonotonic,  // CLOCK_MONOTONIC: comparable with encoder edges
  kCopy,       // copied from an output buffer (memory-to-memory devices): not a capture time
  kUnknown,    // old drivers: cannot be matched with anything
};

struct FrameTimestamp {
  std::int64_t t_us = 0;
  TimestampClock clock = TimestampClock::kUnknown;
  bool start_of_exposure = false;  // else end of frame (the V4L2 default)
};

// v4l2_buffer.timestamp and .flags → the time stamp and what it means.
FrameTimestamp decode_v4l2_timestamp(const timeval& timestamp, std::uint32_t buffer_flags) noexcept;

}  // namespace cosmos
