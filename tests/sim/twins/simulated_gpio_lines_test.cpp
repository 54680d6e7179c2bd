// The simulated GPIO lines: the belt's encoder edges through the project's decoder count
// exactly the ticks the belt advanced, in quadrature and step mode; the photo eye reports a
// part at each part's boundaries with the encoder count there; outputs are recorded; the
// lines are deterministic and poll without allocating.
#include "sim/twins/simulated_gpio_lines.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/common/allocation_counter.hpp"
#include "tests/sim/twins/twin_test_conveyor.hpp"

namespace cosmos {
namespace {

using testing::simulated_gpio;
using testing::twin_test_conveyor;

// Every photo-eye event of the whole stream, the clock moved one frame per poll.
std::vector<PhotoEyeEvent> run_stream(const SimulatedConveyor& conveyor, SimulatedBeltClock& clock,
                                      SimulatedGpioLines& gpio) {
  clock.rewind();
  EXPECT_EQ(gpio.start(), GpioStatus::kOk);
  std::vector<PhotoEyeEvent> events;
  for (std::int64_t k = 1; k <= conveyor.last_profile(); ++k) {
    clock.advance_to_frame(k);
    EXPECT_EQ(gpio.poll_inputs(0), GpioStatus::kOk);
    EXPECT_EQ(gpio.encoder().ticks, clock.ticks_of_frame(k));
    PhotoEyeEvent event;
    while (gpio.next_photo_eye_event(event)) events.push_back(event);
  }
  EXPECT_EQ(gpio.stop(), GpioStatus::kOk);
  return events;
}

TEST(SimulatedGpioLines, EncoderCountIsTheTicksTheBeltAdvanced) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  SimulatedGpioLines gpio(*conveyor, clock, simulated_gpio());
  ASSERT_EQ(gpio.start(), GpioStatus::kOk);
  EXPECT_EQ(gpio.poll_inputs(0), GpioStatus::kTimeout);  // the belt has not moved
  EXPECT_EQ(gpio.encoder().ticks, 0);
  clock.advance_to_frame(1);
  ASSERT_EQ(gpio.poll_inputs(0), GpioStatus::kOk);
  EXPECT_EQ(gpio.encoder().ticks, 4);
  EXPECT_EQ(gpio.encoder().last_step_t_ns, 400'000);  // the fourth tick falls on frame 1
  // 250 frames at once: far more edges than one kernel FIFO read, decoded in batches.
  clock.advance_to_frame(251);
  ASSERT_EQ(gpio.poll_inputs(0), GpioStatus::kOk);
  const EncoderReading reading = gpio.encoder();
  EXPECT_EQ(reading.ticks, 1004);
  EXPECT_EQ(reading.last_step_t_ns, 251 * 400'000);
  EXPECT_EQ(reading.invalid_transitions, 0u);
  EXPECT_EQ(reading.ignored_edges, 0u);
  EXPECT_EQ(reading.reversals, 0u);
  EXPECT_EQ(gpio.decoder().encoder_counts().steps, 1004u);

  // A restart counts from 0 where the belt is, as a real encoder's lines requested anew.
  ASSERT_EQ(gpio.stop(), GpioStatus::kOk);
  ASSERT_EQ(gpio.start(), GpioStatus::kOk);
  clock.advance_to_frame(261);
  ASSERT_EQ(gpio.poll_inputs(0), GpioStatus::kOk);
  EXPECT_EQ(gpio.encoder().ticks, 40);
  EXPECT_EQ(gpio.encoder().invalid_transitions, 0u);
}

TEST(SimulatedGpioLines, StepModeCountsOnePulsePerTick) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  GpioConfig config = simulated_gpio();
  config.encoder_mode = EncoderMode::kStep;
  SimulatedGpioLines gpio(*conveyor, clock, config);
  ASSERT_EQ(gpio.start(), GpioStatus::kOk);
  for (std::int64_t k = 1; k <= 100; ++k) {
    clock.advance_to_frame(k);
    ASSERT_EQ(gpio.poll_inputs(0), GpioStatus::kOk);
    ASSERT_EQ(gpio.encoder().ticks, 4 * k);
  }
  EXPECT_EQ(gpio.encoder().invalid_transitions, 0u);
}

TEST(SimulatedGpioLines, PhotoEyeReportsEachPartAtItsBoundaries) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  SimulatedGpioLines gpio(*conveyor, clock, simulated_gpio());
  const std::vector<PhotoEyeEvent> events = run_stream(*conveyor, clock, gpio);
  const std::vector<PlacedSimPart>& parts = conveyor->placed_parts();
  ASSERT_EQ(events.size(), 2 * parts.size());
  const double mm_per_tick = parameters.encoder_mm_per_tick;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    SCOPED_TRACE(parts[i].name);
    const PhotoEyeEvent& arrival = events[2 * i];
    const PhotoEyeEvent& departure = events[2 * i + 1];
    ASSERT_TRUE(arrival.present);
    ASSERT_FALSE(departure.present);
    // The beam (y = 0) meets the box's downstream face at the arrival's count, and its
    // upstream face has passed it at the departure's.
    const double arrival_belt_mm = arrival.encoder_ticks * mm_per_tick;
    const double departure_belt_mm = departure.encoder_ticks * mm_per_tick;
    EXPECT_GE(arrival_belt_mm + parts[i].bounds_mm.max().y(), -1e-9);
    EXPECT_LT(arrival_belt_mm + parts[i].bounds_mm.max().y(), mm_per_tick);
    EXPECT_GT(departure_belt_mm + parts[i].bounds_mm.min().y(), 0.0);
    EXPECT_LE(departure_belt_mm + parts[i].bounds_mm.min().y(), mm_per_tick + 1e-9);
    // So it spans the part's profiles: the first exposed less than a profile after arrival.
    const std::int64_t first_tick = parameters.encoder_ticks_of_profile(parts[i].first_profile);
    EXPECT_GE(first_tick, arrival.encoder_ticks);
    EXPECT_LT(first_tick, arrival.encoder_ticks + parameters.encoder_ticks_per_profile);
    EXPECT_EQ(arrival.t_ns, clock.tick_time_ns(arrival.encoder_ticks));
    EXPECT_EQ(departure.t_ns, clock.tick_time_ns(departure.encoder_ticks));
  }
  EXPECT_EQ(gpio.decoder().photo_eye_counts().parts, parts.size());
  EXPECT_EQ(gpio.decoder().lost_photo_eye_events(), 0u);
  EXPECT_FALSE(gpio.part_present());

