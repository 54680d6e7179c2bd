#pragma once
// The hardware YAML of a real scanner cell (config/hardware-example.yaml): the V4L2 camera,
// the GPIO lines, and how the stripe is found in the camera's frames. The triangulation
// geometry and the profile grid are not here: they are the `scanner:` section of the cell
// configuration (scanner/scanner_config.hpp), shared with the simulated cell, so a simulated and
// a live cell with one cell.yaml produce profiles on the same grid.
//
//   camera:   CameraConfig's visit() keys and frame_timeout_us (HardwareCameraSection)
//   gpio:     GpioConfig's visit() keys; encoder_a is required, encoder_b too in quadrature
//   stripe:   method (centre_of_gravity|gaussian_three_point), threshold,
//             min_peak_intensity, window_half_width_px (ranges in the pixel format's levels)
//   calibration: ScannerCalibration (scanner/scanner_calibration.hpp), what `cosmos calibrate`
//             measured of the camera, the laser plane and the camera's mount; optional
// docs/parameters.md lists the camera and gpio keys with their defaults and ranges.
//
// A line is a name (`ENC_A`), an offset (`17`) or a map {name: ENC_A | offset: 17,
// active_low: true}. Every section and key but gpio.encoder_a (and encoder_b in quadrature
// mode) is optional, with the defaults of firmware_bridge/camera_config.hpp, gpio_config.hpp
// and laser_stripe_extraction.hpp. An unknown key, a wrong type or a value out of range
// throws InputError `file:LINE: section.key: reason` (1-based line).
//
// The simulated twins (sim/twins/, config/hardware-sim.yaml): `camera.device: simulated`
// and `gpio.chip: simulated` together. The simulated chip has every line, so it takes no
// line keys; the rest (format, size, ROI, buffers, encoder mode, debouncing, stripe) means
// what it means for real devices. One simulated without the other is refused: the twins'
// encoder and photo eye follow the simulated camera's conveyor, which a real camera or a
// real encoder knows nothing of.
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "firmware_bridge/camera_config.hpp"
#include "firmware_bridge/gpio_config.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/scanner_calibration.hpp"

namespace cosmos {

// camera.device and gpio.chip of the simulated twins.
inline constexpr std::string_view kSimulatedDevice = "simulated";

struct HardwareConfig {
  std::filesystem::path file;  // where it was read from, for error hints; empty if built in code
  CameraConfig camera;
  GpioConfig gpio;
  // Grey levels of the camera's pixel format. The 8-bit defaults scale to the format's full
  // scale when not given; the saturation level is always the format's full scale.
  StripeExtractionParameters stripe;
  // The measured geometry; what it leaves uncalibrated is the scanner: section's design.
  ScannerCalibration calibration;
  // The watchdog of one wait for a frame: a stalled camera shows as a timeout, not a hang.
  std::int64_t frame_timeout_us = 100'000;

  // Both are, or neither is (read_hardware_config refuses a half-simulated file).
  bool camera_simulated() const { return camera.device == kSimulatedDevice; }
  bool gpio_simulated() const { return gpio.chip == kSimulatedDevice; }
};

// The `camera:` section: the camera's keys and the watchdog of a wait for its frames, which
// the source keeps beside the camera's settings.
struct HardwareCameraSection {
  CameraConfig& camera;
  std::int64_t& frame_timeout_us;

  template <class Visitor>
  void visit(Visitor& v) {
    v.fields(camera);
    v("frame_timeout_us", frame_timeout_us, "the longest wait for a frame, us",
      Range{100, 10'000'000});
  }
};

inline HardwareCameraSection camera_section(HardwareConfig& config) {
  return {config.camera, config.frame_timeout_us};
}

HardwareConfig read_hardware_config(const std::filesystem::path& yaml_path);

}  // namespace cosmos
