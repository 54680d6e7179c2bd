#pragma once
// Dropped-frame accounting from V4L2 sequence numbers. The driver numbers every frame the
// sensor produced, including those it had to discard because the application held all the
// buffers, so a gap between two dequeued frames is exactly the number of frames lost. The
// counter is 32 bits and wraps (after ~10 days at 5 kHz); unsigned differences handle that.
//
// The tracker also extends the sequence to a 64-bit frame index that survives stream
// restarts (drivers restart their counter at STREAMON), so Profile::seq never goes back.
#include <cstdint>

namespace cosmos {

struct FrameSequenceResult {
  std::uint64_t frame_index = 0;
  std::uint32_t dropped_before = 0;  // frames missing between the previous frame and this one
  bool sequence_reset = false;       // the counter went backwards: re-synchronized here
};

class FrameSequenceTracker {
 public:
  // After STREAMON: the next frame's number becomes the new reference. Nothing is counted
  // as dropped across the restart, since frames are not produced while streaming is off.
  void restart() noexcept { have_previous_ = false; }

  FrameSequenceResult on_frame(std::uint32_t sequence) noexcept;

  std::uint64_t frames() const noexcept { return frames_; }
  std::uint64_t dropped_frames() const noexcept { return dropped_frames_; }
  // Backward jumps (a driver resetting its counter mid-stream) and repeated numbers.
  std::uint64_t sequence_resets() const noexcept { return sequence_resets_; }

 private:
  bool have_previous_ = false;
  bool have_index_ = false;
  std::uint32_t previous_sequence_ = 0;
  std::uint64_t previous_index_ = 0;
  std::uint64_t frames_ = 0;
  std::uint64_t dropped_frames_ = 0;
  std::uint64_t sequence_resets_ = 0;
};

}  // namespace cosmos
