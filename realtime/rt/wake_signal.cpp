#include "realtime/rt/wake_signal.hpp"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <climits>
#include <ctime>

namespace cosmos {
namespace {

long futex(std::atomic<std::uint32_t>& word, int operation, std::uint32_t value,
           const timespec* timeout) noexcept {
  static_assert(sizeof(std::atomic<std::uint32_t>) == sizeof(std::uint32_t));
  return syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word), operation, value, timeout,
                 nullptr, 0);
}

}  // namespace

void WakeSignal::notify() noexcept {
  // Both sides seq_cst (the store-load order of each matters): either the waiter sees the new
  // epoch before it sleeps (and the kernel's own compare in FUTEX_WAIT catches it in between),
  // or this sees it sleeping and wakes it.
  epoch_.fetch_add(1, std::memory_order_seq_cst);
  if (sleeping_.load(std::memory_order_seq_cst) != 0)
    futex(epoch_, FUTEX_WAKE_PRIVATE, INT_MAX, nullptr);
}

void WakeSignal::wait(std::uint32_t seen, std::int64_t timeout_ns) noexcept {
  if (timeout_ns <= 0) return;
  sleeping_.fetch_add(1, std::memory_order_seq_cst);
  if (epoch_.load(std::memory_order_seq_cst) == seen) {
    const timespec timeout{static_cast<std::time_t>(timeout_ns / 1'000'000'000),
                           static_cast<long>(timeout_ns % 1'000'000'000)};
    // Returns at once (EAGAIN) when the epoch moved on in between; a wake, a timeout or a
    // signal ends it otherwise. Each is fine: the caller looks for work again.
    futex(epoch_, FUTEX_WAIT_PRIVATE, seen, &timeout);
  }
  sleeping_.fetch_sub(1, std::memory_order_seq_cst);
}

}  // namespace cosmos
