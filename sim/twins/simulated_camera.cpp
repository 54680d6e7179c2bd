#include "sim/twins/simulated_camera.hpp"

#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <exception>
#include <thread>

#include "scanner/triangulation_geometry.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

// The camera mode's frame-noise stream (sim/simulated_scanner.cpp): the same seed per
// profile draws the same frame, which the twin's tests check byte for byte.
constexpr std::uint64_t kFrameStream = 0xF4A3E;

}  // namespace

SimulatedCamera::SimulatedCamera(const SimulatedConveyor& conveyor, SimulatedBeltClock& clock,
                                 const CameraConfig& config, const FaultPlan& faults,
                                 const SimulatedMounting& truth)
    : conveyor_(conveyor), clock_(clock), config_(config), faults_(faults), truth_(truth) {}

SimulatedCamera::~SimulatedCamera() = default;

CameraStatus SimulatedCamera::fail(const char* format, ...) noexcept {
  char reason[ErrorLine::kCapacity];
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(reason, sizeof reason, format, arguments);
  va_end(arguments);
  error_.set("simulated camera: %s", reason);
  ++stats_.errors;
  return CameraStatus::kError;
}

CameraStatus SimulatedCamera::check_roi() noexcept {
  const ScannerParameters& scanner = conveyor_.parameters();
  if (config_.roi_left_px + config_.width_px > scanner.sensor_width_px) {
    return fail("camera.width: roi_left + width = %d exceeds the sensor's %d columns",
                config_.roi_left_px + config_.width_px, scanner.sensor_width_px);
  }
  // Only the measuring range's rows are ever lit (LaserLineScanner): rows outside it would
  // show a stripe cut where the real sensor would show one.
  const TriangulationGeometry geometry = scanner_triangulation_geometry(scanner);
  const int first_row = geometry.roi_row_offset_px;
  const int end_row = first_row + geometry.roi_height_px;
  if (config_.roi_top_px < first_row || config_.roi_top_px + config_.height_px > end_row) {
    return fail(
        "camera.roi_top, camera.height: rows [%d, %d) leave the simulated scanner's measuring "
        "range, sensor rows [%d, %d) (roi_top %d, height %d cover it)",
        config_.roi_top_px, config_.roi_top_px + config_.height_px, first_row, end_row, first_row,
        geometry.roi_height_px);
  }
  return CameraStatus::kOk;
}

CameraStatus SimulatedCamera::start() noexcept {
  if (streaming_) {
    fail("start: already streaming, stop first");
    return CameraStatus::kWrongState;
  }
  error_.clear();
  if (const CameraStatus status = check_roi(); status != CameraStatus::kOk) return status;
  try {
    ScannerParameters drawing = conveyor_.parameters();
    drawing.camera.bit_depth = significant_bits(config_.pixel_format);
    TriangulationGeometry geometry = scanner_triangulation_geometry(drawing);
    geometry.roi_row_offset_px = config_.roi_top_px;
    geometry.roi_height_px = config_.height_px;
    if (!laser_) {
      laser_ = std::make_unique<LaserLineScanner>(conveyor_.scene(), drawing,
                                                  drawing.sensor_width_px, truth_.sheet_pitch_deg);
      laser_->reserve(line_);
    }
    renderer_ = std::make_unique<CameraFrameRenderer>(drawing, geometry);
    true_geometry_ = true_triangulation_geometry(drawing, truth_);
    const auto count = static_cast<std::size_t>(std::max(config_.buffer_count, 1));
    buffers_.clear();
    for (std::size_t i = 0; i < count; ++i) buffers_.push_back(renderer_->make_frame());
    lent_.assign(count, 0);
  } catch (const std::exception& error) {
    return fail("start: %s", error.what());
  }
  exposure_us_ = config_.exposure_us;
  gain_ = config_.gain;
  stats_.consecutive_timeouts = 0;
  streaming_ = true;
  return CameraStatus::kOk;
}

CameraStatus SimulatedCamera::stop() noexcept {
  streaming_ = false;
  std::fill(lent_.begin(), lent_.end(), 0);
  return CameraStatus::kOk;
}

CameraStatus SimulatedCamera::rewind() noexcept {
  if (streaming_) {
    fail("rewind: camera streaming, stop first");
    return CameraStatus::kWrongState;
  }
  next_index_ = 0;
  frames_lost_ = 0;
  clock_.rewind();
  return CameraStatus::kOk;
}

int SimulatedCamera::lent_frames() const noexcept {
  return static_cast<int>(std::count(lent_.begin(), lent_.end(), 1));
}

CameraStatus SimulatedCamera::inject_losses(std::int64_t timeout_us) noexcept {
  const std::int64_t last = conveyor_.last_profile();
  while (next_index_ <= last && faults_.active(InjectedFault::kFrameGap, next_index_)) {
    ++next_index_;
    ++frames_lost_;
  }
  if (next_index_ > last || !faults_.active(InjectedFault::kCameraStall, next_index_))
    return CameraStatus::kOk;
  // The frames that pass during one wait; if the stall ends within it, the next frame
  // arrives after the stalled ones' time instead of a timeout.
  const double line_rate_hz = conveyor_.parameters().line_rate_hz;
  const auto frames_per_wait = std::max<std::int64_t>(
      1, static_cast<std::int64_t>(static_cast<double>(timeout_us) * line_rate_hz / 1e6));
  std::int64_t stalled = 0;
  while (stalled < frames_per_wait && next_index_ <= last &&
         faults_.active(InjectedFault::kCameraStall, next_index_)) {
    ++next_index_;
    ++stalled;
  }
  frames_lost_ += static_cast<std::uint64_t>(stalled);
  expose_up_to(next_index_ - 1);
  const bool timed_out =
      stalled == frames_per_wait &&
      (next_index_ > last || faults_.active(InjectedFault::kCameraStall, next_index_));
  const auto waited_us =
      timed_out ? timeout_us
                : static_cast<std::int64_t>(static_cast<double>(stalled) * 1e6 / line_rate_hz);
  std::this_thread::sleep_for(std::chrono::microseconds(waited_us));
  if (!timed_out) return CameraStatus::kOk;
  ++stats_.timeouts;
  ++stats_.consecutive_timeouts;
  error_.set("simulated camera: no frame within %lld us (frame %lld, injected stall)",
             static_cast<long long>(timeout_us), static_cast<long long>(next_index_));
  return CameraStatus::kTimeout;
}

