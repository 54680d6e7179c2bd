#pragma once
// Where profiles come from, as the acquisition loop sees it. Three implementations: the
// simulated conveyor (simulated_source.hpp), a recorded log (replay_source.hpp) and the real
// camera + GPIO (hardware_source.hpp). The loop and everything after it cannot tell them
// apart: each hands out the same Profile (core/profile.hpp) with the same field meanings.
//
// Lifecycle: construct (may throw InputError on bad settings) → start() → reserve() each ring
// slot → next() until kEndOfStream or the loop stops → stop(). start() is set-up and may
// allocate; next() runs on the acquisition thread: no allocation once the Profile was
// reserved, no exceptions, no locks; failures come back as status values.
#include <cstdint>
#include <string_view>

#include "core/profile.hpp"

namespace cosmos {

// What a source lost or found wrong since start(), for COSMOS_STATUS: each is a loss a robot
// downstream would otherwise never hear of. Sources without the device report 0.
struct SourceHealth {
  std::uint64_t profiles_lost = 0;      // camera frame gaps, replayed profiles skipped
  std::uint64_t camera_timeouts = 0;    // waits for a frame that hit the watchdog
  std::uint64_t encoder_errors = 0;     // quadrature states skipped (a missed edge)
  std::uint64_t encoder_reversals = 0;  // direction changes of the count
  std::uint64_t gpio_edges_lost = 0;    // input edges never decoded (FIFO or ring overflow)
  std::uint64_t photo_eye_bounces = 0;  // photo-eye edges rejected as bounce or glitch
  // Profiles whose encoder count is not the count at their time stamp: the edges up to it
  // were not read within gpio.frame_edges_wait_us, or it lay before the kept count history.
  std::uint64_t encoder_counts_unsettled = 0;
  // Found in the data by the stream checker (stream_checked_source.hpp): no device reports them.
  std::uint64_t encoder_stalls = 0;      // profiles whose encoder count did not advance
  std::uint64_t laser_off_profiles = 0;  // profiles without a single laser point
};

enum class SourceStatus : std::uint8_t {
  kOk,           // `out` holds the next profile
  kEndOfStream,  // a finite source is exhausted; every later call says so too
  kTimeout,      // no profile this call (watchdog expired, frame discarded): call again
  kError,        // see last_error(); the source must be stopped and started again
};

class ScannerSource {
 public:
  virtual ~ScannerSource() = default;

  // Opens devices / files and builds every buffer. kError with last_error() on failure.
  virtual SourceStatus start() = 0;
  // Sizes a ring slot once for the widest profile this source emits, so next() never
  // allocates into it.
  virtual void reserve(Profile& profile) const = 0;
  // Fills seq, encoder_ticks, t_us, x0_mm, dx_mm and z_mm of `out`.
  virtual SourceStatus next(Profile& out) noexcept = 0;
  virtual void stop() noexcept = 0;

  // Nominal belt travel between consecutive profiles (the conveyor model's Δy).
  virtual double mm_per_profile() const = 0;
  // One line naming the device or file and the reason of the last failure; empty if none.
  virtual std::string_view last_error() const noexcept = 0;
  // Losses and faults so far. Acquisition thread, or once the source is stopped.
  virtual SourceHealth health() const noexcept = 0;
};

}  // namespace cosmos
