#pragma once
// A wake-up call from one thread to a thread that waits for work, without a lock: the
// producer of a ring (SpscRing) notifies after each push, the consumer waits with a timeout
// when it found nothing to do. A notify costs one atomic increment, plus one futex wake system
// call only while the consumer actually sleeps; a wait returns at once when a notify came since
// the consumer last looked, so no notify is lost between its look at the ring and its sleep.
//
// Any number of notifying threads, one waiting thread. No allocation, no exceptions.
#include <atomic>
#include <cstdint>

namespace cosmos {

class WakeSignal {
 public:
  // Producer side (any thread).
  void notify() noexcept;

  // Consumer side: the value to wait on, read *before* the consumer looks for work.
  std::uint32_t epoch() const noexcept { return epoch_.load(std::memory_order_acquire); }
  // Sleeps until a notify after `seen` (an earlier epoch()) or until timeout_ns passed.
  void wait(std::uint32_t seen, std::int64_t timeout_ns) noexcept;

 private:
  std::atomic<std::uint32_t> epoch_{0};
  std::atomic<std::uint32_t> sleeping_{0};
};

}  // namespace cosmos
