#pragma once
// The first hardware-in-the-loop check: does a frame written to vivid's output node come back,
// byte for byte, through the project's V4l2Camera on the capture node, in every pixel format
// the camera supports? The probe writes a numbered test pattern into the output's rows that
// the camera's ROI covers, starts the camera (its own crop, format, buffers, streaming), and
// compares what it dequeues with what was written.
#include <string>

#include "firmware_bridge/camera_config.hpp"
#include "tests/hil/vivid_loop.hpp"

namespace cosmos::hil {

struct LoopProbeResult {
  bool ok = false;
  std::string line;  // one line for the log: format, frames compared, differing bytes or error
};

// The camera's config (device = the capture node) in `format`; vivid set up in the same.
LoopProbeResult probe_loop(const std::string& output_node, CameraConfig camera,
                           VividLoopSettings loop, PixelFormat format, int frames);

}  // namespace cosmos::hil
