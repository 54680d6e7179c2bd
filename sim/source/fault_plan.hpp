#pragma once
// Where the injected faults of the `faults:` section
// (realtime/sources/fault_injection_settings.hpp) fall in the stream: a pure function of the
// profile (camera frame) index and the seed, so the simulated source and the hardware twins, which
// meet a fault at different moments and from different threads, agree on it without sharing state,
// and a replayed run meets the same faults at the same profiles.
//
// A fault with every_profiles = N > 0 occurs once in each run [w·N, (w+1)·N) of profiles,
// w >= 1 (the first run is clean, so the cell starts normally), starting at an offset in the
// run drawn from (seed, fault, w), and lasts `profiles` profiles (at most N). Cheap and
// allocation-free: one hash per query.
#include <cstdint>

#include "realtime/sources/fault_injection_settings.hpp"

namespace cosmos {

enum class InjectedFault : std::uint8_t {
  kFrameGap,
  kCameraStall,
  kEncoderGlitch,
  kEncoderReversal,
  kEncoderStuck,
  kLaserOff,
  kPhotoEyeBounce,
};

class FaultPlan {
 public:
  explicit FaultPlan(const FaultInjectionSettings& settings = {}) : settings_(settings) {}

  // Whether `fault` is under way at profile `profile`.
  bool active(InjectedFault fault, std::int64_t profile) const noexcept;
  // The first profile of the occurrence of `fault` in the run holding `profile` (w >= 1), or
  // -1 when the fault is off or that run is the first.
  std::int64_t occurrence_start(InjectedFault fault, std::int64_t profile) const noexcept;

  const FaultSchedule& schedule(InjectedFault fault) const noexcept;
  const FaultInjectionSettings& settings() const noexcept { return settings_; }

 private:
  FaultInjectionSettings settings_;
};

}  // namespace cosmos
