#pragma once
// Settings of the work cell's digital I/O (the `gpio:` block of
// config/hardware-example.yaml): which GPIO chip, and which of its lines carry the conveyor
// encoder, the part-present photo eye and the three outputs. A line is named either by its
// name (as the device tree or ACPI labels it: stable across kernels) or by its offset on
// the chip; an unconfigured line is simply not used (only the encoder is required).
#include <cstdint>
#include <string>

#include "firmware_bridge/quadrature_decoder.hpp"

namespace cosmos {

struct GpioLineRef {
  std::string name;  // preferred when set
  int offset = -1;   // used when name is empty
  // The line's electrical sense is inverted (sinking outputs, NPN photo eyes). Applied in
  // software to edges and values alike, so edge types never depend on kernel flags.
  bool active_low = false;

  bool configured() const noexcept { return !name.empty() || offset >= 0; }
};

struct GpioConfig {
  // Anything gpiod_chip_open_lookup understands: "gpiochip0", "/dev/gpiochip0", "0", a label.
  std::string chip = "gpiochip0";
  // The name the lines are requested under, shown by gpioinfo: who holds a busy line.
  std::string consumer = "cosmos-cell";

  GpioLineRef encoder_a;
  GpioLineRef encoder_b;  // quadrature: required; step mode: optional direction line
  EncoderMode encoder_mode = EncoderMode::kQuadrature;
  std::int64_t encoder_debounce_ns = 0;

  GpioLineRef photo_eye;  // level after active_low: 1 = beam interrupted = part present
  std::int64_t photo_eye_debounce_ns = 1'000'000;
  std::int64_t photo_eye_min_on_ns = 5'000'000;
  std::int64_t photo_eye_min_off_ns = 20'000'000;

  GpioLineRef laser_enable;
  GpioLineRef camera_trigger;
  GpioLineRef result_ready;
};

}  // namespace cosmos
