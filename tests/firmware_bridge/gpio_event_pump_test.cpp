// The GPIO event pump against file descriptors that carry gpio-cdev's v1 event records (the
// struct gpioevent_data libgpiod reads), written into pipes: edges of several lines come out
// in time order, far more of them than the kernel's 16-event FIFO while nobody polls, time
// moves on while the lines are quiet, a requested read answers at once, and an event not stamped
// with CLOCK_MONOTONIC stops the pump with one line naming the input.
#include "firmware_bridge/gpio_event_pump.hpp"

#include <gtest/gtest.h>
#include <linux/gpio.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

#include "firmware_bridge/kernel_timestamp.hpp"

namespace cosmos {
namespace {

struct EventPipe {
  int fds[2] = {-1, -1};
  EventPipe() { EXPECT_EQ(::pipe(fds), 0); }
  ~EventPipe() {
    ::close(fds[0]);
    ::close(fds[1]);
  }
  void write_event(std::int64_t t_ns, bool rising) const {
    gpioevent_data event{};
    event.timestamp = static_cast<std::uint64_t>(t_ns);
    event.id = rising ? GPIOEVENT_EVENT_RISING_EDGE : GPIOEVENT_EVENT_FALLING_EDGE;
    ASSERT_EQ(::write(fds[1], &event, sizeof event), static_cast<ssize_t>(sizeof event));
  }
};

std::vector<GpioEdge> collect(GpioEventPump& pump, std::size_t wanted) {
  std::vector<GpioEdge> edges;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  GpioEdge edge;
  while (edges.size() < wanted && std::chrono::steady_clock::now() < deadline) {
    pump.wait(10'000'000);
    while (pump.pop(edge)) edges.push_back(edge);
  }
  return edges;
}

TEST(GpioEventPump, HandsOverEdgesOfSeveralLinesInTimeOrder) {
  EventPipe a, b;
  GpioEventPump pump;
  const GpioEventPump::Line lines[] = {{a.fds[0], GpioInput::kEncoderA, false, "encoder_a"},
                                       {b.fds[0], GpioInput::kEncoderB, true, "encoder_b"}};
  // 100 edges per line, interleaved in time, queued line by line as two kernel FIFOs hold
  // them (every edge queued before the pump looks: the order the merger relies on), far more
  // than a FIFO keeps; nobody pops until all are in.
  const std::int64_t t0 = monotonic_now_ns() - 1'000'000'000;
  for (int i = 0; i < 100; ++i) a.write_event(t0 + 20 * i, i % 2 == 0);
  for (int i = 0; i < 100; ++i) b.write_event(t0 + 20 * i + 10, i % 2 == 0);
  ASSERT_TRUE(pump.start(lines, 2)) << pump.error();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const std::vector<GpioEdge> edges = collect(pump, 200);
  ASSERT_EQ(edges.size(), 200u);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    EXPECT_EQ(edges[i].t_ns, t0 + 10 * static_cast<std::int64_t>(i));
    EXPECT_EQ(edges[i].input, i % 2 == 0 ? GpioInput::kEncoderA : GpioInput::kEncoderB);
    // B is active low: its levels are inverted.
    const bool rising = (i / 2) % 2 == 0;
    EXPECT_EQ(edges[i].level, i % 2 == 0 ? rising : !rising);
  }
  EXPECT_EQ(pump.lost_edges(), 0u);
  EXPECT_FALSE(pump.failed());
  pump.stop();
  EXPECT_FALSE(pump.running());
}

TEST(GpioEventPump, TimeMovesOnWhileTheLinesAreQuiet) {
  EventPipe a;
  GpioEventPump pump;
  const GpioEventPump::Line lines[] = {{a.fds[0], GpioInput::kPhotoEye, false, "photo_eye"}};
  ASSERT_TRUE(pump.start(lines, 1));
  const std::int64_t before = pump.known_until_ns();
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_GT(pump.known_until_ns(), before + 20'000'000);
  EXPECT_LE(pump.known_until_ns(), monotonic_now_ns());
}

TEST(GpioEventPump, ARequestedCutWakesTheConsumerWithTheLinesReadPastTheRequest) {
  EventPipe a;
  GpioEventPump pump;
  const GpioEventPump::Line lines[] = {{a.fds[0], GpioInput::kEncoderA, false, "encoder_a"}};
  ASSERT_TRUE(pump.start(lines, 1));
  // No edge ever comes, and idle cuts wake nobody: only the answer to the request ends the
  // (minute-long) wait.
  for (int k = 0; k < 3; ++k) {
    const std::int64_t asked_ns = monotonic_now_ns();
    pump.request_cut();
    pump.wait(60'000'000'000);
    EXPECT_GE(pump.known_until_ns(), asked_ns);
  }
  GpioEdge edge;
  EXPECT_FALSE(pump.pop(edge));
  EXPECT_FALSE(pump.failed());
}

TEST(GpioEventPump, EventsNotOnTheMonotonicClockStopItWithTheInputNamed) {
  EventPipe a;
  GpioEventPump pump;
  const GpioEventPump::Line lines[] = {{a.fds[0], GpioInput::kEncoderA, false, "encoder_a"}};
  ASSERT_TRUE(pump.start(lines, 1));
  a.write_event(monotonic_now_ns() + 3'600'000'000'000, true);  // an hour ahead: REALTIME
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!pump.failed() && std::chrono::steady_clock::now() < deadline) pump.wait(10'000'000);
  ASSERT_TRUE(pump.failed());
  EXPECT_EQ(pump.error(),
            "encoder_a: event time stamps are not CLOCK_MONOTONIC (kernel older than 5.7?)");
  GpioEdge edge;
  EXPECT_FALSE(pump.pop(edge));
}

}  // namespace
}  // namespace cosmos
