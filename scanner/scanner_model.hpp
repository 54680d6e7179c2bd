#pragma once
// The simulated laser-line scanner and conveyor: every parameter with its documented default
// (config/cell.yaml, section `scanner:`, overrides them; scanner/scanner_config.hpp reads it).
//
// Geometry (scanner frame: x across the belt, y along the belt in the direction of travel,
// z up, mm; the origin on the belt surface, in the laser sheet, mid-belt):
//   - The belt surface is the plane z = 0. It moves along +y, driven by an encoder; one
//     profile is exposed every encoder_ticks_per_profile ticks, i.e. every Δy = 0.4 mm, at
//     the line rate (2,500 profiles/s: a belt speed of 1 m/s).
//   - The laser sheet is the vertical plane y = 0 across the belt. The line laser is a fan
//     from a source laser_height_mm above the belt centre (laser_model kFan): surfaces hidden
//     from the source across x lie in laser shadow. kParallel (a telecentric sheet, every
//     ray vertical) has no such shadow.
//   - The camera sits upstream (−y) at camera_height_mm, its optical axis in the y–z plane
//     tilted by the triangulation angle from the sheet, through the origin (the geometry of
//     scanner/triangulation_geometry.hpp). A lit point is measured only if the camera
//     sees it, so the belt just downstream (+y) of a step is lost in camera occlusion.
//   - The measuring range is the sensor's region of interest: lit points whose stripe would
//     fall outside the ROI rows (less the stripe half-width) or off the sensor's columns are
//     not measured, in both output modes. With the defaults (camera 600 mm above the belt,
//     512 ROI rows, the belt line at 90 % of them) heights up to ≈ 148 mm are measured for
//     |x| <= 100 mm, so every catalog part (<= 150 mm) fits in any pose that is not taller
//     than that; the camera's view narrows with height, so near the field's edges less.
#include <cstdint>
#include <span>

#include "core/parameter_visitor.hpp"
#include "core/scanner_sight.hpp"
#include "scanner/triangulation_geometry.hpp"

namespace cosmos {

enum class LaserModel : std::uint8_t { kFan, kParallel };

inline std::span<const ParameterChoice<LaserModel>> parameter_choices(LaserModel) {
  static constexpr ParameterChoice<LaserModel> kChoices[] = {{LaserModel::kFan, "fan"},
                                                             {LaserModel::kParallel, "parallel"}};
  return kChoices;
}

// What the simulated scanner delivers: kProfile calibrated profiles straight from the
// geometry, kCamera sensor frames turned into profiles by the firmware's stripe extraction
// (sim/simulated_scanner.hpp).
enum class ScanMode : std::uint8_t { kProfile, kCamera };

inline std::span<const ParameterChoice<ScanMode>> parameter_choices(ScanMode) {
  static constexpr ParameterChoice<ScanMode> kChoices[] = {{ScanMode::kProfile, "profile"},
                                                           {ScanMode::kCamera, "camera"}};
  return kChoices;
}

// Camera mode: how the sensor image of the stripe is drawn. Levels are fractions of the
// sensor's full scale, so they mean the same for 8-, 10-, 12- and 16-bit frames.
struct CameraFrameParameters {
  int bit_depth = 8;                // 8: CV_8U frames; 10, 12, 16: CV_16U words
  double stripe_sigma_px = 1.5;     // Gaussian stripe profile across the rows
  double stripe_peak_level = 0.85;  // peak at normal incidence on a white (reflectivity 1) surface
  double ambient_level = 0.04;      // uniform ambient light
  double read_noise_level = 0.006;  // σ of the dark and read noise on every pixel
  double speckle_contrast = 0.1;    // σ of the multiplicative laser speckle on stripe pixels
  double full_well_electrons = 5000.0;  // full scale in electrons: sets the shot noise
  double threshold_level = 0.08;        // extraction threshold (above ambient + 4 σ read noise)
  int background_frames = 4;            // pre-rendered ambient + read-noise frames (see renderer)

  template <class Visitor>
  void visit(Visitor& v) {
    v("bit_depth", bit_depth, "8: 8-bit frames; 10, 12, 16: 16-bit words", Range{8, 16});
    v("stripe_sigma_px", stripe_sigma_px, "Gaussian stripe profile across the rows, px",
      Range{0.3, 20});
    v("stripe_peak_level", stripe_peak_level,
      "peak at normal incidence on a white surface, of full scale", Range::above(0, 1));
    v("ambient_level", ambient_level, "uniform ambient light, of full scale", Range::below(0, 1));
    v("read_noise_level", read_noise_level, "sigma of dark and read noise, of full scale",
      Range{0, 0.5});
    v("speckle_contrast", speckle_contrast, "sigma of the multiplicative laser speckle",
      Range{0, 1});
    v("full_well_electrons", full_well_electrons, "full scale in electrons (shot noise)",
      Range{100, 1e7});
    v("threshold_level", threshold_level, "stripe extraction threshold, of full scale",
      Range::open(0, 1));
    v("background_frames", background_frames, "pre-rendered ambient and read-noise frames",
      Range{1, 64});
  }
};

struct ScannerParameters {
  // Conveyor and encoder.
  double encoder_mm_per_tick = 0.1;
  int encoder_ticks_per_profile = 4;  // Δy = 0.4 mm
  double line_rate_hz = 2500.0;

