#include "tests/hil/capture_ticks.hpp"

#include <poll.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos::hil {

CaptureTicks::CaptureTicks(const V4l2Node& node)
    : node_(node), control_id_(node.control_id("Read-Only Integer 32 Bits")) {
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
      const auto value = static_cast<std::uint32_t>(event.u.ctrl.value) & 0xffu;
      tick.missed_events = 0;
      if (have_previous_) {
        sequence_ += static_cast<std::int64_t>((value - previous_value_) & 0xffu);
        tick.missed_events = event.sequence - previous_event_sequence_ - 1;
      } else {
        sequence_ = value;
      }
      have_previous_ = true;
      previous_value_ = value;
      previous_event_sequence_ = event.sequence;
      tick.sequence = sequence_;
      tick.t_ns = timespec_to_ns(event.timestamp);
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
