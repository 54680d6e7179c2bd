#include "sim/simulated_scanner.hpp"

#include <stdexcept>

#include "firmware_bridge/stripe_profiler.hpp"
#include "sim/camera_frame_renderer.hpp"
#include "sim/seeded_random.hpp"

namespace cosmos {
namespace {

constexpr std::uint64_t kNoiseStream = 0x2015E;
constexpr std::uint64_t kFrameStream = 0xF4A3E;

int laser_samples(const ScannerParameters& parameters, ScanMode mode) {
  // Camera mode samples the line once per sensor column at belt height: the drawing joins
  // consecutive samples, so every column the line crosses gets its stripe.
  return mode == ScanMode::kCamera ? parameters.sensor_width_px : parameters.points_per_profile;
}

}  // namespace

struct SimulatedScanner::CameraPath {
  CameraPath(const ScannerParameters& parameters, const TriangulationGeometry& geometry)
      : renderer(parameters, geometry),
        frame(renderer.make_frame()),
        profiler(geometry, renderer.extraction_parameters(), frame.cols) {}

  CameraFrameRenderer renderer;
  cv::Mat frame;
  StripeProfiler profiler;  // the hardware's frame → profile path
};

SimulatedScanner::SimulatedScanner(const ConveyorScene& scene, const ScannerParameters& parameters,
                                   ScanMode mode)
    : parameters_(parameters),
      mode_(mode),
      laser_(scene, parameters, laser_samples(parameters, mode)) {
  laser_.reserve(line_);
  if (mode == ScanMode::kCamera)
    camera_ = std::make_unique<CameraPath>(parameters, laser_.geometry());
}

SimulatedScanner::~SimulatedScanner() = default;

void SimulatedScanner::reserve(Profile& profile) const {
  profile.reserve(static_cast<std::size_t>(parameters_.points_per_profile));
  profile.resize(static_cast<std::size_t>(parameters_.points_per_profile));
}

const cv::Mat& SimulatedScanner::last_frame() const {
  if (!camera_) throw std::logic_error("SimulatedScanner: frames exist in camera mode only");
  return camera_->frame;
}

const StripePeaks& SimulatedScanner::last_peaks() const {
  if (!camera_) throw std::logic_error("SimulatedScanner: stripe peaks exist in camera mode only");
  return camera_->profiler.peaks();
}

void SimulatedScanner::acquire(std::int64_t profile_index, Profile& profile) noexcept {
  const std::int64_t encoder_ticks = parameters_.encoder_ticks_of_profile(profile_index);
  profile.encoder_ticks = encoder_ticks;
  profile.t_us = parameters_.time_us_of_profile(profile_index);
  const int width = parameters_.points_per_profile;
  profile.x0_mm = parameters_.first_sample_x_mm(width);
  profile.dx_mm = parameters_.sample_spacing_mm(width);
  profile.resize(static_cast<std::size_t>(width));
  laser_.trace(laser_y_belt_mm(parameters_, profile_index), line_);
  if (mode_ == ScanMode::kCamera) {
    acquire_camera_mode(encoder_ticks, profile);
  } else {
    acquire_profile_mode(encoder_ticks, profile);
  }
}

void SimulatedScanner::acquire_profile_mode(std::int64_t encoder_ticks, Profile& profile) noexcept {
  SeededRandom noise(
      mix_seed(parameters_.seed ^ kNoiseStream, static_cast<std::uint64_t>(encoder_ticks)));
  const double sigma_mm = parameters_.z_noise_mm;
  for (std::size_t i = 0; i < profile.z_mm.size(); ++i) {
    if (line_.state[i] != LaserSampleState::kMeasured) continue;
    profile.z_mm[i] = static_cast<float>(line_.z_mm[i] + sigma_mm * noise.normal());
  }
}

void SimulatedScanner::acquire_camera_mode(std::int64_t encoder_ticks, Profile& profile) noexcept {
  CameraPath& path = *camera_;
  path.renderer.render(
      line_, mix_seed(parameters_.seed ^ kFrameStream, static_cast<std::uint64_t>(encoder_ticks)),
      path.frame);
  path.profiler.profile_frame(path.frame, path.renderer.roi(), profile);
}

}  // namespace cosmos
