#pragma once
// The simulated twin of the scanner camera (firmware_bridge/camera.hpp), after libcamera's
// vimc: it delivers the frames the simulator's camera mode renders for the simulated conveyor
// (sim/camera_frame_renderer.hpp), so HardwareSource's stripe extraction, triangulation and
// encoder decoding run in the simulated cell exactly as on the real sensor.
//
// Frame k is the sensor image of the laser line at profile k of the simulated scan: the
// LaserLineScanner's line at one sample per sensor column, drawn with the noise seed the
// camera mode uses for that profile, so with the scanner's own ROI and bit depth a frame
// equals SimulatedScanner::last_frame() of camera mode byte for byte. The frame is in the
// hardware config's pixel format (its significant bits set the drawing's full scale) and
// ROI: rows roi_top … roi_top + height of the sensor, which must lie inside the simulated
// scanner's measuring range (its ROI rows: nothing outside them is ever lit), and columns
// roi_left … roi_left + width, cut from a full-width drawing without copying.
//
// Sequence and time: frame indices 0, 1, 2, … (nothing is dropped), t_us the frame's
// exposure time on the shared SimulatedBeltClock (t_is_start_of_exposure), which the camera
// moves to each frame it hands out. Delivered in bursts (deliver_in_bursts(n)), as a
// free-running camera's driver hands over its queue when the reader was held up, the clock
// moves on to the last of n frames before the first of them is handed out, so the belt has
// run past a frame's exposure when the frame arrives; each frame keeps its own t_us. A frame is
// always ready at once, so next_frame()'s timeout never expires; after the conveyor's last profile
// it says kEndOfStream. A restarted camera goes on down the belt where it stopped (frame indices
// continue, as the interface asks); rewind() puts the belt back at frame 0.
//
// Lifecycle as V4l2Camera: start (closed → streaming; builds the scanner, the renderer and
// buffer_count frame buffers) → next_frame / release_frame → stop (any state → closed).
// next_frame, release_frame and the controls on a closed camera are kWrongState; next_frame
// with every buffer lent is kError. Exposure and gain are recorded, not drawn.
// next_frame() renders into a preallocated buffer: no allocation, no exceptions.
//
// Injected faults (sim/source/fault_plan.hpp, by frame index), as a failing V4L2 camera shows
// them: frames of a gap are never delivered and the next frame says how many were lost
// (dropped_before, its index past them); during a stall next_frame() blocks for its whole
// timeout, the belt moving on, and says kTimeout (counted in stats().timeouts) until the
// stall's frames have passed; with the laser off a frame shows the belt with no stripe at all.
// Only the stall blocks (for real time: a camera's wait is wall-clock time).
// The laser follows the GPIO twin's laser_enable line when the camera is told to
// (follow_laser_enable): with it inactive a frame shows the belt under ambient light and no
// stripe, as a calibration's board image does.
// True geometry (scanner/simulated_mounting.hpp): a mounting that moves the camera re-projects
// each lit point through the true camera before drawing, so the frames are what a
// mis-mounted scanner sees while the cell triangulates with the geometry it is told. Which
// points are lit and seen stays the designed camera's call: the true one is a fraction of a
// degree away. A pitched scanner head (sheet_pitch_deg) tilts the traced sheet itself, with
// the camera and source riding on it.
#include <cstdint>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "firmware_bridge/camera.hpp"
#include "firmware_bridge/camera_config.hpp"
#include "firmware_bridge/error_line.hpp"
#include "scanner/simulated_mounting.hpp"
#include "sim/camera_frame_renderer.hpp"
#include "sim/laser_line_scanner.hpp"
#include "sim/source/fault_plan.hpp"
#include "sim/source/simulated_conveyor.hpp"
#include "sim/twins/simulated_belt_clock.hpp"
#include "sim/twins/simulated_gpio_lines.hpp"

namespace cosmos {

class SimulatedCamera final : public Camera {
 public:
  // The conveyor and the clock must outlive the camera.
  SimulatedCamera(const SimulatedConveyor& conveyor, SimulatedBeltClock& clock,
                  const CameraConfig& config, const FaultPlan& faults = FaultPlan{},
                  const SimulatedMounting& truth = {});
  ~SimulatedCamera() override;
  SimulatedCamera(const SimulatedCamera&) = delete;
  SimulatedCamera& operator=(const SimulatedCamera&) = delete;

  // kError with one line naming the key when the ROI leaves the sensor or the simulated
  // scanner's measuring range.
  CameraStatus start() noexcept override;
  CameraStatus stop() noexcept override;
  CameraStatus next_frame(std::int64_t timeout_us, FrameView& frame) noexcept override;
  CameraStatus release_frame(const FrameView& frame) noexcept override;
  CameraStatus set_exposure_us(int exposure_us) noexcept override;
  CameraStatus set_gain(int gain) noexcept override;
  CameraStats stats() const noexcept override { return stats_; }
  std::string_view last_error() const noexcept override { return error_.view(); }

  // Back to frame 0 and the clock to time 0, for a replay of the identical stream; only
  // while stopped (kWrongState otherwise). Restart the GPIO twin after it.
  CameraStatus rewind() noexcept;
  // The laser lights the frames only while `gpio`'s laser_enable is active (it must outlive
  // the camera); without this call it always does.
  void follow_laser_enable(const SimulatedGpioLines& gpio) noexcept { laser_line_ = &gpio; }
  // Frames exposed n at a time before the first of them is handed out (1: one by one).
  void deliver_in_bursts(int frames) noexcept { burst_frames_ = frames < 1 ? 1 : frames; }

  bool streaming() const noexcept { return streaming_; }
  int lent_frames() const noexcept;
  int exposure_us() const noexcept { return exposure_us_; }
  int gain() const noexcept { return gain_; }
  // The laser line of the last frame handed out: the simulator's prediction of the stripe
  // (sensor coordinates u_px, v_px per sample).
  const LaserLine& last_line() const noexcept { return line_; }
  const CameraConfig& config() const noexcept { return config_; }

 private:
  CameraStatus check_roi() noexcept;
  // Skips the frames an injected gap or stall loses; kTimeout after waiting out a stall.
  CameraStatus inject_losses(std::int64_t timeout_us) noexcept;
  // Moves the belt clock on to `frame`'s exposure; never back (a burst ran ahead).
  void expose_up_to(std::int64_t frame) noexcept;
  void project_through_true_camera() noexcept;
  [[gnu::format(printf, 2, 3)]] CameraStatus fail(const char* format, ...) noexcept;

  const SimulatedConveyor& conveyor_;
  SimulatedBeltClock& clock_;
  CameraConfig config_;
  FaultPlan faults_;
  std::uint64_t frames_lost_ = 0;  // lost since the last frame handed out
  SimulatedMounting truth_;
  TriangulationGeometry true_geometry_;
  std::unique_ptr<LaserLineScanner> laser_;
  std::unique_ptr<CameraFrameRenderer> renderer_;
  LaserLine line_;
  const SimulatedGpioLines* laser_line_ = nullptr;
  std::vector<cv::Mat> buffers_;  // full sensor width, the ROI's rows
  std::vector<std::uint8_t> lent_;
  std::int64_t next_index_ = 0;
  int burst_frames_ = 1;
  bool streaming_ = false;
  int exposure_us_ = 0;
  int gain_ = -1;
  CameraStats stats_;
  ErrorLine error_;
};

}  // namespace cosmos
