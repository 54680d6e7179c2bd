#pragma once
// The simulated twin of the work cell's digital I/O (firmware_bridge/gpio.hpp), after
// ros2_control's mock hardware: the quadrature encoder and the photo eye of the simulated
// conveyor, decoded by the project's own decoder, and outputs that are recorded for tests.
//
// Inputs: the belt advances scanner.encoder_mm_per_tick per tick and reaches tick
// k · encoder_ticks_per_profile at camera frame k (SimulatedBeltClock). poll_inputs() emits
// every edge since the last poll up to the clock's "now" — quadrature A/B in Gray order with
// A leading (counting up), or in step mode a pulse on A per tick with B, the direction, held
// low — and the photo eye's edges, each stamped with its tick's time. They go through the
// same EdgeEventMerger and GpioInputDecoder as the libgpiod lines' kernel events (in
// batches no larger than a kernel FIFO read), so the encoder count, the debouncing and the
// photo-eye events with their encoder counts are the real decoder's. The count starts at 0
// at start(), where the lines' levels are read as the real lines' are.
//
// Photo eye: a beam across the belt at y = photo_eye_y_mm (scanner frame), interrupted while
// a placed part's bounding box spans it. At the default 0 the beam lies in the laser sheet,
// so a part is present exactly over the ticks of the profiles that scan it.
//
// Outputs: the simulated chip has every line (encoder A/B, photo eye, laser enable, result
// ready), so set_output() is kOk once started; each write is recorded with
// the clock's time and frame. The line names of a GpioConfig are not used.
//
// Injected faults (sim/source/fault_plan.hpp, by the profile a tick leads up to: ticks
// ((k-1)·n, k·n] of profile k, n = encoder_ticks_per_profile) move the encoder's position
// instead of the belt: stuck, the lines stay quiet; reversed, the position runs back one tick
// per tick (the lines' Gray sequence backwards, which the decoder counts as reversals) and
// forwards from there after it; a glitch loses the first edge of each profile (the decoder
// counts the invalid transitions it causes). The position's lag behind the belt stays after
// the fault, as on a slipping encoder wheel. A bouncing photo eye repeats each of its edges
// twice, its edges a quarter of the debounce time apart.
//
// Deterministic: everything follows from the conveyor and the clock, nothing from the wall
// clock. poll_inputs() and set_output() use preallocated storage: no allocation.
#include <array>
#include <cstdint>
#include <vector>

#include "firmware_bridge/edge_event_merger.hpp"
#include "firmware_bridge/error_line.hpp"
#include "firmware_bridge/gpio.hpp"
#include "firmware_bridge/gpio_config.hpp"
#include "firmware_bridge/gpio_input_decoder.hpp"
#include "sim/source/fault_plan.hpp"
#include "sim/source/simulated_conveyor.hpp"
#include "sim/twins/simulated_belt_clock.hpp"

namespace cosmos {

struct SimulatedGpioSettings {
  double photo_eye_y_mm = 0.0;  // the beam's position along the belt, scanner frame
};

// One set_output() call (or stop() driving an active output inactive).
struct OutputWrite {
  GpioOutput output = GpioOutput::kLaserEnable;
  bool active = false;
  std::int64_t t_ns = 0;   // the clock's time at the write
  std::int64_t frame = 0;  // the clock's frame at the write
};

// The ticks [enter_tick, leave_tick) (belt ticks since frame 0) a part interrupts the beam.
struct BeamInterruption {
  std::int64_t enter_tick = 0;
  std::int64_t leave_tick = 0;
};

class SimulatedGpioLines final : public GpioLines {
 public:
  // Writes kept for output_writes(); later ones are counted in unrecorded_writes().
  static constexpr std::size_t kWriteCapacity = 4096;

  // The conveyor and the clock must outlive the lines.
  SimulatedGpioLines(const SimulatedConveyor& conveyor, const SimulatedBeltClock& clock,
                     const GpioConfig& config, const SimulatedGpioSettings& settings = {},
                     const FaultPlan& faults = FaultPlan{});

  GpioStatus start() noexcept override;
  GpioStatus stop() noexcept override;
  GpioStatus poll_inputs(std::int64_t timeout_ns) noexcept override;
  EncoderReading encoder() const noexcept override { return decoder_.encoder(); }
  // The edges up to the clock's "now" are all there is: no wait.
  GpioStatus encoder_at(std::int64_t t_ns, std::int64_t wait_ns,
                        EncoderAtTime& at) noexcept override;
  bool part_present() const noexcept override { return decoder_.part_present(); }
  bool next_photo_eye_event(PhotoEyeEvent& event) noexcept override {
    return decoder_.next_photo_eye_event(event);
  }
  GpioStatus set_output(GpioOutput output, bool active) noexcept override;
  std::string_view last_error() const noexcept override { return error_.view(); }
  GpioInputHealth input_health() const noexcept override { return decoder_.health(); }

  bool started() const noexcept { return started_; }
  const GpioInputDecoder& decoder() const noexcept { return decoder_; }
  const std::vector<BeamInterruption>& beam_interruptions() const noexcept { return beam_; }
  // The output's level now, and how often it went active.
  bool output_active(GpioOutput output) const noexcept;
  std::uint64_t activations(GpioOutput output) const noexcept;
  const std::vector<OutputWrite>& output_writes() const noexcept { return writes_; }
  std::uint64_t unrecorded_writes() const noexcept { return unrecorded_writes_; }
  void clear_output_writes() noexcept { writes_.clear(); }

 private:
  static constexpr std::size_t kOutputCount = 2;

  struct BeamEdge {
    std::int64_t tick = 0;
    bool present = false;
  };

  // The lines' levels at encoder position `position` (ticks).
  bool level_a(std::int64_t position) const noexcept;
  bool level_b(std::int64_t position) const noexcept;
  // The profile (camera frame) that `tick` leads up to.
  std::int64_t profile_of_tick(std::int64_t tick) const noexcept;
  void push_beam_edge(const BeamEdge& edge) noexcept;
  bool beam_interrupted(std::int64_t tick) const noexcept;
  void push_encoder_edges(std::int64_t tick) noexcept;
  void record(GpioOutput output, bool active) noexcept;

  const SimulatedBeltClock& clock_;
  GpioConfig config_;
  FaultPlan faults_;
  std::int64_t position_ = 0;         // the encoder's position after the last tick emitted
  std::int64_t position_offset_ = 0;  // position − tick: what faults made it lag
  bool step_down_ = false;            // step mode: the direction line's level
  std::vector<BeamInterruption> beam_;
  std::vector<BeamEdge> beam_edges_;  // in tick order
  GpioInputDecoder decoder_;
  EdgeEventMerger merger_;
  bool started_ = false;
  std::int64_t next_tick_ = 1;  // the next tick whose edges are to be emitted
  std::size_t next_beam_edge_ = 0;
  std::array<bool, kOutputCount> outputs_{};
  std::array<std::uint64_t, kOutputCount> activations_{};
  std::vector<OutputWrite> writes_;
  std::uint64_t unrecorded_writes_ = 0;
  ErrorLine error_;
};

}  // namespace cosmos
