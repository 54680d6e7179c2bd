#pragma once
// The ray-cast laser line: for one position of the belt, the surface points the laser sheet
// lights, sampled at uniform x across the field of view, and for each whether the scanner
// can measure it. Both output modes start here: profile mode adds z noise to the measured
// samples, camera mode draws the lit points into a sensor frame.
//
// How a sample is found (Embree rays in the belt frame, see conveyor_scene.hpp):
//   1. A probe ray straight down the sheet at the sample's x finds the top surface point
//      (the belt, z = 0, when it meets no part). Sampling at the grid x itself gives every
//      profile sample its exact height: there is no interpolation error to confuse with
//      sensor noise. Where a fan ray would light a lower surface under an overhang at the
//      same x, the probe reports the top surface; the resampling of a real sensor keeps the
//      higher surface there too (firmware_bridge/profile_resampling.hpp).
//   2. Laser shadow (fan model): a top point is lit iff no top point between it and the
//      source's x rises above the fan ray to it — the horizon of the source, swept outward
//      from the source in the sheet. Any occluder of a fan ray lies in the sheet and under a
//      top point, so this needs no extra ray; it resolves shadow edges to one sample.
//   3. Incidence (laser ray vs surface normal) beyond max_incidence_deg: dropout.
//   4. Camera occlusion: a surface facing away from the camera, or an Embree occlusion ray
//      from the point to the camera centre that meets a part, hides the point. Belt points
//      whose line of sight clears every part's coarse height bounds (height_bound_grid.hpp)
//      need no ray.
//   5. Measuring range: the camera's projection of the point must fall on the sensor
//      columns and inside the ROI rows, clear of the stripe half-width at the edges.
//   6. Reflected intensity reflectivity · cos(incidence) below the minimum: dark.
// Rays are traced in packets of 8 in sample order, one thread: the result never depends on
// timing. After construction nothing allocates.
#include <cstdint>
#include <limits>
#include <vector>

#include "scanner/scanner_model.hpp"
#include "scanner/sheet_pitch.hpp"
#include "scanner/triangulation_geometry.hpp"
#include "sim/conveyor_scene.hpp"

namespace cosmos {

enum class LaserSampleState : std::uint8_t {
  kMeasured,        // lit, seen by the camera, in range, bright enough
  kDark,            // as kMeasured but reflects less than min_reflected_intensity
  kLaserShadow,     // the laser fan does not reach it
  kGrazing,         // incidence beyond max_incidence_deg
  kCameraOccluded,  // the camera does not see it
  kOutOfRange,      // its image falls outside the sensor's ROI
};

// One laser line, sample i at x = x0_mm + i · dx_mm. Owned by the caller, reused.
struct LaserLine {
  double x0_mm = 0.0;
  double dx_mm = 1.0;
  std::vector<float> z_mm;       // top surface height along the sheet (0 on the belt)
  std::vector<float> intensity;  // reflectivity · cos(incidence); 0 where unlit
  std::vector<float> u_px;       // camera image of the point, full-sensor pixels
  std::vector<float> v_px;
  std::vector<LaserSampleState> state;

  int width() const { return static_cast<int>(z_mm.size()); }
  double x_mm(int i) const { return x0_mm + i * dx_mm; }
};

class LaserLineScanner {
 public:
  // `samples` points across the field of view. The scene must outlive the scanner and be
  // committed before tracing. `sheet_pitch_deg` tilts the scanner head about the belt's x axis
  // (scanner/sheet_pitch.hpp): the sheet, the source and the camera turn together, and the
  // line's z_mm are in-sheet heights, as the scanner's own triangulation measures them.
  LaserLineScanner(const ConveyorScene& scene, const ScannerParameters& parameters, int samples,
                   double sheet_pitch_deg = 0.0);

  // Sizes `line` for this scanner once, so that trace() never allocates.
  void reserve(LaserLine& line) const;
  // The laser line when the sheet lies at y = laser_y_belt_mm in the belt frame
  // (laser_y_belt_mm(parameters, k) for profile k).
  // With a pitched sheet, laser_y_belt_mm is the sheet's foot on the belt.
  void trace(double laser_y_belt_mm, LaserLine& line);

  const ScannerParameters& parameters() const { return parameters_; }
  const TriangulationGeometry& geometry() const { return geometry_; }

 private:
  // Rays down the sheet from the height top_z_mm onto samples [first, end).
  void probe_top_surface(double y_mm, int first, int end, double top_z_mm, LaserLine& line);
  // The x span of `part` the sheet can meet when its foot is at y_mm: false if none.
  bool sheet_x_extent(const PlacedPart& part, double y_mm, double& low_mm, double& high_mm) const;
  void sweep_laser_horizon(LaserLine& line) const;
  // What steps 3-6 make of a lit top point (sheet frame: the sheet is y = 0), camera
  // occlusion by the parts aside.
  struct LitPoint {
    LaserSampleState state = LaserSampleState::kMeasured;
    float intensity = 0.0f;
    float u_px = std::numeric_limits<float>::quiet_NaN();
    float v_px = std::numeric_limits<float>::quiet_NaN();
  };
  LitPoint classify_lit_point(const Eigen::Vector3d& point_scanner_mm,
                              const Eigen::Vector3d& normal, double cos_incidence) const;
  void classify(double y_mm, LaserLine& line);
  void trace_camera_occlusion(double y_mm, LaserLine& line);

  // The camera's centre in the belt frame when the sheet's foot is at y_mm.
  Eigen::Vector3d camera_belt_mm(double y_mm) const;

  const ConveyorScene& scene_;
  ScannerParameters parameters_;
  SheetPitch pitch_;
  TriangulationGeometry geometry_;
  int samples_ = 0;
  double cos_max_incidence_ = 0.0;
  double min_roi_row_px_ = 0.0;
  double max_roi_row_px_ = 0.0;
  // Each sample's belt point (the sheet at z = 0) classified once: the same in every profile.
  std::vector<LitPoint> belt_samples_;
  // Scratch, sized at construction: unit normals (belt frame) of the top points, and the
  // samples whose camera ray must be traced.
  std::vector<float> normal_x_;
  std::vector<float> normal_y_;
  std::vector<float> normal_z_;
  std::vector<int> occlusion_candidates_;
  // The parts that may hide the belt from the camera in the current line, with their sight.
  struct PartSight {
    const PlacedPart* part = nullptr;
    HeightBoundGrid::BeltSight sight;
  };
  std::vector<PartSight> belt_sights_;
  std::vector<int> belt_sight_marks_;  // difference array of HeightBoundGrid::mark_belt_sights
};

}  // namespace cosmos
