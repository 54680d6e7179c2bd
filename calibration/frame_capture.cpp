#include "calibration/frame_capture.hpp"

#include <string_view>

#include "core/input_error.hpp"
#include "firmware_bridge/frame_view_mat.hpp"

namespace cosmos {
namespace {

[[noreturn]] void fail(const FrameCaptureSettings& settings, std::string_view reason) {
  throw InputError(settings.device + ": capture: " + std::string(reason));
}

}  // namespace

std::vector<StripeFrame> capture_frames(Camera& camera, GpioLines& gpio,
                                        const FrameCaptureSettings& settings) {
  if (settings.frames < 1) fail(settings, "at least one frame must be asked for");
  const GpioStatus laser = gpio.set_output(GpioOutput::kLaserEnable, settings.laser_on);
  if (laser == GpioStatus::kNotConfigured && settings.laser_on)
    fail(settings, "stripe frames need the laser, and gpio.laser_enable is not configured");
  if (laser != GpioStatus::kOk && laser != GpioStatus::kNotConfigured)
    fail(settings, gpio.last_error());

  std::vector<StripeFrame> frames;
  frames.reserve(static_cast<std::size_t>(settings.frames));
  int to_settle = settings.settle_frames;
  int timeouts = 0;
  std::int64_t last_kept_ticks = 0;
  while (static_cast<int>(frames.size()) < settings.frames) {
    FrameView frame;
    const CameraStatus waited = camera.next_frame(settings.frame_timeout_us, frame);
    if (waited == CameraStatus::kTimeout || waited == CameraStatus::kNoFrame) {
      if (++timeouts >= settings.max_consecutive_timeouts)
        fail(settings, "no frame within " + std::to_string(timeouts) + " watchdogs of " +
                           std::to_string(settings.frame_timeout_us / 1000) + " ms");
      continue;
    }
    if (waited == CameraStatus::kEndOfStream)
      fail(settings, "the camera ended after " + std::to_string(frames.size()) + " of " +
                         std::to_string(settings.frames) + " frames");
    if (waited != CameraStatus::kOk) fail(settings, camera.last_error());
    timeouts = 0;
    if (gpio.poll_inputs(0) == GpioStatus::kError) {
      camera.release_frame(frame);
      fail(settings, gpio.last_error());
    }
    const std::int64_t ticks = gpio.encoder().ticks;
    const bool settling = to_settle > 0;
    to_settle -= settling ? 1 : 0;
    const bool moved_enough = frames.empty() || settings.every_ticks <= 0 ||
                              ticks - last_kept_ticks >= settings.every_ticks;
    if (!settling && moved_enough) {
      frames.push_back({frame_as_mat(frame).clone(), frame.roi_top_px, ticks});
      last_kept_ticks = ticks;
    }
    if (camera.release_frame(frame) != CameraStatus::kOk) fail(settings, camera.last_error());
  }
  return frames;
}

}  // namespace cosmos
