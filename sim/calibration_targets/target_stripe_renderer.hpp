#pragma once
// Stripe frames of analytic calibration targets as the TRUE camera of a simulated cell sees
// them: the laser sheet (y = 0 of the sheet frame, pitched against the belt by the true
// mounting's sheet_pitch_deg, scanner/sheet_pitch.hpp) lights the target's top surface at
// in-sheet height s(x) at every sensor column's worth of x; each lit point the true
// camera sees (its surface faces the camera) is projected through the true lens and drawn
// by the camera mode's own renderer (sim/camera_frame_renderer.hpp), with its noise, levels
// and stripe profile, into the rows [roi_top_px, roi_top_px + rows_px) of the sensor.
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <opencv2/core/mat.hpp>

#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/scanner_model.hpp"
#include "scanner/sheet_pitch.hpp"
#include "scanner/triangulation_geometry.hpp"
#include "sim/camera_frame_renderer.hpp"
#include "sim/laser_line_scanner.hpp"

namespace cosmos {

// The target's top surface in the sheet at x (mm): false where nothing is lit.
struct SurfacePoint {
  double s_mm = 0.0;                                  // height along the sheet
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, belt frame
  double reflectance = 1.0;
};
using SheetProfile = std::function<bool(double x_mm, SurfacePoint& point)>;

class TargetStripeRenderer {
 public:
  TargetStripeRenderer(const ScannerParameters& scanner, const TriangulationGeometry& true_geometry,
                       int roi_top_px, int rows_px, double sheet_pitch_deg = 0.0);

  cv::Mat render(const SheetProfile& profile, std::uint64_t frame_seed);
  StripeExtractionParameters extraction_parameters() const {
    return renderer_->extraction_parameters();
  }

 private:
  ScannerParameters scanner_;
  TriangulationGeometry geometry_;
  SheetPitch pitch_;
  std::unique_ptr<CameraFrameRenderer> renderer_;
  LaserLine line_;
  cv::Mat frame_;
};

}  // namespace cosmos
