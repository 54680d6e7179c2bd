#include "sim/twins/simulated_belt_clock.hpp"

#include <cmath>
#include <stdexcept>

namespace cosmos {

SimulatedBeltClock::SimulatedBeltClock(const ScannerParameters& parameters)
    : line_rate_hz_(parameters.line_rate_hz),
      ticks_per_frame_(parameters.encoder_ticks_per_profile) {
  if (!(line_rate_hz_ > 0.0) || ticks_per_frame_ < 1) {
    throw std::invalid_argument(
        "simulated belt clock: line_rate_hz must be > 0 and encoder_ticks_per_profile >= 1");
  }
}

std::int64_t SimulatedBeltClock::frame_time_ns(std::int64_t frame) const noexcept {
  // The same rounding as ScannerParameters::time_us_of_profile, so t_us equals the
  // simulated source's.
  return 1000 * std::llround(static_cast<double>(frame) * 1e6 / line_rate_hz_);
}

std::int64_t SimulatedBeltClock::tick_time_ns(std::int64_t tick) const noexcept {
  // Floor division: ticks before tick 0 (none are emitted) would still be ordered.
  std::int64_t frame = tick / ticks_per_frame_;
  if (tick % ticks_per_frame_ < 0) --frame;
  const std::int64_t within = tick - frame * ticks_per_frame_;
  const std::int64_t start_ns = frame_time_ns(frame);
  return start_ns + (frame_time_ns(frame + 1) - start_ns) * within / ticks_per_frame_;
}

}  // namespace cosmos
