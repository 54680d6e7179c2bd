#pragma once
// The simulated laser-line scanner as a source of Profiles (core/profile.hpp), in one of two
// output modes:
//   kProfile  calibrated profiles straight from the ray-cast geometry (the fast path): the
//             measured samples of the laser line, sampled on the profile's own uniform x grid,
//             with Gaussian z noise (z_noise_mm) from a generator seeded per profile by
//             (seed, encoder tick), so a profile never depends on what was scanned before.
//   kCamera   the hardware path: the laser line is drawn into a sensor frame
//             (camera_frame_renderer.hpp), and firmware_bridge's stripe extraction,
//             triangulation and resampling turn the frame into the profile. The noise then
//             comes from the image (speckle, shot and read noise), not from z_noise_mm.
// Both give z = 0 on the visible belt, as a real scanner does; consumers remove the belt by
// a height threshold (ConditioningParameters::height_threshold_mm, range_image_scan.hpp).
//
// acquire() allocates nothing once the Profile was reserved: buffers are sized at
// construction.
#include <cstdint>
#include <memory>
#include <opencv2/core/mat.hpp>

#include "core/profile.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/laser_line_scanner.hpp"

namespace cosmos {

class SimulatedScanner {
 public:
  // The scene must outlive the scanner and be committed before acquire().
  SimulatedScanner(const ConveyorScene& scene, const ScannerParameters& parameters, ScanMode mode);
  ~SimulatedScanner();
  SimulatedScanner(const SimulatedScanner&) = delete;
  SimulatedScanner& operator=(const SimulatedScanner&) = delete;

  // Sizes a profile for this scanner (points_per_profile samples) once.
  void reserve(Profile& profile) const;
  // Exposes profile k: encoder tick k · encoder_ticks_per_profile. Sets encoder_ticks, t_us,
  // x0_mm, dx_mm and z_mm; seq is the caller's (its stream index). Never throws.
  void acquire(std::int64_t profile_index, Profile& profile) noexcept;

  // Changes the noise seed (model views draw fresh noise per view from one scanner).
  void set_seed(std::uint64_t seed) { parameters_.seed = seed; }

  ScanMode mode() const { return mode_; }
  const ScannerParameters& parameters() const { return parameters_; }
  // The last laser line (profile mode: at profile resolution; camera mode: at sensor
  // columns), and in camera mode the last frame and its stripe peaks.
  const LaserLine& last_line() const { return line_; }
  const cv::Mat& last_frame() const;
  const StripePeaks& last_peaks() const;

 private:
  struct CameraPath;

  void acquire_profile_mode(std::int64_t encoder_ticks, Profile& profile) noexcept;
  void acquire_camera_mode(std::int64_t encoder_ticks, Profile& profile) noexcept;

  ScannerParameters parameters_;
  ScanMode mode_;
  LaserLineScanner laser_;
  LaserLine line_;
  std::unique_ptr<CameraPath> camera_;
};

}  // namespace cosmos
