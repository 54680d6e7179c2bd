#include "tests/hil/capture_ticks.hpp"

#include <poll.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos::hil {

std::int64_t unwrap_sequence(std::int64_t low_bits, std::int64_t t_ns, std::int64_t t0_ns,
                             double frame_period_ns) {
  const auto elapsed =
      static_cast<std::int64_t>(std::llround(static_cast<double>(t_ns - t0_ns) / frame_period_ns));
  std::int64_t sequence = elapsed - ((elapsed - low_bits) % 256 + 256) % 256;
  if (elapsed - sequence > 128) sequence += 256;
  return sequence;
}

CaptureTicks::CaptureTicks(const V4l2Node& node, double frame_period_ns)
    : node_(node),
      control_id_(node.control_id("Read-Only Integer 32 Bits")),
      frame_period_ns_(frame_period_ns),
      initial_value_(node.control("Read-Only Integer 32 Bits") & 0xff) {
  v4l2_event_subscription subscription{};
  subscription.type = V4L2_EVENT_CTRL;
  subscription.id = control_id_;
  node_.call(VIDIOC_SUBSCRIBE_EVENT, &subscription, "VIDIOC_SUBSCRIBE_EVENT");
}

CaptureTicks::~CaptureTicks() {
  v4l2_event_subscription subscription{};
  subscription.type = V4L2_EVENT_CTRL;
  subscription.id = control_id_;
  node_.try_call(VIDIOC_UNSUBSCRIBE_EVENT, &subscription);
}

bool CaptureTicks::wait(int timeout_ms, CaptureTick& tick) {
  for (;;) {
    v4l2_event event{};
    const int error = node_.try_call(VIDIOC_DQEVENT, &event);
    if (error == 0) {
      if (event.type != V4L2_EVENT_CTRL || event.id != control_id_ ||
          (event.u.ctrl.changes & V4L2_EVENT_CTRL_CH_VALUE) == 0) {
        continue;
      }
      const auto value = static_cast<std::int64_t>(event.u.ctrl.value & 0xff);
      const std::int64_t t_ns = timespec_to_ns(event.timestamp);
      // Events merged away while this one waited (the subscription keeps one) are fills too.
      tick.missed_events = event.sequence - previous_event_sequence_ - 1;
      if (!have_previous_) {
        t0_ns_ = t_ns - static_cast<std::int64_t>(static_cast<double>(value) * frame_period_ns_);
      }
      have_previous_ = true;
      previous_event_sequence_ = event.sequence;
      tick.sequence = unwrap_sequence(value, t_ns, t0_ns_, frame_period_ns_);
      tick.t_ns = t_ns;
      ++events_;
      return true;
    }
    if (error != ENOENT) {
      throw std::runtime_error(node_.path() + ": VIDIOC_DQEVENT: " + std::strerror(error));
    }
    pollfd request{node_.fd(), POLLPRI, 0};
    const int ready = ::poll(&request, 1, timeout_ms);
    if (ready < 0 && errno != EINTR) {
      throw std::runtime_error(node_.path() + ": poll for events: " + std::strerror(errno));
    }
    if (ready == 0) return false;
  }
}

}  // namespace cosmos::hil