  // Deterministic: the same stream again gives the same events.
  const std::vector<PhotoEyeEvent> again = run_stream(*conveyor, clock, gpio);
  ASSERT_EQ(again.size(), events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(again[i].encoder_ticks, events[i].encoder_ticks);
    EXPECT_EQ(again[i].t_ns, events[i].t_ns);
  }
}

TEST(SimulatedGpioLines, OutputsAreRecordedWithTheBeltsTime) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  SimulatedGpioLines gpio(*conveyor, clock, simulated_gpio());
  EXPECT_EQ(gpio.set_output(GpioOutput::kLaserEnable, true), GpioStatus::kWrongState);
  EXPECT_EQ(gpio.last_error(), "simulated GPIO: set_output: lines not started");
  EXPECT_EQ(gpio.poll_inputs(0), GpioStatus::kWrongState);
  ASSERT_EQ(gpio.start(), GpioStatus::kOk);
  ASSERT_EQ(gpio.set_output(GpioOutput::kLaserEnable, true), GpioStatus::kOk);
  clock.advance_to_frame(10);
  ASSERT_EQ(gpio.set_output(GpioOutput::kResultReady, true), GpioStatus::kOk);
  clock.advance_to_frame(11);
  ASSERT_EQ(gpio.set_output(GpioOutput::kResultReady, false), GpioStatus::kOk);
  EXPECT_TRUE(gpio.output_active(GpioOutput::kLaserEnable));
  EXPECT_FALSE(gpio.output_active(GpioOutput::kResultReady));
  EXPECT_EQ(gpio.activations(GpioOutput::kResultReady), 1u);
  // stop() drives the laser off, as the real lines do before releasing them.
  ASSERT_EQ(gpio.stop(), GpioStatus::kOk);
  EXPECT_FALSE(gpio.output_active(GpioOutput::kLaserEnable));
  const std::vector<OutputWrite>& writes = gpio.output_writes();
  ASSERT_EQ(writes.size(), 4u);
  EXPECT_EQ(writes[0].output, GpioOutput::kLaserEnable);
  EXPECT_TRUE(writes[0].active);
  EXPECT_EQ(writes[0].frame, 0);
  EXPECT_EQ(writes[1].output, GpioOutput::kResultReady);
  EXPECT_EQ(writes[1].t_ns, 10 * 400'000);
  EXPECT_EQ(writes[2].frame, 11);
  EXPECT_EQ(writes[3].output, GpioOutput::kLaserEnable);
  EXPECT_FALSE(writes[3].active);
  EXPECT_EQ(writes[3].frame, 11);
}

TEST(SimulatedGpioLines, PollAndOutputsAllocateNothing) {
  const ScannerParameters parameters;
  const auto conveyor = twin_test_conveyor(parameters);
  SimulatedBeltClock clock(parameters);
  SimulatedGpioLines gpio(*conveyor, clock, simulated_gpio());
  ASSERT_EQ(gpio.start(), GpioStatus::kOk);
  std::uint64_t allocations = 0;
  int transitions = 0;
  for (std::int64_t k = 1; k <= conveyor->last_profile(); ++k) {
    clock.advance_to_frame(k);
    const std::uint64_t before = test::allocations_on_this_thread();
    gpio.poll_inputs(0);
    PhotoEyeEvent event;
    while (gpio.next_photo_eye_event(event)) ++transitions;
    gpio.set_output(GpioOutput::kResultReady, k % 2 == 0);
    allocations += test::allocations_on_this_thread() - before;
  }
  EXPECT_EQ(transitions, 6);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace cosmos
