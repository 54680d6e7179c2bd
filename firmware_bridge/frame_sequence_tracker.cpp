#include "firmware_bridge/frame_sequence_tracker.hpp"

namespace cosmos {

namespace {

// A forward step of 2^31 frames or more is read as a backward jump: at 10 kHz that many lost
// frames would take 2.5 days, while a driver resetting its counter is an everyday event.
constexpr std::uint32_t kLargestForwardStep = 0x7fff'ffffu;

}  // namespace

FrameSequenceResult FrameSequenceTracker::on_frame(std::uint32_t sequence) noexcept {
  FrameSequenceResult result;
  ++frames_;
  if (!have_previous_) {
    result.frame_index = have_index_ ? previous_index_ + 1 : 0;
  } else {
    // Unsigned 32-bit difference: 0xffffffff → 0x00000000 is a step of 1.
    const std::uint32_t step = sequence - previous_sequence_;
    if (step == 0 || step > kLargestForwardStep) {
      ++sequence_resets_;
      result.sequence_reset = true;
      result.frame_index = previous_index_ + 1;
    } else {
      result.dropped_before = step - 1;
      dropped_frames_ += result.dropped_before;
      result.frame_index = previous_index_ + step;
    }
  }
  have_previous_ = true;
  have_index_ = true;
  previous_sequence_ = sequence;
  previous_index_ = result.frame_index;
  return result;
}

}  // namespace cosmos
