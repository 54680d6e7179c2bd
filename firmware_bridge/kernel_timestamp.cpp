#include "firmware_bridge/kernel_timestamp.hpp"

#include <linux/videodev2.h>

namespace cosmos {

timespec ns_to_timespec(std::int64_t t_ns) noexcept {
  if (t_ns < 0) t_ns = 0;
  timespec t{};
  t.tv_sec = static_cast<time_t>(t_ns / 1'000'000'000);
  t.tv_nsec = static_cast<long>(t_ns % 1'000'000'000);
  return t;
}

std::int64_t monotonic_now_ns() noexcept {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return timespec_to_ns(now);
}

FrameTimestamp decode_v4l2_timestamp(const timeval& timestamp,
                                     std::uint32_t buffer_flags) noexcept {
  FrameTimestamp result;
  result.t_us = timeval_to_us(timestamp);
  switch (buffer_flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) {
    case V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC:
      result.clock = TimestampClock::kMonotonic;
      break;
    case V4L2_BUF_FLAG_TIMESTAMP_COPY:
      result.clock = TimestampClock::kCopy;
      break;
    default:
      result.clock = TimestampClock::kUnknown;
      break;
  }
  result.start_of_exposure =
      (buffer_flags & V4L2_BUF_FLAG_TSTAMP_SRC_MASK) == V4L2_BUF_FLAG_TSTAMP_SRC_SOE;
  return result;
}

}  // namespace cosmos
