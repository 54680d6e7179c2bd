#include "sim/calibration_targets/target_stripe_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scanner/simulated_mounting.hpp"

namespace cosmos {
namespace {

TEST(TargetStripeRenderer, TheBeltsStripeLiesWhereTheRolledTrueCameraSeesIt) {
  ScannerParameters scanner;
  scanner.sensor_width_px = 640;
  scanner.sensor_height_px = 512;
  scanner.roi_height_px = 256;
  SimulatedMounting truth;
  truth.roll_deg = 0.5;
  truth.laser_plane_tilt_deg = 1.0;
  const TriangulationGeometry geometry = true_triangulation_geometry(scanner, truth);
  const TriangulationGeometry designed = scanner_triangulation_geometry(scanner);
  TargetStripeRenderer renderer(scanner, geometry, designed.roi_row_offset_px,
                                designed.roi_height_px);
  const cv::Mat frame = renderer.render(
      [](double, SurfacePoint& point) {
        point.reflectance = 0.5;
        return true;
      },
      21);
  LaserStripeExtractor extractor(renderer.extraction_parameters());
  StripePeaks peaks;
  ASSERT_EQ(extractor.extract(frame, {designed.roi_row_offset_px, 0}, peaks),
            StripeExtractionStatus::kOk);
  int compared = 0;
  double worst_px = 0.0;
  for (double x = -100.0; x <= 100.0; x += 10.0) {
    Eigen::Vector2d uv;
    ASSERT_TRUE(geometry.project_to_image({x, 0.0, 0.0}, uv));
    const int column = static_cast<int>(std::lround(uv.x()));
    // The stripe's row at the column's centre: the line's slope times the sub-column offset.
    Eigen::Vector2d next;
    geometry.project_to_image({x + 1.0, 0.0, 0.0}, next);
    const double row = uv.y() + (column - uv.x()) * (next.y() - uv.y()) / (next.x() - uv.x());
    const float found = peaks.row_px[static_cast<std::size_t>(column)];
    ASSERT_TRUE(std::isfinite(found)) << "column " << column;
    worst_px = std::max(worst_px, std::abs(found - row));
    ++compared;
  }
  EXPECT_EQ(compared, 21);
  EXPECT_LT(worst_px, 0.15);
  // The rolled camera sees the belt's line slope across the image: its ends differ in row.
  Eigen::Vector2d left, right;
  geometry.project_to_image({-100.0, 0.0, 0.0}, left);
  geometry.project_to_image({100.0, 0.0, 0.0}, right);
  EXPECT_GT(std::abs(left.y() - right.y()), 1.5);
}

}  // namespace
}  // namespace cosmos
