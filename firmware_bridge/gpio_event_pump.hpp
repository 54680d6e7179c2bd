#pragma once
// Reads the kernel's GPIO line events on a thread of its own, so that none is lost while the
// acquisition loop is busy elsewhere. gpio-cdev queues 16 events per line and drops later
// ones silently (the v1 events libgpiod 1.6 reads carry no sequence number that would show
// it), so a loop that polls less often than every 16 edges loses encoder counts for good:
// at start-up (`cosmos cell` starts its source, then loads the model base), or whenever the
// acquisition thread is held up. Against the real driver (gpio-sim under qemu, scripts/hil.sh)
// a belt that moved while the cell started put every pose tens of millimetres behind.
//
// The thread waits on the lines' event file descriptors, restores the time order across lines
// (EdgeEventMerger, up to a cut taken before the queues are read), and hands the ordered
// edges to the loop through an EdgeRing together with the time up to which every edge has
// been handed over (known_until_ns). It also wakes every kIdlePeriodNs without edges, so that
// the decoder's debounce and photo-eye timers move on while the lines are quiet, and at once
// when the consumer asks for a new cut (request_cut): a frame whose time stamp lies after the
// last cut learns without an idle period's delay that no edge came before it.
//
// The consumer side (request_cut, wait, pop, known_until_ns, failed) is real-time: lock-free,
// no allocation, only eventfd reads and writes and ppoll.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <thread>

#include "firmware_bridge/edge_event_merger.hpp"
#include "firmware_bridge/edge_ring.hpp"
#include "firmware_bridge/error_line.hpp"
#include "firmware_bridge/gpio_input_decoder.hpp"

namespace cosmos {

class GpioEventPump {
 public:
  // A second of edges at 64 kHz: far more than any start-up or hold-up of the loop.
  static constexpr std::size_t kDefaultCapacity = 1u << 16;
  static constexpr std::int64_t kIdlePeriodNs = 2'000'000;

  struct Line {
    int fd = -1;  // the requested line's event fd (gpiod_line_event_get_fd)
    GpioInput input = GpioInput::kEncoderA;
    bool active_low = false;
    const char* role = "";  // for messages: "encoder_a" …
  };

  explicit GpioEventPump(std::size_t capacity = kDefaultCapacity);
  ~GpioEventPump();
  GpioEventPump(const GpioEventPump&) = delete;
  GpioEventPump& operator=(const GpioEventPump&) = delete;

  // Set-up: starts reading `lines` (at most kGpioInputCount). False with error() when the
  // thread or its eventfds cannot be made.
  bool start(const Line* lines, std::size_t count) noexcept;
  // Stops and joins the thread; the lines' fds stay the caller's. Edges not popped are dropped.
  void stop() noexcept;
  bool running() const noexcept { return thread_.joinable(); }

  // Consumer: asks the thread to read the lines now and move known_until_ns to that time;
  // it wakes wait() when done.
  void request_cut() noexcept;
  // Consumer: returns once an edge is waiting or a requested cut was taken, or after
  // timeout_ns.
  void wait(std::int64_t timeout_ns) noexcept;
  bool pop(GpioEdge& edge) noexcept { return ring_.pop(edge); }
  // Every edge stamped up to this time (CLOCK_MONOTONIC) is in the ring or was popped; read
  // it before popping.
  std::int64_t known_until_ns() const noexcept {
    return known_until_ns_.load(std::memory_order_acquire);
  }
  // The thread stopped on an error (a line's events unreadable, or not CLOCK_MONOTONIC).
  bool failed() const noexcept { return failed_.load(std::memory_order_acquire); }
  std::string_view error() const noexcept { return error_.view(); }
  // Edges lost inside the pump: its merger or its ring full (the loop did not keep up).
  std::uint64_t lost_edges() const noexcept {
    return ring_.dropped() + merger_lost_.load(std::memory_order_relaxed);
  }

 private:
  void run() noexcept;
  [[gnu::format(printf, 2, 3)]] void fail(const char* format, ...) noexcept;

  EdgeRing ring_;
  EdgeEventMerger merger_;  // the pump thread's
  Line lines_[kGpioInputCount] = {};
  std::size_t line_count_ = 0;
  int stop_fd_ = -1;
  int request_fd_ = -1;  // consumer -> thread: take a cut now
  int wake_fd_ = -1;
  std::thread thread_;
  std::atomic<std::int64_t> known_until_ns_{0};
  std::atomic<std::uint64_t> merger_lost_{0};
  std::atomic<bool> failed_{false};
  ErrorLine error_;  // written by the thread before failed_ is set
};

}  // namespace cosmos
