#pragma once
// The camera of the laser-line scanner, as the acquisition loop sees it. Two implementations:
// V4l2Camera talks to a V4L2 device (v4l2_camera.hpp); SimulatedCamera (sim/twins/) hands
// out the frames the simulator's camera mode draws for the simulated conveyor, so the same
// stripe extraction and triangulation (HardwareSource) run with and without hardware.
//
// Frames are lent, not copied: next_frame() hands out a view into a driver buffer and the
// caller gives it back with release_frame() once the stripe is extracted. A frame copy at
// 1280×256×2 bytes and several kHz would cost more than the extraction itself.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "firmware_bridge/pixel_format.hpp"

namespace cosmos {

enum class CameraStatus : std::uint8_t {
  kOk,
  kTimeout,     // the watchdog expired without a frame (counted in CameraStats::timeouts)
  kNoFrame,     // woke up without a usable frame (signal, corrupted frame): just try again
  kWrongState,  // a lifecycle step was called out of order
  kError,       // the device refused: see last_error()
  // No frame will ever come: a finite camera (the simulated one, once its conveyor's last
  // part has passed) is exhausted. A real camera never says it.
  kEndOfStream,
};

// One frame, valid until it is released. Rows are bytes_per_line apart (drivers pad rows);
// a 16-bit sample is little-endian, its low significant_bits carry the intensity.
struct FrameView {
  const std::uint8_t* data = nullptr;
  int width_px = 0;
  int height_px = 0;
  int bytes_per_line = 0;
  PixelFormat format = PixelFormat::kGrey8;
  // Sensor position of pixel (0, 0): triangulation needs full-sensor coordinates.
  int roi_top_px = 0;
  int roi_left_px = 0;
  // Frame index since the camera was started: consecutive unless frames were dropped,
  // continuing across stream restarts (the Profile's seq).
  std::uint64_t frame_index = 0;
  std::uint32_t dropped_before = 0;  // frames lost between the previous frame and this one
  // CLOCK_MONOTONIC, µs; the simulated camera's belt clock instead (from 0 at its start).
  std::int64_t t_us = 0;
  // Which instant t_us marks: start of exposure when the driver says so, else end of frame.
  bool t_is_start_of_exposure = false;
  int buffer_index = -1;  // the implementation's handle for release_frame()

  int bytes_per_pixel() const noexcept { return cosmos::bytes_per_pixel(format); }
  int significant_bits() const noexcept { return cosmos::significant_bits(format); }
  const std::uint8_t* row(int r) const noexcept {
    return data + static_cast<std::ptrdiff_t>(r) * bytes_per_line;
  }
};

struct CameraStats {
  std::uint64_t frames = 0;          // frames handed out
  std::uint64_t dropped_frames = 0;  // from sequence-number gaps
  std::uint64_t timeouts = 0;        // watchdog expiries
  std::uint64_t consecutive_timeouts = 0;
  std::uint64_t corrupted_frames = 0;  // flagged bad by the driver or short: requeued unseen
  std::uint64_t sequence_resets = 0;   // the driver's counter jumped backwards mid-stream
  std::uint64_t errors = 0;
};

class Camera {
 public:
  virtual ~Camera() = default;

  // Brings the camera from closed to streaming (set-up: may allocate, not real-time).
  virtual CameraStatus start() noexcept = 0;
  // Back to closed from any state; frames still held become invalid.
  virtual CameraStatus stop() noexcept = 0;

  // Real-time: waits at most timeout_us for the next frame. Never allocates or throws.
  virtual CameraStatus next_frame(std::int64_t timeout_us, FrameView& frame) noexcept = 0;
  // Real-time: gives the frame's buffer back to the camera.
  virtual CameraStatus release_frame(const FrameView& frame) noexcept = 0;

  virtual CameraStatus set_exposure_us(int exposure_us) noexcept = 0;
  virtual CameraStatus set_gain(int gain) noexcept = 0;

  virtual CameraStats stats() const noexcept = 0;
  // One line naming the device and the reason of the last failure, empty if none.
  virtual std::string_view last_error() const noexcept = 0;
};

}  // namespace cosmos
