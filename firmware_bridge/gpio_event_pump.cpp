#include "firmware_bridge/gpio_event_pump.hpp"

#include <gpiod.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <system_error>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos {
namespace {

// libgpiod reads at most this many events per call: the kernel FIFO depth.
constexpr int kEventBatch = 16;

// An event stamped this far after the cut cannot be CLOCK_MONOTONIC: kernels before 5.7
// stamped GPIO events with CLOCK_REALTIME, which would hold every event back forever.
constexpr std::int64_t kClockMismatchNs = 1'000'000'000;

}  // namespace

GpioEventPump::GpioEventPump(std::size_t capacity) : ring_(capacity) {}

GpioEventPump::~GpioEventPump() { stop(); }

void GpioEventPump::fail(const char* format, ...) noexcept {
  char reason[ErrorLine::kCapacity];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(reason, sizeof reason, format, arguments);
  va_end(arguments);
  error_.set("%s", reason);
  failed_.store(true, std::memory_order_release);
  if (wake_fd_ >= 0) eventfd_write(wake_fd_, 1);
}

bool GpioEventPump::start(const Line* lines, std::size_t count) noexcept {
  stop();
  if (count > kGpioInputCount) {
    error_.set("at most %zu input lines", kGpioInputCount);
    return false;
  }
  for (std::size_t i = 0; i < count; ++i) lines_[i] = lines[i];
  line_count_ = count;
  failed_.store(false, std::memory_order_relaxed);
  error_.clear();
  merger_.clear();
  ring_.clear();
  known_until_ns_.store(monotonic_now_ns(), std::memory_order_release);
  stop_fd_ = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  request_fd_ = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  wake_fd_ = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  if (stop_fd_ < 0 || request_fd_ < 0 || wake_fd_ < 0) {
    error_.set("cannot make an eventfd for the edge reader: %s", errno_text(errno));
    stop();
    return false;
  }
  try {
    thread_ = std::thread([this] { run(); });
  } catch (const std::system_error& error) {
    error_.set("cannot start the edge reader thread: %s", error.what());
    stop();
    return false;
  }
  return true;
}

void GpioEventPump::stop() noexcept {
  if (thread_.joinable()) {
    eventfd_write(stop_fd_, 1);
    thread_.join();
  }
  for (int* fd : {&stop_fd_, &request_fd_, &wake_fd_}) {
    if (*fd >= 0) ::close(*fd);
    *fd = -1;
  }
}

void GpioEventPump::request_cut() noexcept {
  if (request_fd_ >= 0) eventfd_write(request_fd_, 1);
}

void GpioEventPump::wait(std::int64_t timeout_ns) noexcept {
  pollfd wake{wake_fd_, POLLIN, 0};
  const timespec timeout = ns_to_timespec(timeout_ns);
  if (::ppoll(&wake, 1, &timeout, nullptr) > 0) {
    eventfd_t count = 0;
    eventfd_read(wake_fd_, &count);
  }
}

void GpioEventPump::run() noexcept {
  // fds: the stop request, the cut request, then the lines.
  constexpr std::size_t kFirstLine = 2;
  std::array<pollfd, kGpioInputCount + kFirstLine> fds{};
  fds[0] = {stop_fd_, POLLIN, 0};
  fds[1] = {request_fd_, POLLIN, 0};
  for (std::size_t i = 0; i < line_count_; ++i) fds[i + kFirstLine] = {lines_[i].fd, POLLIN, 0};
  const auto watched = static_cast<nfds_t>(line_count_ + kFirstLine);
  const timespec idle = ns_to_timespec(kIdlePeriodNs);
  const timespec no_wait{};
  gpiod_line_event events[kEventBatch];
  for (;;) {
    const int woke = ::ppoll(fds.data(), watched, &idle, nullptr);
    if (woke < 0 && errno != EINTR) {
      fail("waiting for edge events: %s", errno_text(errno));
      return;
    }
    if ((fds[0].revents & POLLIN) != 0) return;
    const bool requested = (fds[1].revents & POLLIN) != 0;
    if (requested) {
      eventfd_t count = 0;
      eventfd_read(request_fd_, &count);
    }
    // The cut is taken before the queues are read: see EdgeEventMerger.
    const std::int64_t cut_ns = monotonic_now_ns();
    if (::ppoll(fds.data() + kFirstLine, watched - kFirstLine, &no_wait, nullptr) < 0 &&
        errno != EINTR) {
      fail("checking edge events: %s", errno_text(errno));
      return;
    }
    for (std::size_t i = 0; i < line_count_; ++i) {
      if ((fds[i + kFirstLine].revents & POLLIN) == 0) continue;
      const Line& line = lines_[i];
      const int count = gpiod_line_event_read_fd_multiple(line.fd, events, kEventBatch);
      if (count < 0) {
        fail("%s: reading edge events: %s", line.role, errno_text(errno));
        return;
      }
      for (int e = 0; e < count; ++e) {
        const std::int64_t t_ns = timespec_to_ns(events[e].ts);
        if (t_ns > cut_ns + kClockMismatchNs) {
          fail("%s: event time stamps are not CLOCK_MONOTONIC (kernel older than 5.7?)", line.role);
          return;
        }
        const bool rising = events[e].event_type == GPIOD_LINE_EVENT_RISING_EDGE;
        if (!merger_.push({t_ns, line.input, rising != line.active_low})) {
          merger_lost_.fetch_add(1, std::memory_order_relaxed);
        }
      }
    }
    bool handed = false;
    merger_.drain(cut_ns, [&](const GpioEdge& edge) { handed = ring_.push(edge) || handed; });
    known_until_ns_.store(cut_ns, std::memory_order_release);
    if (handed || requested) eventfd_write(wake_fd_, 1);
  }
}

}  // namespace cosmos