CameraStatus SimulatedCamera::next_frame(std::int64_t timeout_us, FrameView& frame) noexcept {
  if (!streaming_) {
    fail("next_frame: camera not started");
    return CameraStatus::kWrongState;
  }
  if (inject_losses(timeout_us) == CameraStatus::kTimeout) return CameraStatus::kTimeout;
  if (next_index_ > conveyor_.last_profile()) {
    error_.set("simulated camera: frame %lld: the conveyor's last profile has passed",
               static_cast<long long>(next_index_));
    return CameraStatus::kEndOfStream;
  }
  const auto free_buffer = std::find(lent_.begin(), lent_.end(), 0);
  if (free_buffer == lent_.end()) {
    return fail("next_frame: all %zu buffers are held by the caller, release_frame one first",
                lent_.size());
  }
  const auto index = static_cast<std::size_t>(free_buffer - lent_.begin());
  const ScannerParameters& scanner = conveyor_.parameters();
  const std::int64_t ticks = scanner.encoder_ticks_of_profile(next_index_);
  laser_->trace(laser_y_belt_mm(scanner, next_index_), line_);
  const bool laser_disabled =
      laser_line_ != nullptr && !laser_line_->output_active(GpioOutput::kLaserEnable);
  if (laser_disabled || faults_.active(InjectedFault::kLaserOff, next_index_))
    std::fill(line_.state.begin(), line_.state.end(), LaserSampleState::kLaserShadow);
  if (moves_camera(truth_)) project_through_true_camera();
  cv::Mat& buffer = buffers_[index];
  renderer_->render(line_, mix_seed(scanner.seed ^ kFrameStream, static_cast<std::uint64_t>(ticks)),
                    buffer);
  // A burst begins when the clock has not reached this frame: it exposes the burst's frames.
  if (clock_.frame() < next_index_ || (next_index_ == 0 && clock_.frame() == 0))
    expose_up_to(std::min(next_index_ + burst_frames_ - 1, conveyor_.last_profile()));
  lent_[index] = 1;

  frame.format = config_.pixel_format;
  frame.data = buffer.ptr(0) + static_cast<std::ptrdiff_t>(config_.roi_left_px) *
                                   bytes_per_pixel(config_.pixel_format);
  frame.width_px = config_.width_px;
  frame.height_px = config_.height_px;
  frame.bytes_per_line = static_cast<int>(buffer.step[0]);
  frame.roi_top_px = config_.roi_top_px;
  frame.roi_left_px = config_.roi_left_px;
  frame.frame_index = static_cast<std::uint64_t>(next_index_);
  frame.dropped_before = static_cast<std::uint32_t>(frames_lost_);
  stats_.dropped_frames += frames_lost_;
  frames_lost_ = 0;
  stats_.consecutive_timeouts = 0;
  frame.t_us = clock_.frame_time_ns(next_index_) / 1000;
  frame.t_is_start_of_exposure = true;
  frame.buffer_index = static_cast<int>(index);
  ++next_index_;
  ++stats_.frames;
  return CameraStatus::kOk;
}

void SimulatedCamera::expose_up_to(std::int64_t frame) noexcept {
  if (frame > clock_.frame()) clock_.advance_to_frame(frame);
}

void SimulatedCamera::project_through_true_camera() noexcept {
  for (int i = 0; i < line_.width(); ++i) {
    const auto s = static_cast<std::size_t>(i);
    const Eigen::Vector3d point_belt_mm(line_.x_mm(i), 0.0, line_.z_mm[s]);
    Eigen::Vector2d uv_px;
    if (!true_geometry_.project_to_image(point_belt_mm, uv_px)) {
      line_.state[s] = LaserSampleState::kOutOfRange;
      continue;
    }
    line_.u_px[s] = static_cast<float>(uv_px.x());
    line_.v_px[s] = static_cast<float>(uv_px.y());
  }
}

CameraStatus SimulatedCamera::release_frame(const FrameView& frame) noexcept {
  if (!streaming_) {
    fail("release_frame: camera not started");
    return CameraStatus::kWrongState;
  }
  const int index = frame.buffer_index;
  if (index < 0 || index >= static_cast<int>(lent_.size()) ||
      lent_[static_cast<std::size_t>(index)] == 0) {
    return fail("release_frame: buffer %d is not lent out", index);
  }
  lent_[static_cast<std::size_t>(index)] = 0;
  return CameraStatus::kOk;
}

CameraStatus SimulatedCamera::set_exposure_us(int exposure_us) noexcept {
  if (!streaming_) {
    fail("set_exposure_us: camera not started");
    return CameraStatus::kWrongState;
  }
  exposure_us_ = exposure_us;
  return CameraStatus::kOk;
}

CameraStatus SimulatedCamera::set_gain(int gain) noexcept {
  if (!streaming_) {
    fail("set_gain: camera not started");
    return CameraStatus::kWrongState;
  }
  gain_ = gain;
  return CameraStatus::kOk;
}

}  // namespace cosmos
