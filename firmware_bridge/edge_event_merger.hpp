#pragma once
// Restores the time order of edge events read from several GPIO lines. The kernel queues
// each line's events in its own FIFO; reading line A's queue then line B's gives A's events
// first even when a B edge came between them, and the quadrature decoder needs the true
// interleaving. Events are pushed as read and drained in time-stamp order, but only up to a
// cut time taken before the queues were read: every edge stamped before the cut was already
// queued when the queues were read, while a later one may still have a predecessor on
// another line that is not read yet. Those wait for the next cut.
//
// Real-time: fixed per-input rings, no allocation, no exceptions. Ties keep input order, so
// the merged sequence is deterministic.
#include <array>
#include <cstddef>
#include <cstdint>

#include "firmware_bridge/gpio_input_decoder.hpp"

namespace cosmos {

class EdgeEventMerger {
 public:
  // Per input: a kernel FIFO holds 16 events, read in one batch per poll; 64 leaves room for
  // events held back past a cut plus a full new batch.
  static constexpr std::size_t kCapacityPerInput = 64;

  // Appends an event read from its input's queue (each input's events arrive in time order).
  // False, and counted, when that input's ring is full: the event is lost.
  bool push(const GpioEdge& edge) noexcept;

  // Hands every held event stamped at or before cut_ns to sink(const GpioEdge&), oldest first.
  template <class Sink>
  void drain(std::int64_t cut_ns, Sink&& sink) noexcept {
    for (;;) {
      std::size_t best = kGpioInputCount;
      for (std::size_t i = 0; i < kGpioInputCount; ++i) {
        if (rings_[i].count == 0) continue;
        const GpioEdge& head = rings_[i].slots[rings_[i].first];
        if (head.t_ns > cut_ns) continue;
        if (best == kGpioInputCount || head.t_ns < rings_[best].slots[rings_[best].first].t_ns)
          best = i;
      }
      if (best == kGpioInputCount) return;
      Ring& ring = rings_[best];
      sink(ring.slots[ring.first]);
      ring.first = (ring.first + 1) % kCapacityPerInput;
      --ring.count;
    }
  }

  std::size_t held() const noexcept;
  std::uint64_t overflowed() const noexcept { return overflowed_; }
  void clear() noexcept;

 private:
  struct Ring {
    std::array<GpioEdge, kCapacityPerInput> slots{};
    std::size_t first = 0;
    std::size_t count = 0;
  };
  std::array<Ring, kGpioInputCount> rings_{};
  std::uint64_t overflowed_ = 0;
};

}  // namespace cosmos
