#pragma once
// Frames taken from the cell's own camera for `cosmos calibrate`: a real scanner is
// calibrated from board images and stripe frames it records itself, through the very camera
// and GPIO code the cell scans with (firmware_bridge/), and written as the frame directories
// the calibrations read (frame_list.hpp).
//
// The laser is switched through the cell's laser_enable line for the capture: off for board
// images (the corners, seen under ambient light), on for stripe frames. The exposures that
// straddle a switch are not kept (`settle_frames`). With `every_ticks`, frames are kept only
// once the belt has moved that far since the last one kept, so a block or sphere plate
// carried past the scanner is sampled evenly whatever the camera's rate; the encoder count
// stored with a frame is the one read when the frame arrived, as the hardware source does.
//
// Not real-time: the frames are copied out of the driver's buffers (a calibration needs few
// of them). Devices that fail, or a camera that stays silent, end the capture with
// InputError naming the device and the reason.
#include <cstdint>
#include <string>
#include <vector>

#include "calibration/stripe_frame.hpp"
#include "firmware_bridge/camera.hpp"
#include "firmware_bridge/gpio.hpp"

namespace cosmos {

struct FrameCaptureSettings {
  int frames = 1;                // frames to keep
  bool laser_on = false;         // laser_enable while capturing
  int settle_frames = 2;         // frames dropped after the laser switched
  std::int64_t every_ticks = 0;  // encoder ticks between kept frames; 0: every frame
  std::int64_t frame_timeout_us = 200'000;
  int max_consecutive_timeouts = 25;  // a camera silent for this many watchdogs has failed
  std::string device;                 // the camera's name, for the messages
};

// Captures from started devices; leaves them started, the laser as the settings asked.
std::vector<StripeFrame> capture_frames(Camera& camera, GpioLines& gpio,
                                        const FrameCaptureSettings& settings);

}  // namespace cosmos
