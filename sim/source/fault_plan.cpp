#include "sim/source/fault_plan.hpp"

#include <algorithm>

#include "sim/seeded_random.hpp"

namespace cosmos {

const FaultSchedule& FaultPlan::schedule(InjectedFault fault) const noexcept {
  switch (fault) {
    case InjectedFault::kFrameGap:
      return settings_.frame_gaps;
    case InjectedFault::kCameraStall:
      return settings_.camera_stalls;
    case InjectedFault::kEncoderGlitch:
      return settings_.encoder_glitches;
    case InjectedFault::kEncoderReversal:
      return settings_.encoder_reversals;
    case InjectedFault::kEncoderStuck:
      return settings_.encoder_stuck;
    case InjectedFault::kLaserOff:
      return settings_.laser_off;
    case InjectedFault::kPhotoEyeBounce:
      return settings_.photo_eye_bounces;
  }
  return settings_.frame_gaps;
}

std::int64_t FaultPlan::occurrence_start(InjectedFault fault, std::int64_t profile) const noexcept {
  const FaultSchedule& schedule = this->schedule(fault);
  if (!schedule.on() || profile < 0) return -1;
  const std::int64_t every = schedule.every_profiles;
  const std::int64_t run = profile / every;
  if (run == 0) return -1;
  const std::int64_t length = std::min<std::int64_t>(schedule.profiles, every);
  const std::uint64_t stream =
      static_cast<std::uint64_t>(fault) << 56 ^ static_cast<std::uint64_t>(run);
  const auto offset = static_cast<std::int64_t>(mix_seed(settings_.seed, stream) %
                                                static_cast<std::uint64_t>(every - length + 1));
  return run * every + offset;
}

bool FaultPlan::active(InjectedFault fault, std::int64_t profile) const noexcept {
  const std::int64_t start = occurrence_start(fault, profile);
  if (start < 0 || profile < start) return false;
  return profile - start < std::min(schedule(fault).profiles, schedule(fault).every_profiles);
}

}  // namespace cosmos
