#pragma once
// Settings of the scanner camera (the `camera:` block of config/hardware-example.yaml).
// Defaults describe the designed sensor of triangulation_geometry.hpp: a 1280-column sensor
// read out as a 256-row band around the laser line.
#include <cstdint>
#include <string>

#include "firmware_bridge/pixel_format.hpp"

namespace cosmos {

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
};

}  // namespace cosmos
