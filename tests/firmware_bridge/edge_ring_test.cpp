// The ring that carries decoded-in-order GPIO edges from the pump's thread to the loop: order
// kept, a full ring drops and counts, and a producer and a consumer thread lose nothing.
#include "firmware_bridge/edge_ring.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace cosmos {
namespace {

TEST(EdgeRing, KeepsOrderAndCountsWhatDidNotFit) {
  EdgeRing ring(3);  // rounded up to 4
  EXPECT_EQ(ring.capacity(), 4u);
  for (int i = 0; i < 6; ++i) ring.push({i, GpioInput::kEncoderA, i % 2 == 0});
  EXPECT_EQ(ring.dropped(), 2u);
  GpioEdge edge;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(ring.pop(edge));
    EXPECT_EQ(edge.t_ns, i);
    EXPECT_EQ(edge.level, i % 2 == 0);
  }
  EXPECT_FALSE(ring.pop(edge));
  ring.push({10, GpioInput::kPhotoEye, true});
  ring.clear();
  EXPECT_FALSE(ring.pop(edge));
}

TEST(EdgeRing, OneProducerOneConsumerLoseNothing) {
  EdgeRing ring(64);
  constexpr int kEdges = 200'000;
  std::thread producer([&] {
    for (int i = 0; i < kEdges; ++i) {
      while (!ring.push({i, GpioInput::kEncoderB, false})) std::this_thread::yield();
    }
  });
  std::int64_t expected = 0;
  GpioEdge edge;
  while (expected < kEdges) {
    if (ring.pop(edge)) {
      ASSERT_EQ(edge.t_ns, expected);
      ++expected;
    }
  }
  producer.join();
  EXPECT_EQ(expected, kEdges);
}

}  // namespace
}  // namespace cosmos
