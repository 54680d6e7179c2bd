#include "firmware_bridge/gpio_input_decoder.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "firmware_bridge/edge_event_merger.hpp"

namespace cosmos {
namespace {

constexpr std::int64_t kMs = 1'000'000;

// Edges of a forward-moving quadrature encoder: one every quarter period from t0_ns.
std::vector<GpioEdge> encoder_edges(int counts, std::int64_t t0_ns, std::int64_t quarter_ns) {
  std::vector<GpioEdge> edges;
  bool a = false;
  bool b = false;
  for (int i = 1; i <= counts; ++i) {
    const int phase = i % 4;
    const bool next_a = phase == 1 || phase == 2;
    const bool next_b = phase == 2 || phase == 3;
    const std::int64_t t = t0_ns + i * quarter_ns;
    if (next_a != a) edges.push_back({t, GpioInput::kEncoderA, next_a});
    if (next_b != b) edges.push_back({t, GpioInput::kEncoderB, next_b});
    a = next_a;
    b = next_b;
  }
  return edges;
}

TEST(EdgeEventMerger, RestoresTimeOrderAcrossLinesUpToTheCut) {
  EdgeEventMerger merger;
  // Read line by line, as poll_inputs does: all of A's queue, then B's, then the eye's.
  for (const std::int64_t t : {10, 30, 50, 70}) merger.push({t, GpioInput::kEncoderA, true});
  for (const std::int64_t t : {20, 40, 60}) merger.push({t, GpioInput::kEncoderB, true});
  merger.push({35, GpioInput::kPhotoEye, true});
  std::vector<std::int64_t> order;
  merger.drain(55, [&](const GpioEdge& e) { order.push_back(e.t_ns); });
  EXPECT_EQ(order, (std::vector<std::int64_t>{10, 20, 30, 35, 40, 50}));
  EXPECT_EQ(merger.held(), 2u);  // 60 and 70 wait: a 56 on another line may not be read yet
  merger.push({65, GpioInput::kPhotoEye, false});
  order.clear();
  merger.drain(100, [&](const GpioEdge& e) { order.push_back(e.t_ns); });
  EXPECT_EQ(order, (std::vector<std::int64_t>{60, 65, 70}));
}

TEST(EdgeEventMerger, FullRingRefusesAndCounts) {
  EdgeEventMerger merger;
  for (std::size_t i = 0; i < EdgeEventMerger::kCapacityPerInput; ++i) {
    ASSERT_TRUE(merger.push({static_cast<std::int64_t>(i), GpioInput::kEncoderA, i % 2 == 0}));
  }
  EXPECT_FALSE(merger.push({1000, GpioInput::kEncoderA, true}));
  EXPECT_EQ(merger.overflowed(), 1u);
  EXPECT_TRUE(merger.push({1000, GpioInput::kEncoderB, true}));
}

// The photo-eye transition carries the encoder count at its edge, exactly, although the
// debouncer decides only milliseconds (hundreds of encoder counts) later and the kernel
// queues deliver each line's events separately.
TEST(GpioInputDecoder, PartArrivalCarriesTheEncoderCountAtItsEdge) {
  GpioInputParameters parameters;
  parameters.photo_eye = {1 * kMs, 5 * kMs, 20 * kMs};
  GpioInputDecoder decoder(parameters);
  decoder.reset(false, false, false, 0);
  EdgeEventMerger merger;

  std::vector<GpioEdge> edges = encoder_edges(4000, 0, 10'000);  // 100 counts per ms
  // The part's leading edge at 12.345 ms, bouncing once.
  edges.push_back({12'345'000, GpioInput::kPhotoEye, true});
  edges.push_back({12'400'000, GpioInput::kPhotoEye, false});
  edges.push_back({12'500'000, GpioInput::kPhotoEye, true});
  // Polls every 0.5 ms. Each reads the lines one after the other, and events up to 30 µs
  // past the cut have already arrived by then: they must wait for the next poll.
  constexpr std::int64_t kLateNs = 30'000;
  std::int64_t previous_cut = -kLateNs - 1;  // the first poll takes everything up to its cut
  for (std::int64_t cut = kMs / 2; cut <= 40 * kMs; cut += kMs / 2) {
    for (const GpioInput input :
         {GpioInput::kEncoderA, GpioInput::kEncoderB, GpioInput::kPhotoEye}) {
      for (const GpioEdge& e : edges) {
        if (e.input == input && e.t_ns > previous_cut + kLateNs && e.t_ns <= cut + kLateNs) {
          ASSERT_TRUE(merger.push(e));
        }
      }
    }
    merger.drain(cut, [&](const GpioEdge& e) { decoder.on_edge(e); });
    decoder.advance_to(cut);
    previous_cut = cut;
  }
  EXPECT_EQ(decoder.encoder().ticks, 4000);
  EXPECT_EQ(decoder.encoder().invalid_transitions, 0u);
  EXPECT_TRUE(decoder.part_present());
  PhotoEyeEvent event;
  ASSERT_TRUE(decoder.next_photo_eye_event(event));
  EXPECT_TRUE(event.present);
  EXPECT_EQ(event.t_ns, 12'345'000);
  EXPECT_EQ(event.encoder_ticks, 1234);  // encoder edges every 10 µs, the 1234th at 12.340 ms
  EXPECT_FALSE(decoder.next_photo_eye_event(event));
}

TEST(GpioInputDecoder, TransitionsQueueUntilReadAndOverflowIsCounted) {
  GpioInputDecoder decoder;  // no filtering: each edge is a transition
  decoder.reset(false, false, false, 0);
  const std::int64_t transitions = GpioInputDecoder::kEventCapacity + 3;
  for (std::int64_t i = 0; i < transitions; ++i)
    decoder.on_edge({100 * (i + 1), GpioInput::kPhotoEye, i % 2 == 0});
  EXPECT_EQ(decoder.lost_photo_eye_events(), 3u);
  PhotoEyeEvent event;
  std::size_t read = 0;
  while (decoder.next_photo_eye_event(event)) {
    EXPECT_EQ(event.present, read % 2 == 0);
    EXPECT_EQ(event.t_ns, static_cast<std::int64_t>(100 * (read + 1)));
    ++read;
  }
  EXPECT_EQ(read, GpioInputDecoder::kEventCapacity);
}

}  // namespace
}  // namespace cosmos
