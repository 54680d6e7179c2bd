// The wake signal between a ring's producer and its idle consumer: a notify since the
// consumer's look is never slept through, a wait without one ends at its timeout, and a
// hundred thousand items pass from a producer to a consumer that sleeps whenever the ring is
// empty, none lost and none waited for past a notify (a lost wake-up would hang the test for
// the hour of its wait, and ctest would fail it at its timeout).
#include "realtime/rt/wake_signal.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <thread>

#include "realtime/rt/spsc_ring.hpp"

namespace cosmos {
namespace {

constexpr std::int64_t kAnHourNs = 3'600'000'000'000;

TEST(WakeSignal, ANotifySinceTheLookEndsTheWaitAtOnce) {
  WakeSignal signal;
  const std::uint32_t seen = signal.epoch();
  signal.notify();
  EXPECT_NE(signal.epoch(), seen);
  signal.wait(seen, kAnHourNs);  // returns: the epoch moved on before the sleep
}

TEST(WakeSignal, AWaitWithoutNotifyEndsAtItsTimeout) {
  WakeSignal signal;
  const std::uint32_t seen = signal.epoch();
  signal.wait(seen, 1'000'000);
  signal.wait(seen, 0);
  signal.wait(seen, -5);
  EXPECT_EQ(signal.epoch(), seen);
}

TEST(WakeSignal, ASleepingConsumerIsWokenByTheProducer) {
  WakeSignal signal;
  std::atomic<bool> ready{false};
  std::thread consumer([&] {
    for (;;) {
      const std::uint32_t seen = signal.epoch();
      if (ready.load(std::memory_order_acquire)) return;
      signal.wait(seen, kAnHourNs);
    }
  });
  ready.store(true, std::memory_order_release);
  signal.notify();
  consumer.join();
  EXPECT_TRUE(ready.load());
}

TEST(WakeSignal, EveryItemReachesAConsumerThatSleepsWhenTheRingIsEmpty) {
  constexpr std::int64_t kItems = 100'000;
  SpscRing<std::int64_t> ring(8);
  WakeSignal signal;
  std::int64_t received = 0, sum = 0;
  std::thread consumer([&] {
    while (received < kItems) {
      const std::uint32_t seen = signal.epoch();
      std::int64_t item = 0;
      if (ring.try_pop(item)) {
        ++received;
        sum += item;
        continue;
      }
      signal.wait(seen, kAnHourNs);
    }
  });
  for (std::int64_t i = 1; i <= kItems; ++i) {
    while (!ring.try_push(i)) std::this_thread::yield();
    signal.notify();
  }
  consumer.join();
  EXPECT_EQ(received, kItems);
  EXPECT_EQ(sum, kItems * (kItems + 1) / 2);
}

}  // namespace
}  // namespace cosmos
