// The acquisition-thread calls of the hardware adapters allocate nothing once started (the
// real-time discipline: no allocation per profile, so no page fault or allocator lock can
// delay a line): camera frame dequeue/requeue, including timeouts, drops and corrupted
// frames, and the GPIO edge decoding chain.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "firmware_bridge/edge_event_merger.hpp"
#include "firmware_bridge/gpio_input_decoder.hpp"
#include "firmware_bridge/v4l2_camera.hpp"
#include "tests/common/allocation_counter.hpp"
#include "tests/firmware_bridge/fake_video_device.hpp"

namespace cosmos {
namespace {

using test::allocations_on_this_thread;

int* volatile escaped = nullptr;  // keeps the compiler from eliding the allocation below

TEST(HotPathAllocation, CounterSeesAnAllocation) {
  const std::uint64_t before = allocations_on_this_thread();
  escaped = new int(1);
  delete escaped;
  EXPECT_EQ(allocations_on_this_thread() - before, 1u);
}

TEST(HotPathAllocation, CameraFrameLoopAllocatesNothing) {
  test::FakeVideoDevice device;
  CameraConfig config;
  config.width_px = 128;
  config.height_px = 16;
  V4l2Camera camera(config, device);
  ASSERT_EQ(camera.start(), CameraStatus::kOk);
  for (std::uint32_t s = 0; s < 300; ++s) {
    if (s % 50 == 7) device.time_out();
    if (s % 40 == 3) continue;  // a dropped frame
    device.deliver(s, 1000 * s, s % 70 == 11 ? V4L2_BUF_FLAG_ERROR : 0);
  }
  device.record_calls = false;

  const std::uint64_t before = allocations_on_this_thread();
  int frames = 0;
  FrameView frame;
  while (!device.script.empty()) {
    const CameraStatus status = camera.next_frame(1000, frame);
    if (status == CameraStatus::kOk) {
      ++frames;
      ASSERT_EQ(camera.release_frame(frame), CameraStatus::kOk);
    }
  }
  EXPECT_EQ(allocations_on_this_thread() - before, 0u);
  EXPECT_GT(frames, 250);
  EXPECT_GT(camera.stats().dropped_frames, 0u);
  EXPECT_GT(camera.stats().timeouts, 0u);
  EXPECT_GT(camera.stats().corrupted_frames, 0u);
}

TEST(HotPathAllocation, GpioEdgeDecodingAllocatesNothing) {
  GpioInputParameters parameters;
  parameters.encoder.debounce_ns = 500;
  parameters.photo_eye = {1'000'000, 2'000'000, 5'000'000};
  GpioInputDecoder decoder(parameters);
  decoder.reset(false, false, false, 0);
  EdgeEventMerger merger;
  std::vector<GpioEdge> edges;
  bool a = false;
  bool b = false;
  for (int i = 1; i <= 20'000; ++i) {
    const int phase = i % 4;
    const bool next_a = phase == 1 || phase == 2;
    const bool next_b = phase == 2 || phase == 3;
    if (next_a != a) edges.push_back({i * 10'000LL, GpioInput::kEncoderA, next_a});
    if (next_b != b) edges.push_back({i * 10'000LL, GpioInput::kEncoderB, next_b});
    a = next_a;
    b = next_b;
    if (i % 3000 == 0)
      edges.push_back({i * 10'000LL + 1, GpioInput::kPhotoEye, (i / 3000) % 2 == 1});
  }

  const std::uint64_t before = allocations_on_this_thread();
  std::size_t next = 0;
  PhotoEyeEvent event;
  int transitions = 0;
  for (std::int64_t cut = 100'000; next < edges.size(); cut += 100'000) {
    while (next < edges.size() && edges[next].t_ns <= cut) merger.push(edges[next++]);
    merger.drain(cut, [&](const GpioEdge& e) { decoder.on_edge(e); });
    decoder.advance_to(cut);
    while (decoder.next_photo_eye_event(event)) ++transitions;
  }
  EXPECT_EQ(allocations_on_this_thread() - before, 0u);
  EXPECT_EQ(decoder.encoder().ticks, 20'000);
  EXPECT_EQ(transitions, 6);
}

}  // namespace
}  // namespace cosmos
