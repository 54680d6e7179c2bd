#pragma once
// vivid's video loop set up as the cell's camera. vivid (the kernel's virtual video test
// driver) copies the frame at the head of its output queue into each capture buffer when
// "Loop Video" is on and the two sides match: an HDMI input looped from an HDMI output of the
// same size and pixel format (vivid_vid_can_loop). The capture side is the cell's: its
// V4l2Camera crops the ROI out of the input's frame (VIDIOC_S_SELECTION) and sets the
// format, exactly as on a real camera. This side sets what a camera's cable would: the
// input's and the output's DV timings (their frame size and rate), the loop, the on-screen
// text off (vivid draws counters into captured frames otherwise), and the output's format.
//
// The output runs faster than the capture (a multiple of its rate): vivid's output thread
// retires the head frame only once the next one is queued, and it must do so between two
// capture ticks for every capture to see a new frame (FramePlayer, frame_player.hpp).
#include <cstdint>
#include <string>

#include "firmware_bridge/pixel_format.hpp"
#include "tests/hil/v4l2_node.hpp"

namespace cosmos::hil {

struct DvTimingsPreset {
  const char* name;  // "1280x720p30" …
  v4l2_dv_timings timings;
};

// Known presets: 1280x720 at 24, 25, 30, 50, 60 Hz (CEA-861) and 1280x768 at 60 and
// 120 Hz reduced blanking (DMT). Throws for another name, listing the known ones.
v4l2_dv_timings dv_timings_preset(const std::string& name);
// Frames per second of DV timings (pixel clock over total pixels).
double frame_rate_hz(const v4l2_dv_timings& timings);

struct VividLoopSettings {
  std::string capture_timings = "1280x720p24";
  std::string output_timings = "1280x720p60";
  PixelFormat pixel_format = PixelFormat::kGrey8;
};

struct OutputFormat {
  int width_px = 0;
  int height_px = 0;
  int bytes_per_line = 0;
  std::uint32_t size_bytes = 0;
  double capture_rate_hz = 0;  // the capture side's frame rate
  double output_rate_hz = 0;
};

// Configures both nodes (neither may be streaming) and returns the output's format.
OutputFormat configure_vivid_loop(const V4l2Node& capture, const V4l2Node& output,
                                  const VividLoopSettings& settings);

}  // namespace cosmos::hil
