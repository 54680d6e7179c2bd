#pragma once
// Settings of the work cell's digital I/O (the `gpio:` block of
// config/hardware-example.yaml): which GPIO chip, and which of its lines carry the conveyor
// encoder, the part-present photo eye and the two outputs (no camera trigger: the camera runs
// free). A line is named either by its name (as the device tree or ACPI labels it: stable
// across kernels) or by its offset on the chip; an unconfigured line is simply not used (only
// the encoder is required). visit() lists the keys (realtime/config/hardware_config.hpp reads
// them; a line's key takes a name, an offset or a map, which that reader handles).
#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "core/parameter_visitor.hpp"
#include "firmware_bridge/quadrature_decoder.hpp"

namespace cosmos {

inline std::span<const ParameterChoice<EncoderMode>> parameter_choices(EncoderMode) {
  static constexpr std::array<ParameterChoice<EncoderMode>, 2> kChoices{
      {{EncoderMode::kQuadrature, "quadrature"}, {EncoderMode::kStep, "step"}}};
  return kChoices;
}

inline constexpr double kMaxGpioMicroseconds = 10'000'000;

struct GpioLineRef {
  std::string name;  // preferred when set
  int offset = -1;   // used when name is empty
  // The line's electrical sense is inverted (sinking outputs, NPN photo eyes). Applied in
  // software to edges and values alike, so edge types never depend on kernel flags.
  bool active_low = false;

  bool configured() const noexcept { return !name.empty() || offset >= 0; }
};

// A line's default as docs/parameters.md shows it: "none" (not configured).
inline std::string parameter_value_text(const GpioLineRef& ref) {
  if (!ref.name.empty()) return "\"" + ref.name + "\"";
  return ref.offset >= 0 ? std::to_string(ref.offset) : "none";
}

struct GpioConfig {
  // Anything gpiod_chip_open_lookup understands: "gpiochip0", "/dev/gpiochip0", "0", a label.
  std::string chip = "gpiochip0";
  // The name the lines are requested under, shown by gpioinfo: who holds a busy line.
  std::string consumer = "cosmos-cell";

  GpioLineRef encoder_a;
  GpioLineRef encoder_b;  // quadrature: required; step mode: optional direction line
  EncoderMode encoder_mode = EncoderMode::kQuadrature;
  std::int64_t encoder_debounce_us = 0;

  GpioLineRef photo_eye;  // level after active_low: 1 = beam interrupted = part present
  std::int64_t photo_eye_debounce_us = 1'000;
  std::int64_t photo_eye_min_on_us = 5'000;
  std::int64_t photo_eye_min_off_us = 20'000;

  GpioLineRef laser_enable;
  GpioLineRef result_ready;

  // How long a frame waits for the encoder's edges up to its time stamp to be read: the
  // event reader thread's latency, or a time stamp the driver puts ahead of the dequeue.
  std::int64_t frame_edges_wait_us = 2'000;

  // The decoders count in nanoseconds (kernel event stamps).
  std::int64_t encoder_debounce_ns() const { return encoder_debounce_us * 1000; }
  std::int64_t photo_eye_debounce_ns() const { return photo_eye_debounce_us * 1000; }
  std::int64_t photo_eye_min_on_ns() const { return photo_eye_min_on_us * 1000; }
  std::int64_t photo_eye_min_off_ns() const { return photo_eye_min_off_us * 1000; }
  std::int64_t frame_edges_wait_ns() const { return frame_edges_wait_us * 1000; }

  template <class Visitor>
  void visit(Visitor& v) {
    v("chip", chip, "GPIO chip: gpiochip0, /dev/gpiochip0, 0 or a label; simulated: the twins");
    v("consumer", consumer, "the name the lines are requested under (gpioinfo shows it)");
    v("encoder_a", encoder_a, "encoder line A (required); quadrature: A, step: the step pulse");
    v("encoder_b", encoder_b,
      "encoder line B (required for quadrature); step: an optional direction level");
    v("encoder_mode", encoder_mode, "quadrature: A and B 90 deg apart; step: pulse + direction");
    v("debounce_us", encoder_debounce_us,
      "encoder edges closer than this to the previous one are bounce, us (0: off)",
      Range{0, kMaxGpioMicroseconds});
    v("photo_eye", photo_eye, "part-present photo eye (1 = beam interrupted)");
    v("photo_eye_debounce_us", photo_eye_debounce_us, "photo-eye bounce time, us",
      Range{0, kMaxGpioMicroseconds});
    v("photo_eye_min_on_us", photo_eye_min_on_us, "shorter beam interruptions are not a part, us",
      Range{0, kMaxGpioMicroseconds});
    v("photo_eye_min_off_us", photo_eye_min_off_us, "shorter gaps do not end a part, us",
      Range{0, kMaxGpioMicroseconds});
    v("laser_enable", laser_enable, "output: on while the source streams");
    v("result_ready", result_ready, "output: pulses once per published result");
    v("frame_edges_wait_us", frame_edges_wait_us,
      "longest wait of a frame for the encoder edges up to its time stamp, us (the count at "
      "that time is the frame's)",
      Range{0, kMaxGpioMicroseconds});
  }
};

}  // namespace cosmos
