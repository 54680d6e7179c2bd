#pragma once
// When vivid's capture side filled a buffer, seen from another process. vivid sets its
// "Read-Only Integer 32 Bits" control to the frame's sequence number (mod 256) as it starts
// filling each capture buffer, and a changed control raises a V4L2_EVENT_CTRL on every file
// handle subscribed to it, whichever node it is open on. The player subscribes on its output
// node and so learns of every frame the cell's camera is given, with the kernel's time and
// the frame's sequence number, without touching the cell's capture queue.
//
// The sequence number is unwrapped from its 8 bits with the capture's clock: vivid numbers
// its frames by the time since streaming began (a tick without a free buffer produces no
// event but still advances the number, and the cell may hold every buffer for seconds while
// it starts), so the number is the one ≡ the 8 bits (mod 256) nearest to the time since the
// first event over the frame period, which is exact while the capture thread's lateness
// stays under 128 frames.
#include <cstdint>

#include "tests/hil/v4l2_node.hpp"

namespace cosmos::hil {

struct CaptureTick {
  std::int64_t sequence = 0;        // the capture's frame sequence number, unwrapped
  std::int64_t t_ns = 0;            // CLOCK_MONOTONIC when the fill began
  std::uint32_t missed_events = 0;  // events merged away since the previous one (the player lagged)
};

// The sequence number ≡ `low_bits` (mod 256) nearest to (t_ns − t0_ns) / frame_period_ns.
std::int64_t unwrap_sequence(std::int64_t low_bits, std::int64_t t_ns, std::int64_t t0_ns,
                             double frame_period_ns);

class CaptureTicks {
 public:
  // `frame_period_ns`: the capture's frame period (its DV timings).
  CaptureTicks(const V4l2Node& node, double frame_period_ns);
  ~CaptureTicks();
  CaptureTicks(const CaptureTicks&) = delete;
  CaptureTicks& operator=(const CaptureTicks&) = delete;

  // Waits up to timeout_ms for the next fill; false on timeout.
  bool wait(int timeout_ms, CaptureTick& tick);
  std::int64_t events() const { return events_; }
  // A control only raises an event when its value changes: when it held 0 already (nothing
  // streamed since the driver was loaded), the stream's frame 0 is filled without one.
  bool first_fill_silent() const { return initial_value_ == 0; }

 private:
  const V4l2Node& node_;
  std::uint32_t control_id_ = 0;
  double frame_period_ns_ = 0;
  bool have_previous_ = false;
  std::int64_t t0_ns_ = 0;                               // time of frame 0, from the first event
  std::uint32_t previous_event_sequence_ = 0xffffffffu;  // the first event is number 0
  std::int64_t events_ = 0;
  std::int64_t initial_value_ = 0;
};

}  // namespace cosmos::hil
