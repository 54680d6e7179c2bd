#pragma once
// One range profile: the heights the scanner measured along the laser line at one encoder
// step. Every ScannerSource (simulated ray caster, camera + stripe extraction, replay) emits
// this one type, so everything downstream of the source cannot tell them apart.
//
// Frame: the scanner frame, x across the belt, y along the belt (direction of travel),
// z up (towards the scanner), millimetres. Sample i lies at x = x0_mm + i * dx_mm on the
// laser line; z_mm[i] is its height, NaN where the sensor saw nothing (occlusion, gap,
// out of range). The profile's y is given by encoder_ticks through the conveyor model.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace cosmos {

struct Profile {
  std::uint64_t seq = 0;           // index in the source's stream, no gaps unless dropped
  std::int64_t encoder_ticks = 0;  // conveyor encoder count when the line was exposed
  std::int64_t t_us = 0;           // exposure time stamp, microseconds, monotonic clock
  double x0_mm = 0.0;              // x of sample 0
  double dx_mm = 1.0;              // sample spacing along x
  std::vector<float> z_mm;         // height per sample, NaN = no data

  static constexpr float kNoData = std::numeric_limits<float>::quiet_NaN();

  // Real-time code reuses one Profile per ring slot: reserve the configured maximum width
  // once at warm-up and no later resize() allocates.
  void reserve(std::size_t max_width) { z_mm.reserve(max_width); }

  // Sets the width and marks every sample as no data. A std::vector never gives capacity
  // back, so the capacity grows at most to the widest profile ever seen, and only once.
  void resize(std::size_t width) {
    z_mm.resize(width);
    clear_data();
  }

  void clear_data() {
    for (float& z : z_mm) z = kNoData;
  }

  std::size_t width() const { return z_mm.size(); }
  double x_mm(std::size_t i) const { return x0_mm + static_cast<double>(i) * dx_mm; }
  bool has_data(std::size_t i) const { return !std::isnan(z_mm[i]); }
};

}  // namespace cosmos
