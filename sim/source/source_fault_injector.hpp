#pragma once
// The injected faults as the simulated source meets them (SimulatedSource::next), on the
// profiles it scans: what a camera and an encoder that fail would hand the cell.
//   frame gaps       the profile is lost: the next one comes with its own, later seq
//   camera stalls    no profile: next() times out (one camera timeout per profile of the
//                    stall, which the paced loop spaces at the line rate), then the stream goes
//                    on with a seq gap
//   encoder glitch   the count reads 1000 ticks high during the occurrence, then right again
//   reversal         the count runs backwards, one profile's ticks per profile, then forwards
//                    again from there (the belt backed up: later counts stay short)
//   stuck encoder    the count repeats while the belt moves on, then advances from there
//   laser off        a profile without a single point
// Sequential: after() must see the scanned profiles in order; restart() with the stream.
#include <cstdint>

#include "core/profile.hpp"
#include "sim/source/fault_plan.hpp"

namespace cosmos {

class SourceFaultInjector {
 public:
  enum class Action : std::uint8_t { kScan, kLose, kTimeout };

  SourceFaultInjector(const FaultInjectionSettings& settings, int encoder_ticks_per_profile);

  void restart() noexcept;
  // Before profile `profile` is scanned: scan it, lose it, or time out instead.
  Action before(std::int64_t profile) noexcept;
  // After it was scanned into `out` (encoder_ticks and z_mm set): the encoder and laser faults.
  void after(std::int64_t profile, Profile& out) noexcept;

  std::uint64_t camera_timeouts() const noexcept { return camera_timeouts_; }
  const FaultPlan& plan() const noexcept { return plan_; }

 private:
  FaultPlan plan_;
  std::int64_t ticks_per_profile_ = 4;
  std::int64_t encoder_offset_ = 0;  // ticks the count has fallen behind the belt
  std::uint64_t camera_timeouts_ = 0;
};

}  // namespace cosmos
