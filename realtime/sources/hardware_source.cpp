#include "realtime/sources/hardware_source.hpp"

#include <string_view>

#include "firmware_bridge/frame_view_mat.hpp"
#include "firmware_bridge/gpio_lines.hpp"
#include "firmware_bridge/v4l2_camera.hpp"

namespace cosmos {
namespace {

int view_length(std::string_view text) { return static_cast<int>(text.size()); }

}  // namespace

HardwareSource::HardwareSource(const HardwareConfig& config, const ScannerParameters& parameters)
    : config_(config),
      parameters_(parameters),
      owned_camera_(std::make_unique<V4l2Camera>(config.camera)),
      owned_gpio_(std::make_unique<LibgpiodLines>(config.gpio)),
      camera_(owned_camera_.get()),
      gpio_(owned_gpio_.get()) {}

HardwareSource::HardwareSource(const HardwareConfig& config, const ScannerParameters& parameters,
                               Camera& camera, GpioLines& gpio)
    : config_(config), parameters_(parameters), camera_(&camera), gpio_(&gpio) {}

HardwareSource::~HardwareSource() { stop(); }

SourceStatus HardwareSource::fail_start(std::string_view reason, const char* key) {
  if (config_.file.empty()) {
    error_.set("%.*s", view_length(reason), reason.data());
  } else {
    error_.set("%.*s (%s in %s)", view_length(reason), reason.data(), key, config_.file.c_str());
  }
  return SourceStatus::kError;
}

SourceStatus HardwareSource::check_camera_fits_sensor() {
  // The triangulation table covers the scanner's sensor: a band outside it has no geometry.
  const CameraConfig& camera = config_.camera;
  const char* file = config_.file.empty() ? "hardware config" : config_.file.c_str();
  if (camera.roi_left_px + camera.width_px > parameters_.sensor_width_px) {
    error_.set("%s: camera.width: roi_left + width = %d exceeds scanner.sensor_width_px %d", file,
               camera.roi_left_px + camera.width_px, parameters_.sensor_width_px);
    return SourceStatus::kError;
  }
  if (camera.roi_top_px + camera.height_px > parameters_.sensor_height_px) {
    error_.set("%s: camera.height: roi_top + height = %d exceeds scanner.sensor_height_px %d", file,
               camera.roi_top_px + camera.height_px, parameters_.sensor_height_px);
    return SourceStatus::kError;
  }
  return SourceStatus::kOk;
}

SourceStatus HardwareSource::start() {
  stop();
  error_.clear();
  dropped_ = 0;
  encoder_counts_unsettled_ = 0;
  photo_eye_ = {};
  result_pulses_ = 0;
  // Results announced while stopped are not owed: their parts were seen by an earlier run.
  results_signalled_ = results_announced_.load(std::memory_order_relaxed);
  result_ready_high_ = false;
  if (check_camera_fits_sensor() != SourceStatus::kOk) return SourceStatus::kError;
  width_ = parameters_.points_per_profile;
  const CameraConfig& camera = config_.camera;
  profiler_ = std::make_unique<StripeProfiler>(
      calibrated_triangulation_geometry(parameters_, config_.calibration), config_.stripe,
      camera.roi_top_px, camera.height_px, camera.width_px);

  // The camera first: it is the device a machine without scanner hardware lacks first.
  if (camera_->start() != CameraStatus::kOk) {
    const std::string_view reason = camera_->last_error();
    const bool opening = reason.find(": open: ") != std::string_view::npos;
    return fail_start(reason, opening ? "camera.device" : "camera");
  }
  corrupted_at_start_ = camera_->stats().corrupted_frames;
  if (gpio_->start() != GpioStatus::kOk) {
    const std::string_view reason = gpio_->last_error();
    const bool opening = reason.find("cannot open GPIO chip") != std::string_view::npos;
    const SourceStatus status = fail_start(reason, opening ? "gpio.chip" : "gpio");
    camera_->stop();
    return status;
  }
  const GpioStatus laser = gpio_->set_output(GpioOutput::kLaserEnable, true);
  if (laser != GpioStatus::kOk && laser != GpioStatus::kNotConfigured) {
    const SourceStatus status = fail_start(gpio_->last_error(), "gpio.laser_enable");
    gpio_->stop();
    camera_->stop();
    return status;
  }
  started_ = true;
  return SourceStatus::kOk;
}

SourceHealth HardwareSource::health() const noexcept {
  SourceHealth health{.profiles_lost = dropped_,
                      .encoder_counts_unsettled = encoder_counts_unsettled_};
  if (camera_) {
    const CameraStats stats = camera_->stats();
    health.camera_timeouts = stats.timeouts;
    // A corrupted frame is requeued unseen: its profile is lost as a dropped frame's is.
    if (stats.corrupted_frames > corrupted_at_start_)
      health.profiles_lost += stats.corrupted_frames - corrupted_at_start_;
  }
  if (gpio_) {
    const EncoderReading encoder = gpio_->encoder();
    const GpioInputHealth inputs = gpio_->input_health();
    health.encoder_errors = encoder.invalid_transitions;
    health.encoder_reversals = encoder.reversals;
    health.gpio_edges_lost = inputs.edges_lost;
    health.photo_eye_bounces = inputs.photo_eye_bounces;
  }
  return health;
}

void HardwareSource::reserve(Profile& profile) const {
  profile.reserve(static_cast<std::size_t>(parameters_.points_per_profile));
}

SourceStatus HardwareSource::next(Profile& out) noexcept {
  if (!started_) {
    error_.set("%s: next() before start()", config_.camera.device.c_str());
    return SourceStatus::kError;
  }
  if (out.z_mm.capacity() < static_cast<std::size_t>(width_)) {
    error_.set("%s: profile slot not reserved for %d samples", config_.camera.device.c_str(),
               width_);
    return SourceStatus::kError;
  }
  FrameView frame;
  const CameraStatus waited = camera_->next_frame(config_.frame_timeout_us, frame);
  if (waited == CameraStatus::kEndOfStream) return SourceStatus::kEndOfStream;
  if (waited != CameraStatus::kOk) {
    const std::string_view reason = camera_->last_error();
    error_.set("%.*s", view_length(reason), reason.data());
    const bool retry = waited == CameraStatus::kTimeout || waited == CameraStatus::kNoFrame;
    return retry ? SourceStatus::kTimeout : SourceStatus::kError;
  }
  dropped_ += frame.dropped_before;
  EncoderAtTime encoder;
  if (gpio_->encoder_at(frame.t_us * 1000, config_.gpio.frame_edges_wait_ns(), encoder) ==
      GpioStatus::kError) {
    const std::string_view reason = gpio_->last_error();
    error_.set("%.*s", view_length(reason), reason.data());
    camera_->release_frame(frame);
    return SourceStatus::kError;
  }
  encoder_counts_unsettled_ += encoder.settled ? 0 : 1;
  drain_photo_eye();
  out.seq = frame.frame_index;
  out.encoder_ticks = encoder.ticks;
  out.t_us = frame.t_us;
  out.x0_mm = parameters_.first_sample_x_mm(width_);
  out.dx_mm = parameters_.sample_spacing_mm(width_);
  out.resize(static_cast<std::size_t>(width_));
  const StripeExtractionStatus extracted =
      profiler_->profile_frame(frame_as_mat(frame), frame_roi(frame), out);
  const CameraStatus released = camera_->release_frame(frame);
  if (extracted != StripeExtractionStatus::kOk) {
    error_.set("%s: frame %llu: no stripe extraction on a %dx%d frame of %d bytes per pixel",
               config_.camera.device.c_str(), static_cast<unsigned long long>(frame.frame_index),
               frame.width_px, frame.height_px, frame.bytes_per_pixel());
    return SourceStatus::kError;
  }
  if (released != CameraStatus::kOk) {
    const std::string_view reason = camera_->last_error();
    error_.set("%.*s", view_length(reason), reason.data());
    return SourceStatus::kError;
  }
  return drive_result_ready();
}

void HardwareSource::drain_photo_eye() noexcept {
  PhotoEyeEvent event;
  while (gpio_->next_photo_eye_event(event)) {
    ++(event.present ? photo_eye_.arrivals : photo_eye_.departures);
    photo_eye_.last = event;
  }
}

SourceStatus HardwareSource::drive_result_ready() noexcept {
  GpioStatus status = GpioStatus::kOk;
  if (result_ready_high_) {
    // High for one frame period, then low for at least one: results stay separate pulses.
    result_ready_high_ = false;
    status = gpio_->set_output(GpioOutput::kResultReady, false);
  } else if (results_signalled_ != results_announced_.load(std::memory_order_relaxed)) {
    ++results_signalled_;
    status = gpio_->set_output(GpioOutput::kResultReady, true);
    if (status == GpioStatus::kOk) {
      result_ready_high_ = true;
      ++result_pulses_;
    }
  }
  if (status == GpioStatus::kOk || status == GpioStatus::kNotConfigured) return SourceStatus::kOk;
  const std::string_view reason = gpio_->last_error();
  error_.set("%.*s", view_length(reason), reason.data());
  return SourceStatus::kError;
}

void HardwareSource::stop() noexcept {
  if (!started_) return;
  // The laser goes off first: a stopped cell must not leave it lit.
  gpio_->set_output(GpioOutput::kLaserEnable, false);
  if (result_ready_high_) gpio_->set_output(GpioOutput::kResultReady, false);
  result_ready_high_ = false;
  gpio_->stop();
  camera_->stop();
  started_ = false;
}

}  // namespace cosmos
