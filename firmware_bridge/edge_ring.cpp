#include "firmware_bridge/edge_ring.hpp"

#include <bit>

namespace cosmos {

EdgeRing::EdgeRing(std::size_t capacity)
    : slots_(std::bit_ceil(capacity < 2 ? std::size_t{2} : capacity)), mask_(slots_.size() - 1) {}

bool EdgeRing::push(const GpioEdge& edge) noexcept {
  const std::uint64_t tail = tail_.load(std::memory_order_relaxed);
  if (tail - head_.load(std::memory_order_acquire) >= slots_.size()) {
    dropped_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  slots_[tail & mask_] = edge;
  tail_.store(tail + 1, std::memory_order_release);
  return true;
}

bool EdgeRing::pop(GpioEdge& edge) noexcept {
  const std::uint64_t head = head_.load(std::memory_order_relaxed);
  if (head == tail_.load(std::memory_order_acquire)) return false;
  edge = slots_[head & mask_];
  head_.store(head + 1, std::memory_order_release);
  return true;
}

void EdgeRing::clear() noexcept {
  head_.store(tail_.load(std::memory_order_acquire), std::memory_order_release);
}

}  // namespace cosmos