  // Optical geometry.
  double triangulation_angle_deg = 30.0;
  double camera_height_mm = 600.0;  // camera centre above the belt
  double laser_height_mm = 600.0;   // fan source above the belt centre
  LaserModel laser_model = LaserModel::kFan;
  double field_of_view_mm = 256.0;  // across the belt, at belt height
  int points_per_profile = 640;     // W: profile samples across the field of view

  // Sensor: the camera model used for camera-mode frames and for the measuring range.
  int sensor_width_px = 1280;
  int sensor_height_px = 1024;
  int roi_height_px = 512;
  double belt_row_fraction_of_roi = 0.9;

  // Surface response: a lit point is a dropout when the laser meets the surface more
  // obliquely than max_incidence_deg, or when the Lambertian reflection
  // reflectivity · cos(incidence) is below min_reflected_intensity (of a white surface at
  // normal incidence). Camera mode draws the stripe with that intensity and extracts it
  // with the matching minimum peak, so the two modes drop the same points.
  double max_incidence_deg = 80.0;
  double min_reflected_intensity = 0.2;
  double reflectivity = 1.0;

  // Measurement noise (profile mode: Gaussian on z; camera mode: image noise instead) and
  // its seed.
  double z_noise_mm = 0.02;
  std::uint64_t seed = 1;

  CameraFrameParameters camera;

  template <class Visitor>
  void visit(Visitor& v) {
    v("encoder_mm_per_tick", encoder_mm_per_tick, "belt travel per encoder tick, mm",
      Range::above(0, 100));
    v("encoder_ticks_per_profile", encoder_ticks_per_profile, "encoder ticks per profile",
      Range{1, 100000});
    v("line_rate_hz", line_rate_hz, "profiles per second (paces the belt in time)",
      Range::above(0, 1e6));
    v("triangulation_angle_deg", triangulation_angle_deg,
      "camera axis against the laser sheet, deg", Range{5, 75});
    v("camera_height_mm", camera_height_mm, "camera centre above the belt, mm", Range{50, 5000});
    v("laser_height_mm", laser_height_mm, "fan source above the belt centre, mm", Range{50, 5000});
    v("laser_model", laser_model, "fan: a line laser's fan (laser shadows); parallel: none");
    v("field_of_view_mm", field_of_view_mm, "profile width across the belt at belt height, mm",
      Range{10, 5000});
    v("points_per_profile", points_per_profile, "samples across the field of view",
      Range{16, 8192});
    v("sensor_width_px", sensor_width_px, "sensor columns", Range{64, 8192});
    v("sensor_height_px", sensor_height_px, "sensor rows", Range{16, 8192});
    v("roi_height_px", roi_height_px, "rows of the region of interest (<= sensor_height_px)",
      Range{16, 8192});
    v("belt_row_fraction_of_roi", belt_row_fraction_of_roi,
      "where the belt line falls in the ROI, of its rows", Range::open(0, 1));
    v("max_incidence_deg", max_incidence_deg, "more oblique laser incidence: dropout, deg",
      Range::open(0, 90));
    v("min_reflected_intensity", min_reflected_intensity,
      "weaker Lambertian reflection: dropout, of a white surface's", Range{0, 1});
    v("reflectivity", reflectivity, "surface reflectivity", Range::above(0, 1));
    v("z_noise_mm", z_noise_mm, "profile-mode height noise sigma, mm", Range{0, 10});
    v("seed", seed, "seed of every random number of a simulated scan");
    v.retired("background_height_mm", "conditioning.height_threshold_mm");
    v("camera", camera, "camera-mode frame drawing");
  }

  double profile_step_mm() const { return encoder_mm_per_tick * encoder_ticks_per_profile; }
  double belt_speed_mm_per_s() const { return profile_step_mm() * line_rate_hz; }
  // Where the belt is (how far it moved since encoder tick 0) at a tick count.
  double belt_offset_mm(std::int64_t encoder_ticks) const {
    return static_cast<double>(encoder_ticks) * encoder_mm_per_tick;
  }
  std::int64_t encoder_ticks_of_profile(std::int64_t profile_index) const {
    return profile_index * encoder_ticks_per_profile;
  }
  // Exposure time of a profile, taking encoder tick 0 as time 0 (the belt runs steadily).
  std::int64_t time_us_of_profile(std::int64_t profile_index) const;
  // Sample i of a profile of `samples` points lies at x = -fov/2 + (i + 1/2) · fov/samples.
  double sample_spacing_mm(int samples) const { return field_of_view_mm / samples; }
  double first_sample_x_mm(int samples) const {
    return -0.5 * field_of_view_mm + 0.5 * sample_spacing_mm(samples);
  }
  // Rows kept clear at the ROI edges: the extractor refuses a stripe cut by the frame edge.
  int roi_margin_rows() const;
};

// The camera and laser sheet of the scanner, built by firmware_bridge's design helper.
TriangulationGeometry scanner_triangulation_geometry(const ScannerParameters& parameters);
// Where that scanner measures a point from (the recognizer's surface-seen test).
ScannerSight scanner_sight(const ScannerParameters& parameters);

}  // namespace cosmos
