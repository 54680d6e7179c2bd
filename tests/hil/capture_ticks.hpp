#pragma once
// When vivid's capture side filled a buffer, seen from another process. vivid sets its
// "Read-Only Integer 32 Bits" control to the frame's sequence number (mod 256) as it starts
// filling each capture buffer, and a changed control raises a V4L2_EVENT_CTRL on every file
// handle subscribed to it, whichever node it is open on. The player subscribes on its output
// node and so learns of every frame the cell's camera is given, with the kernel's time and
// the frame's sequence number, without touching the cell's capture queue.
//
// The sequence number is unwrapped from its 8 bits by the step since the previous event: a
// capture tick without a free buffer produces no event but still advances the number, and
// fewer than 256 such ticks pass between two events.
#include <cstdint>

#include "tests/hil/v4l2_node.hpp"

namespace cosmos::hil {

struct CaptureTick {
  std::int64_t sequence = 0;        // the capture's frame sequence number, unwrapped
  std::int64_t t_ns = 0;            // CLOCK_MONOTONIC when the fill began
  std::uint32_t missed_events = 0;  // events merged away since the previous one (the player lagged)
};

class CaptureTicks {
 public:
  explicit CaptureTicks(const V4l2Node& node);
  ~CaptureTicks();
  CaptureTicks(const CaptureTicks&) = delete;
  CaptureTicks& operator=(const CaptureTicks&) = delete;

  // Waits up to timeout_ms for the next fill; false on timeout.
  bool wait(int timeout_ms, CaptureTick& tick);
  std::int64_t events() const { return events_; }

 private:
  const V4l2Node& node_;
  std::uint32_t control_id_ = 0;
  bool have_previous_ = false;
  std::int64_t sequence_ = 0;
  std::uint32_t previous_value_ = 0;
  std::uint32_t previous_event_sequence_ = 0;
  std::int64_t events_ = 0;
};

}  // namespace cosmos::hil
