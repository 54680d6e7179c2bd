#include "scanner/scanner_model.hpp"

#include <cmath>

namespace cosmos {

std::int64_t ScannerParameters::time_us_of_profile(std::int64_t profile_index) const {
  return std::llround(static_cast<double>(profile_index) * 1e6 / line_rate_hz);
}

int ScannerParameters::roi_margin_rows() const {
  return static_cast<int>(std::ceil(3.0 * camera.stripe_sigma_px)) + 1;
}

TriangulationGeometry scanner_triangulation_geometry(const ScannerParameters& parameters) {
  TriangulationDesign design;
  design.triangulation_angle_deg = parameters.triangulation_angle_deg;
  design.standoff_mm = parameters.camera_height_mm;
  design.field_of_view_across_mm = parameters.field_of_view_mm;
  design.sensor_width_px = parameters.sensor_width_px;
  design.sensor_height_px = parameters.sensor_height_px;
  design.roi_height_px = parameters.roi_height_px;
  design.belt_row_fraction_of_roi = parameters.belt_row_fraction_of_roi;
  return make_triangulation_geometry(design);
}

ScannerSight scanner_sight(const ScannerParameters& parameters) {
  ScannerSight sight;
  sight.camera_mm = scanner_triangulation_geometry(parameters).t_scanner_camera_mm;
  sight.laser_height_mm =
      parameters.laser_model == LaserModel::kFan ? parameters.laser_height_mm : 0;
  return sight;
}

}  // namespace cosmos
