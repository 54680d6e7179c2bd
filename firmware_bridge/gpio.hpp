#pragma once
// The work cell's digital I/O, as the acquisition loop sees it: the conveyor encoder count,
// part-present transitions from the photo eye (each with the encoder count at the edge), and
// the outputs. Two implementations: LibgpiodLines drives real lines (gpio_lines.hpp);
// SimulatedGpioLines (sim/twins/) emits the simulated conveyor's edges into the same decoder.
//
// The outputs as HardwareSource uses them: laser_enable is on while the source streams;
// result_ready pulses once per result announced to it (a published pose). There is no camera
// trigger: the camera runs free.
#include <cstdint>
#include <string_view>

namespace cosmos {

enum class GpioStatus : std::uint8_t {
  kOk,
  kTimeout,        // no input edge within the wait
  kNotConfigured,  // the output has no line in the config
  kWrongState,     // not started
  kError,          // see last_error()
};

enum class GpioOutput : std::uint8_t { kLaserEnable, kResultReady };

struct EncoderReading {
  std::int64_t ticks = 0;
  std::int64_t last_step_t_ns = 0;  // CLOCK_MONOTONIC
  std::uint64_t invalid_transitions = 0;
  std::uint64_t ignored_edges = 0;
  std::uint64_t reversals = 0;
};

// The encoder count as of an instant (a frame's time stamp).
struct EncoderAtTime {
  std::int64_t ticks = 0;
  // Every edge stamped up to the instant was decoded, and the kept history reaches back to it.
  // Otherwise `ticks` is the best count there was: the edges read by the end of the wait, or
  // the oldest count kept.
  bool settled = false;
};

struct PhotoEyeEvent {
  bool present = false;            // true: a part arrived; false: it left
  std::int64_t t_ns = 0;           // the edge that began it, CLOCK_MONOTONIC
  std::int64_t encoder_ticks = 0;  // encoder count at that edge
};

// What the input decoding could not use, since start(): a loss the loop must count, since a
// lost encoder edge shifts every later pose and a lost photo-eye edge hides a part.
struct GpioInputHealth {
  std::uint64_t edges_lost = 0;         // kernel FIFO or event ring overflow, undelivered events
  std::uint64_t photo_eye_bounces = 0;  // photo-eye edges the debouncer rejected
};

class GpioLines {
 public:
  virtual ~GpioLines() = default;

  // Requests the lines and drives every output inactive (set-up, may allocate).
  virtual GpioStatus start() noexcept = 0;
  // Drives outputs inactive and releases the lines.
  virtual GpioStatus stop() noexcept = 0;

  // Real-time: waits at most timeout_ns for input edges and decodes all that arrived.
  virtual GpioStatus poll_inputs(std::int64_t timeout_ns) noexcept = 0;
  virtual EncoderReading encoder() const noexcept = 0;
  // Real-time: the count as of t_ns (CLOCK_MONOTONIC; the simulated twins' belt clock), after
  // decoding every edge stamped up to t_ns, waiting at most wait_ns for the edges to be read.
  // kError when the lines failed.
  virtual GpioStatus encoder_at(std::int64_t t_ns, std::int64_t wait_ns,
                                EncoderAtTime& at) noexcept = 0;
  virtual bool part_present() const noexcept = 0;
  // Real-time: the oldest undelivered photo-eye transition; false when there is none.
  virtual bool next_photo_eye_event(PhotoEyeEvent& event) noexcept = 0;
  virtual GpioInputHealth input_health() const noexcept = 0;
  // Real-time: active = the output's asserted level (after active_low).
  virtual GpioStatus set_output(GpioOutput output, bool active) noexcept = 0;

  // One line naming the chip/line and the reason of the last failure, empty if none.
  virtual std::string_view last_error() const noexcept = 0;
};

}  // namespace cosmos
