#include "sim/source/source_fault_injector.hpp"

#include <algorithm>

namespace cosmos {
namespace {

// A count spike no belt can make in one profile: the replay's y = -100 km of a bad reading.
constexpr std::int64_t kGlitchTicks = 1000;

}  // namespace

SourceFaultInjector::SourceFaultInjector(const FaultInjectionSettings& settings,
                                         int encoder_ticks_per_profile)
    : plan_(settings), ticks_per_profile_(std::max(encoder_ticks_per_profile, 1)) {}

void SourceFaultInjector::restart() noexcept {
  encoder_offset_ = 0;
  camera_timeouts_ = 0;
}

SourceFaultInjector::Action SourceFaultInjector::before(std::int64_t profile) noexcept {
  if (plan_.active(InjectedFault::kFrameGap, profile)) return Action::kLose;
  if (plan_.active(InjectedFault::kCameraStall, profile)) {
    ++camera_timeouts_;
    return Action::kTimeout;
  }
  return Action::kScan;
}

void SourceFaultInjector::after(std::int64_t profile, Profile& out) noexcept {
  if (plan_.active(InjectedFault::kEncoderStuck, profile)) {
    encoder_offset_ -= ticks_per_profile_;  // the previous profile's count again
  } else if (plan_.active(InjectedFault::kEncoderReversal, profile)) {
    encoder_offset_ -= 2 * ticks_per_profile_;  // one profile's ticks back
  }
  out.encoder_ticks += encoder_offset_;
  if (plan_.active(InjectedFault::kEncoderGlitch, profile)) out.encoder_ticks += kGlitchTicks;
  if (plan_.active(InjectedFault::kLaserOff, profile))
    std::fill(out.z_mm.begin(), out.z_mm.end(), Profile::kNoData);
}

}  // namespace cosmos
