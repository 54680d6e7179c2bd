#pragma once
// The live scanner as a ScannerSource (`hardware`): the camera that images the laser line
// and the GPIO lines of the conveyor encoder, the photo eye and the cell's outputs, from the
// hardware YAML (hardware_config.hpp), with the triangulation geometry and the profile grid
// of the cell's `scanner:` section (ScannerParameters), exactly as the simulated cell uses
// them. The devices are a V4L2 camera and libgpiod lines, or any Camera and GpioLines the
// caller supplies: the simulated twins (sim/twins/) run this very path without hardware.
//
// start() opens the camera device and the GPIO chip, and fails with one line naming the
// device and the config key that names it ("/dev/video0: open: No such file or directory
// (camera.device in hw.yaml)"). There is never a fallback to the simulator: a cell that was
// told to use hardware and has none must stop, not scan imaginary parts. Then it drives
// laser-enable on (when configured) and streams.
//
// next() waits up to frame_timeout_us for a frame, drains the encoder's and the photo eye's
// edges, turns the frame into the profile with the simulator's camera-mode code
// (StripeProfiler) and gives the frame back. seq is the camera's frame index, t_us the
// frame's time stamp (CLOCK_MONOTONIC), encoder_ticks the count at that time stamp
// (GpioLines::encoder_at, waiting up to gpio.frame_edges_wait_us for the edges before it):
// not the count when the frame was dequeued, which jitters with a free-running camera's
// bursts of delivery while the belt moved evenly. A driver that stamps the end of the frame
// puts a constant offset on the count at constant belt speed, which cancels (the pose is
// published with the count of its last row). A count that could not be settled is counted
// in health().encoder_counts_unsettled. Every frame that never became a profile adds to
// health().profiles_lost: the frames the camera lost (sequence gaps) and those it delivered
// corrupted, so that the loss equals the gaps in the profiles' seq.
// A finite camera's end (CameraStatus::kEndOfStream) is the source's kEndOfStream.
//
// Photo eye: its transitions are counted (photo_eye(): arrivals, departures, and the latest
// with the encoder count at its edge); nothing else depends on them yet, since the part
// tracker finds parts in the profiles themselves.
//
// Result ready: announce_result() may be called from any thread (the publisher's, once a
// pose went out); the acquisition thread, the only one that touches the GPIO lines, turns
// each announcement into one pulse of result_ready: raised at the next frame, lowered at the
// frame after, and low for at least a frame before the next pulse. Pulses still owed when
// the stream ends are not sent.
// The camera runs free: no output triggers it.
#include <atomic>
#include <cstdint>
#include <memory>

#include "firmware_bridge/camera.hpp"
#include "firmware_bridge/error_line.hpp"
#include "firmware_bridge/gpio.hpp"
#include "firmware_bridge/stripe_profiler.hpp"
#include "realtime/config/hardware_config.hpp"
#include "realtime/sources/scanner_source.hpp"
#include "scanner/scanner_model.hpp"

namespace cosmos {

// The photo eye's transitions seen by next() since start().
struct PhotoEyeTally {
  std::uint64_t arrivals = 0;    // part present
  std::uint64_t departures = 0;  // part gone
  PhotoEyeEvent last;            // the latest of either
};

class HardwareSource final : public ScannerSource {
 public:
  // The cell's own devices: a V4l2Camera and libgpiod lines built from the config.
  HardwareSource(const HardwareConfig& config, const ScannerParameters& parameters);
  // Devices supplied by the caller (fakes in tests); they must outlive the source.
  HardwareSource(const HardwareConfig& config, const ScannerParameters& parameters, Camera& camera,
                 GpioLines& gpio);
  ~HardwareSource() override;
  HardwareSource(const HardwareSource&) = delete;
  HardwareSource& operator=(const HardwareSource&) = delete;

  SourceStatus start() override;
  void reserve(Profile& profile) const override;
  SourceStatus next(Profile& out) noexcept override;
  void stop() noexcept override;

  double mm_per_profile() const override { return parameters_.profile_step_mm(); }
  std::string_view last_error() const noexcept override { return error_.view(); }
  SourceHealth health() const noexcept override;

  // The last frame's stripe (diagnostics); valid after the first profile.
  const StripeProfiler* profiler() const { return profiler_.get(); }
  // Read on the acquisition thread, or once the source is stopped.
  const PhotoEyeTally& photo_eye() const noexcept { return photo_eye_; }
  // The devices, for tools that take whole frames themselves between start() and stop()
  // (`cosmos calibrate capture`); the cell's loop reads them only through next().
  Camera& camera() noexcept { return *camera_; }
  GpioLines& gpio() noexcept { return *gpio_; }
  // Any thread: a result (a published pose) for result_ready to signal.
  void announce_result() noexcept { results_announced_.fetch_add(1, std::memory_order_relaxed); }
  // result_ready pulses begun since start(); read as photo_eye().
  std::uint64_t result_pulses() const noexcept { return result_pulses_; }

 private:
  // Fails start() with `reason` and the config key that names the failing device.
  SourceStatus fail_start(std::string_view reason, const char* key);
  SourceStatus check_camera_fits_sensor();
  void drain_photo_eye() noexcept;
  // kError with the GPIO's reason when the line refused.
  SourceStatus drive_result_ready() noexcept;

  HardwareConfig config_;
  ScannerParameters parameters_;
  std::unique_ptr<Camera> owned_camera_;
  std::unique_ptr<GpioLines> owned_gpio_;
  Camera* camera_ = nullptr;
  GpioLines* gpio_ = nullptr;
  std::unique_ptr<StripeProfiler> profiler_;
  int width_ = 0;  // profile samples
  bool started_ = false;
  std::uint64_t dropped_ = 0;
  std::uint64_t corrupted_at_start_ = 0;  // the camera's count when it started
  std::uint64_t encoder_counts_unsettled_ = 0;
  PhotoEyeTally photo_eye_;
  std::atomic<std::uint64_t> results_announced_{0};
  std::uint64_t results_signalled_ = 0;  // announcements taken up (acquisition thread)
  std::uint64_t result_pulses_ = 0;
  bool result_ready_high_ = false;
  ErrorLine error_;
};

}  // namespace cosmos
