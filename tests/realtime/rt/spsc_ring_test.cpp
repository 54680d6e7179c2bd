// The single-producer/single-consumer ring: full and empty, wrap-around, in-place slots, and
// a million sequence numbers passed between two threads in order with none lost.
#include "realtime/rt/spsc_ring.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <thread>
#include <vector>

namespace cosmos {
namespace {

TEST(SpscRing, EmptyAndFull) {
  SpscRing<int> ring(3);
  EXPECT_EQ(ring.capacity(), 3u);
  EXPECT_TRUE(ring.empty());
  EXPECT_EQ(ring.try_front(), nullptr);
  int out = -1;
  EXPECT_FALSE(ring.try_pop(out));
  EXPECT_EQ(out, -1);

  EXPECT_TRUE(ring.try_push(10));
  EXPECT_TRUE(ring.try_push(11));
  EXPECT_TRUE(ring.try_push(12));
  EXPECT_EQ(ring.size(), 3u);
  EXPECT_FALSE(ring.try_push(13));
  EXPECT_EQ(ring.try_begin_push(), nullptr);

  ASSERT_NE(ring.try_front(), nullptr);
  EXPECT_EQ(*ring.try_front(), 10);
  ring.pop();
  EXPECT_EQ(ring.size(), 2u);
  EXPECT_TRUE(ring.try_push(13));  // the freed slot is usable again
  EXPECT_FALSE(ring.try_push(14));

  for (int expected : {11, 12, 13}) {
    ASSERT_TRUE(ring.try_pop(out));
    EXPECT_EQ(out, expected);
  }
  EXPECT_TRUE(ring.empty());
  EXPECT_FALSE(ring.try_pop(out));
}

TEST(SpscRing, CapacityOneAlternates) {
  SpscRing<int> ring(1);
  for (int k = 0; k < 5; ++k) {
    ASSERT_TRUE(ring.try_push(k));
    EXPECT_FALSE(ring.try_push(100 + k));
    int out = -1;
    ASSERT_TRUE(ring.try_pop(out));
    EXPECT_EQ(out, k);
  }
}

TEST(SpscRing, WrapsAroundManyTimesKeepingOrder) {
  SpscRing<std::int64_t> ring(5);  // not a power of two on purpose
  std::int64_t next_in = 0, next_out = 0;
  // Uneven bursts so that the full and empty points fall on every slot index.
  for (int round = 0; round < 200; ++round) {
    const int pushes = 1 + round % 5;
    for (int k = 0; k < pushes && ring.try_push(next_in); ++k) ++next_in;
    const int pops = 1 + (round * 3) % 4;
    std::int64_t out = -1;
    for (int k = 0; k < pops && ring.try_pop(out); ++k) {
      ASSERT_EQ(out, next_out);
      ++next_out;
    }
    ASSERT_EQ(ring.size(), static_cast<std::size_t>(next_in - next_out));
  }
  EXPECT_GT(next_in, 400);  // well past 5 slots: many wrap-arounds
}

TEST(SpscRing, SlotsAreFilledInPlaceAndKeepTheirBuffers) {
  SpscRing<std::vector<float>> ring(4, [](std::vector<float>& slot) { slot.reserve(640); });
  std::vector<const float*> buffers;
  ring.for_each_slot([&buffers](std::vector<float>& slot) {
    EXPECT_GE(slot.capacity(), 640u);
    buffers.push_back(slot.data());
  });
  for (int k = 0; k < 10; ++k) {
    std::vector<float>* slot = ring.try_begin_push();
    ASSERT_NE(slot, nullptr);
    slot->assign(640, static_cast<float>(k));  // within capacity: no reallocation
    ring.commit_push();
    const std::vector<float>* front = ring.try_front();
    ASSERT_NE(front, nullptr);
    EXPECT_EQ(front->data(), buffers[k % 4]);
    EXPECT_EQ((*front)[639], static_cast<float>(k));
    ring.pop();
  }
}

TEST(SpscRing, TwoThreadsPassAMillionSequenceNumbersInOrder) {
  constexpr std::uint64_t kCount = 1'000'000;
  SpscRing<std::uint64_t> ring(1024);
  std::thread producer([&ring] {
    for (std::uint64_t sequence = 0; sequence < kCount;) {
      std::uint64_t* slot = ring.try_begin_push();
      if (slot == nullptr) {
        std::this_thread::yield();
        continue;
      }
      *slot = sequence++;
      ring.commit_push();
    }
  });
  std::uint64_t expected = 0, out_of_order = 0, sum = 0;
  while (expected < kCount) {
    const std::uint64_t* front = ring.try_front();
    if (front == nullptr) {
      std::this_thread::yield();
      continue;
    }
    if (*front != expected) ++out_of_order;
    sum += *front;
    ++expected;
    ring.pop();
  }
  producer.join();
  EXPECT_EQ(out_of_order, 0u);
  EXPECT_EQ(sum, kCount * (kCount - 1) / 2);
  EXPECT_TRUE(ring.empty());
}

}  // namespace
}  // namespace cosmos
