#pragma once
// Decoded-in-order GPIO edges handed from the thread that reads the kernel's line events
// (GpioEventPump) to the acquisition thread that decodes them: one producer, one consumer,
// fixed capacity, lock-free. A full ring drops the newest edge and counts it.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "firmware_bridge/gpio_input_decoder.hpp"

namespace cosmos {

class EdgeRing {
 public:
  // Set-up: allocates `capacity` slots (rounded up to a power of two).
  explicit EdgeRing(std::size_t capacity);

  // Producer thread only.
  bool push(const GpioEdge& edge) noexcept;
  // Consumer thread only: the oldest edge; false when there is none.
  bool pop(GpioEdge& edge) noexcept;
  // Consumer thread only, while the producer is stopped.
  void clear() noexcept;

  std::size_t capacity() const noexcept { return slots_.size(); }
  std::uint64_t dropped() const noexcept { return dropped_.load(std::memory_order_relaxed); }

 private:
  std::vector<GpioEdge> slots_;
  std::size_t mask_ = 0;
  alignas(64) std::atomic<std::uint64_t> head_{0};  // next to pop
  alignas(64) std::atomic<std::uint64_t> tail_{0};  // next to push
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace cosmos
