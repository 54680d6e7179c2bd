#pragma once
// Settings of the scanner camera (the `camera:` block of config/hardware-example.yaml).
// Defaults describe the designed sensor of triangulation_geometry.hpp: a 1280-column sensor
// read out as a 256-row band around the laser line. visit() lists the keys
// (realtime/config/hardware_config.hpp reads them).
#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "core/parameter_visitor.hpp"
#include "firmware_bridge/pixel_format.hpp"

namespace cosmos {

// The file names of the formats are pixel_format_name's.
inline std::span<const ParameterChoice<PixelFormat>> parameter_choices(PixelFormat) {
  static const std::array<ParameterChoice<PixelFormat>, 4> kChoices = [] {
    std::array<ParameterChoice<PixelFormat>, 4> choices{};
    const PixelFormat formats[] = {PixelFormat::kGrey8, PixelFormat::kY10, PixelFormat::kY12,
                                   PixelFormat::kY16};
    for (std::size_t i = 0; i < choices.size(); ++i)
      choices[i] = {formats[i], pixel_format_name(formats[i])};
    return choices;
  }();
  return kChoices;
}

// The most driver buffers a camera is given (V4l2Camera's buffer table).
inline constexpr int kMaxCameraBuffers = 16;

struct CameraConfig {
  std::string device = "/dev/video0";
  PixelFormat pixel_format = PixelFormat::kGrey8;
  int width_px = 1280;
  int height_px = 256;
  // Region of interest: the sensor rows and columns the band starts at. A shorter band means
  // a faster frame rate, so the ROI is cropped on the sensor (VIDIOC_S_SELECTION), not in
  // software. A driver without cropping is accepted only for an ROI at (0, 0).
  int roi_top_px = 0;
  int roi_left_px = 0;
  // 0 leaves the driver's exposure alone; V4L2 counts it in 100 µs units, so it is rounded.
  int exposure_us = 0;
  // Driver units; negative leaves the driver's gain alone.
  int gain = -1;
  // Driver buffers: enough that the loop can hold one frame while the driver fills the
  // others, few enough to keep latency low.
  int buffer_count = 4;

  template <class Visitor>
  void visit(Visitor& v) {
    v("device", device, "V4L2 device; simulated: the simulated twin camera");
    v("pixel_format", pixel_format, "pixel format (bit depth)");
    v("width", width_px, "frame width, px", Range{16, 8192});
    v("height", height_px, "frame height (the band's rows), px", Range{1, 8192});
    v("roi_top", roi_top_px, "sensor row the band starts at", Range{0, 8191});
    v("roi_left", roi_left_px, "sensor column the band starts at", Range{0, 8191});
    v("exposure_us", exposure_us, "exposure, us (0: the driver's; V4L2 rounds to 100 us)",
      Range{0, 10'000'000});
    v("gain", gain, "gain, driver units (default -1: the driver's)", Range{0, 1'000'000});
    v("buffer_count", buffer_count, "driver buffers", Range{2, kMaxCameraBuffers});
  }
};

}  // namespace cosmos
