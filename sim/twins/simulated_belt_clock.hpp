#pragma once
// The time line the hardware twins share: where the simulated belt is when. The camera's
// frame k exposes profile k of the simulated scan (sim/source/simulated_conveyor.hpp), at
// encoder tick k · encoder_ticks_per_profile and at time t_k = k · 1e6 / line_rate_hz µs
// (ScannerParameters::time_us_of_profile: SimulatedSource's t_us), tick 0 at time 0. The
// ticks between two frames are evenly spaced between their times, so the tick of frame k
// falls exactly on t_k.
//
// Time never comes from the wall clock: the simulated camera moves the clock to each frame
// it hands out and the simulated GPIO lines deliver the encoder and photo-eye edges up to
// there. A run is therefore the same however it is paced, and an encoder count read right
// after frame k is exactly the count at its exposure (a real free-running camera's count
// lags by the readout; the twin's does not, so poses meet the ground truth exactly).
#include <cstdint>

#include "scanner/scanner_model.hpp"

namespace cosmos {

class SimulatedBeltClock {
 public:
  explicit SimulatedBeltClock(const ScannerParameters& parameters);

  std::int64_t frame_time_ns(std::int64_t frame) const noexcept;
  std::int64_t tick_time_ns(std::int64_t tick) const noexcept;
  std::int64_t ticks_of_frame(std::int64_t frame) const noexcept {
    return frame * ticks_per_frame_;
  }
  int ticks_per_frame() const noexcept { return ticks_per_frame_; }

  // The frame the belt has reached (its exposure instant is "now"); 0 at the start.
  std::int64_t frame() const noexcept { return frame_; }
  std::int64_t now_ns() const noexcept { return frame_time_ns(frame_); }
  std::int64_t ticks_now() const noexcept { return ticks_of_frame(frame_); }
  void advance_to_frame(std::int64_t frame) noexcept { frame_ = frame; }
  void rewind() noexcept { frame_ = 0; }

 private:
  double line_rate_hz_ = 2500.0;
  int ticks_per_frame_ = 4;
  std::int64_t frame_ = 0;
};

}  // namespace cosmos
