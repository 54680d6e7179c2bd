#pragma once
// T_cell_scanner from a scan of the sphere plate (calibration_targets.hpp): the frames are
// triangulated through the calibrated scanner, laid out along the belt by their encoder
// counts (belt frame: y = −ticks · mm_per_tick at the sheet's foot, each point up the
// pitched sheet from there, scanner/sheet_pitch.hpp), the points above the plate
// grouped into spheres, each sphere's centre fitted with the known radius, carried to the
// belt position of the target file's encoder count, and matched to the file's cell-frame
// centres by the rigid fit of least residual over every pairing.
#include <string>
#include <vector>

#include "calibration/calibration_targets.hpp"
#include "calibration/stripe_frame.hpp"
#include "core/rigid_transform.hpp"
#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/sheet_pitch.hpp"
#include "scanner/triangulation_geometry.hpp"

namespace cosmos {

struct CellFrameSettings {
  int min_points_per_sphere = 40;
  // A pairing whose worst feature is further off is no match of the file to the scan.
  double max_feature_residual_mm = 1.0;
};

struct CellFrameResult {
  bool ok = false;
  std::string reason;
  RigidTransform T_cell_scanner;
  std::vector<Eigen::Vector3d> centres_scanner_mm;  // fitted, in the file's order
  std::vector<double> sphere_rms_mm;                // radial residual of each fit
  std::vector<double> feature_residual_mm;          // |T c_scanner − c_cell| per feature
  double rms_mm = 0.0;
  std::vector<Eigen::Vector3d> points_belt;  // every point above the plate, for the report
};

CellFrameResult calibrate_cell_frame(const std::vector<StripeFrame>& frames,
                                     const SpherePlate& plate,
                                     const TriangulationGeometry& geometry, double mm_per_tick,
                                     double sheet_pitch_deg,
                                     const StripeExtractionParameters& extraction,
                                     const CellFrameSettings& settings = {});

}  // namespace cosmos
