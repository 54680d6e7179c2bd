#pragma once
// A single-producer/single-consumer lock-free ring of fixed capacity: the one way the
// real-time loop hands work to other threads without blocking, locking or allocating. Every
// slot is constructed once, up front; the producer writes a slot in place (try_begin_push,
// fill, commit_push) and the consumer reads it in place (try_front, use, pop), so passing a
// Profile never copies or allocates as long as the owner reserved each slot's buffers
// beforehand (the init callback or for_each_slot).
//
// Exactly one thread may call the producer functions and exactly one the consumer functions;
// construction and for_each_slot happen before either starts. Any capacity >= 1 works: each
// side keeps its own wrapped slot index, so no modulo or power-of-two mask is needed.
#include <atomic>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace cosmos {

template <typename T>
class SpscRing {
 public:
  explicit SpscRing(std::size_t capacity) : slots_(capacity) { assert(capacity >= 1); }

  // `init(T&)` runs once per slot, e.g. to reserve a profile's sample buffer.
  template <typename Init>
  SpscRing(std::size_t capacity, Init&& init) : SpscRing(capacity) {
    for_each_slot(std::forward<Init>(init));
  }

  SpscRing(const SpscRing&) = delete;
  SpscRing& operator=(const SpscRing&) = delete;

  // Not thread-safe: only before the producer and consumer start.
  template <typename Function>
  void for_each_slot(Function&& function) {
    for (T& slot : slots_) function(slot);
  }

  std::size_t capacity() const noexcept { return slots_.size(); }

  // Producer. The slot to fill, or nullptr when the ring is full. It holds whatever an earlier
  // element left there (buffers keep their capacity): overwrite every field that matters.
  T* try_begin_push() noexcept {
    const std::uint64_t tail = tail_.load(std::memory_order_relaxed);
    if (tail - producer_.cached_head >= slots_.size()) {
      // Acquire: the consumer's reads of the slot about to be reused happened before.
      producer_.cached_head = head_.load(std::memory_order_acquire);
      if (tail - producer_.cached_head >= slots_.size()) return nullptr;
    }
    return &slots_[producer_.write_index];
  }

  // Producer. Publishes the slot returned by the last successful try_begin_push.
  void commit_push() noexcept {
    if (++producer_.write_index == slots_.size()) producer_.write_index = 0;
    // Release: the slot's contents become visible before the consumer sees the new tail.
    tail_.store(tail_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
  }

  // Producer convenience for small types: copies (or moves) the value in; false when full.
  template <typename U>
  bool try_push(U&& value) noexcept(noexcept(std::declval<T&>() = std::declval<U>())) {
    T* slot = try_begin_push();
    if (slot == nullptr) return false;
    *slot = std::forward<U>(value);
    commit_push();
    return true;
  }

  // Consumer. The oldest element, or nullptr when the ring is empty; valid until pop().
  T* try_front() noexcept {
    const std::uint64_t head = head_.load(std::memory_order_relaxed);
    if (consumer_.cached_tail == head) {
      // Acquire: pairs with commit_push, so the slot's contents are complete.
      consumer_.cached_tail = tail_.load(std::memory_order_acquire);
      if (consumer_.cached_tail == head) return nullptr;
    }
    return &slots_[consumer_.read_index];
  }

  // Consumer. Releases the element returned by the last successful try_front.
  void pop() noexcept {
    if (++consumer_.read_index == slots_.size()) consumer_.read_index = 0;
    head_.store(head_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
  }

  // Consumer convenience: copies the oldest element into `out` (assignment, so a reserved
  // `out` does not allocate) and pops it; false when empty.
  bool try_pop(T& out) noexcept(noexcept(out = std::declval<const T&>())) {
    const T* front = try_front();
    if (front == nullptr) return false;
    out = *front;
    pop();
    return true;
  }

  // Either side, or a monitor: exact when called by one side with the other idle, otherwise a
  // snapshot that may be off by the operations in flight.
  std::size_t size() const noexcept {
    const std::uint64_t head = head_.load(std::memory_order_acquire);
    const std::uint64_t tail = tail_.load(std::memory_order_acquire);
    // head is read first and only grows, so tail - head >= 0; it can exceed the capacity
    // when the consumer popped and the producer pushed between the two loads.
    const std::uint64_t count = tail - head;
    return count < slots_.size() ? static_cast<std::size_t>(count) : slots_.size();
  }
  bool empty() const noexcept { return size() == 0; }

 private:
  // One line per writer so that the producer's and consumer's stores never invalidate each
  // other's lines (false sharing). 64 bytes is the line of every x86-64 and most ARM cores;
  // std::hardware_destructive_interference_size is avoided because GCC warns that its value
  // may differ between compilation units.
  static constexpr std::size_t kCacheLineBytes = 64;

  // Element counts since construction (never wrap in practice: 2^64 elements), written by
  // one side and read by the other.
  alignas(kCacheLineBytes) std::atomic<std::uint64_t> tail_{0};
  alignas(kCacheLineBytes) std::atomic<std::uint64_t> head_{0};
  // Each side's private state, on its own line: the wrapped slot index and the last value
  // seen of the other side's count, which spares reading the shared line on most calls.
  struct alignas(kCacheLineBytes) ProducerState {
    std::size_t write_index = 0;
    std::uint64_t cached_head = 0;
  } producer_;
  struct alignas(kCacheLineBytes) ConsumerState {
    std::size_t read_index = 0;
    std::uint64_t cached_tail = 0;
  } consumer_;
  std::vector<T> slots_;
};

}  // namespace cosmos
