#include "firmware_bridge/edge_event_merger.hpp"

namespace cosmos {

bool EdgeEventMerger::push(const GpioEdge& edge) noexcept {
  Ring& ring = rings_[static_cast<std::size_t>(edge.input)];
  if (ring.count == kCapacityPerInput) {
    ++overflowed_;
    return false;
  }
  ring.slots[(ring.first + ring.count) % kCapacityPerInput] = edge;
  ++ring.count;
  return true;
}

std::size_t EdgeEventMerger::held() const noexcept {
  std::size_t total = 0;
  for (const Ring& ring : rings_) total += ring.count;
  return total;
}

void EdgeEventMerger::clear() noexcept {
  for (Ring& ring : rings_) {
    ring.first = 0;
    ring.count = 0;
  }
}

}  // namespace cosmos
