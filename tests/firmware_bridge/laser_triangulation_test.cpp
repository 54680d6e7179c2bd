#include "firmware_bridge/laser_triangulation.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <vector>

#include "firmware_bridge/laser_stripe_extraction.hpp"
#include "scanner/triangulation_geometry.hpp"
#include "tests/firmware_bridge/synthetic_stripe.hpp"

namespace cosmos {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A smooth part profile on the laser plane: z(x) in mm, all within the default ROI.
double surface_z_mm(double x_mm) { return 20.0 + 12.0 * std::sin(x_mm / 25.0) + 0.05 * x_mm; }

TriangulationGeometry distorted_geometry() {
  TriangulationGeometry g = make_triangulation_geometry();
  g.camera.k1 = -0.12;
  g.camera.k2 = 0.08;
  g.camera.p1 = 0.0008;
  g.camera.p2 = -0.0005;
  g.camera.k3 = -0.02;
  g.camera.cx_px += 3.7;  // a calibrated principal point is never exactly the centre
  g.camera.cy_px -= 2.2;
  return g;
}

// The surface point (x, 0, z(x)) that sensor column u sees, by bisection on x: this is
// what the simulator's camera does, drawing the stripe where the camera sees the laser.
bool surface_point_at_column(const TriangulationGeometry& g, double u_px, Eigen::Vector3d& p_mm) {
  const auto column_of = [&](double x) {
    Eigen::Vector2d uv;
    g.project_to_image({x, 0.0, surface_z_mm(x)}, uv);
    return uv.x();
  };
  double lo = -160.0;
  double hi = 160.0;
  if (!(column_of(lo) < u_px && u_px < column_of(hi))) return false;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (column_of(mid) < u_px ? lo : hi) = mid;
  }
  const double x = 0.5 * (lo + hi);
  p_mm = {x, 0.0, surface_z_mm(x)};
  return true;
}

TEST(TriangulationGeometry, DesignedCameraSeesTheBeltLineAcrossTheSensor) {
  const TriangulationGeometry g = make_triangulation_geometry();
  EXPECT_NEAR(
      (g.R_scanner_camera.transpose() * g.R_scanner_camera - Eigen::Matrix3d::Identity()).norm(),
      0.0, 1e-12);
  EXPECT_NEAR(g.R_scanner_camera.determinant(), 1.0, 1e-12);
  EXPECT_NEAR(g.t_scanner_camera_mm.z(), 300.0, 1e-9);
  // The optical axis is 30° from the vertical laser sheet.
  EXPECT_NEAR(std::acos(-g.R_scanner_camera.col(2).z()) * 180.0 / 3.14159265358979, 30.0, 1e-9);

  Eigen::Vector2d uv;
  ASSERT_TRUE(g.project_to_image({0.0, 0.0, 0.0}, uv));
  EXPECT_NEAR(uv.x(), 639.5, 1e-9);
  EXPECT_NEAR(uv.y(), 511.5, 1e-9);
  // 256 mm of belt span the 1280 columns: ±128 mm land on the outer pixel edges.
  ASSERT_TRUE(g.project_to_image({-128.0, 0.0, 0.0}, uv));
  EXPECT_NEAR(uv.x(), -0.5, 1e-9);
  ASSERT_TRUE(g.project_to_image({128.0, 0.0, 0.0}, uv));
  EXPECT_NEAR(uv.x(), 1279.5, 1e-9);
  // The belt line sits at 3/4 of the ROI height; a part's top moves the stripe up.
  EXPECT_EQ(g.roi_height_px, 256);
  EXPECT_EQ(g.roi_row_offset_px, 320);
  Eigen::Vector2d above;
  ASSERT_TRUE(g.project_to_image({0.0, 0.0, 40.0}, above));
  EXPECT_LT(above.y(), 511.5 - 100.0);
  EXPECT_GT(above.y(), g.roi_row_offset_px);
  // A point behind the camera is not seen.
  EXPECT_FALSE(g.project_to_image(g.t_scanner_camera_mm - g.R_scanner_camera.col(2), uv));
}

class Distortion : public ::testing::TestWithParam<bool> {
 protected:
  TriangulationGeometry geometry() const {
    return GetParam() ? distorted_geometry() : make_triangulation_geometry();
  }
};

TEST_P(Distortion, ProjectThenUndistortReturnsThePlanePoint) {
  const TriangulationGeometry g = geometry();
  double worst_mm = 0.0;
  for (double x = -120.0; x <= 120.0; x += 7.5) {
    for (double z = -20.0; z <= 60.0; z += 10.0) {
      const Eigen::Vector3d p(x, 0.0, z);
      Eigen::Vector2d uv;
      ASSERT_TRUE(g.project_to_image(p, uv));
      Eigen::Vector3d back;
      ASSERT_TRUE(g.image_to_laser_plane(uv, back));
      worst_mm = std::max(worst_mm, (back - p).norm());
    }
  }
  EXPECT_LE(worst_mm, 1e-6);
}

// Exact image points (from the projection) through the per-frame lookup table.
TEST_P(Distortion, LookupTableTriangulatesExactPeaksWithinAMicrometre) {
  const TriangulationGeometry g = geometry();
  const LaserTriangulator triangulator(g);
  StripePeaks peaks;
  peaks.column_offset_px = 0;
  peaks.row_px.assign(static_cast<std::size_t>(g.camera.width_px),
                      std::numeric_limits<float>::quiet_NaN());
  std::vector<Eigen::Vector3d> truth(peaks.row_px.size());
  for (int u = 0; u < g.camera.width_px; ++u) {
    Eigen::Vector3d p;
    if (!surface_point_at_column(g, u, p)) continue;
    Eigen::Vector2d uv;
    g.project_to_image(p, uv);
    peaks.row_px[static_cast<std::size_t>(u)] = static_cast<float>(uv.y());
    truth[static_cast<std::size_t>(u)] = p;
  }
  TriangulatedStripe stripe;
  triangulator.triangulate(peaks, stripe);
  double worst_mm = 0.0;
  int compared = 0;
  for (std::size_t u = 0; u < peaks.row_px.size(); ++u) {
    if (std::isnan(peaks.row_px[u])) continue;
    ASSERT_FALSE(std::isnan(stripe.x_mm[u])) << u;
    worst_mm = std::max({worst_mm, std::abs(stripe.x_mm[u] - truth[u].x()),
                         std::abs(stripe.z_mm[u] - truth[u].z())});
    ++compared;
  }
  std::printf("[ accuracy ] lookup table, %s: max error %.2e mm over %d columns\n",
              GetParam() ? "distorted" : "pinhole", worst_mm, compared);
  EXPECT_GE(compared, 1270);
  EXPECT_EQ(stripe.valid_points, compared);
  EXPECT_LE(worst_mm, 1e-3);
}

// The whole hardware path on a simulated frame: draw the stripe where the camera sees the
// surface, extract it, triangulate it, and land back on the surface.
TEST_P(Distortion, FrameRoundTripWithinAHundredthOfAMillimetre) {
  const TriangulationGeometry g = geometry();
  std::vector<double> centre_rows(static_cast<std::size_t>(g.camera.width_px), kNaN);
  std::vector<Eigen::Vector3d> truth(centre_rows.size());
  for (int u = 0; u < g.camera.width_px; ++u) {
    Eigen::Vector3d p;
    if (!surface_point_at_column(g, u, p)) continue;
    Eigen::Vector2d uv;
    g.project_to_image(p, uv);
    centre_rows[static_cast<std::size_t>(u)] = uv.y() - g.roi_row_offset_px;  // ROI rows
    truth[static_cast<std::size_t>(u)] = p;
  }
  const cv::Mat frame =
      test::render_stripe<std::uint16_t>(centre_rows, g.roi_height_px, {2.0, 50000.0});
  StripeExtractionParameters parameters;
  parameters.method = StripePeakMethod::kGaussianThreePoint;
  parameters.threshold = 5000;
  parameters.min_peak_intensity = 10000;
  LaserStripeExtractor extractor(parameters);
  StripePeaks peaks;
  ASSERT_EQ(extractor.extract(frame, {g.roi_row_offset_px, 0}, peaks), StripeExtractionStatus::kOk);
  const LaserTriangulator triangulator(g);
  TriangulatedStripe stripe;
  triangulator.triangulate(peaks, stripe);

  double worst_mm = 0.0;
  double sum2 = 0.0;
  int compared = 0;
  for (std::size_t u = 0; u < centre_rows.size(); ++u) {
    if (std::isnan(centre_rows[u])) continue;
    ASSERT_FALSE(std::isnan(stripe.z_mm[u])) << u;
    const double e = std::hypot(stripe.x_mm[u] - truth[u].x(), stripe.z_mm[u] - truth[u].z());
    worst_mm = std::max(worst_mm, e);
    sum2 += e * e;
    ++compared;
  }
  std::printf("[ accuracy ] frame round trip, %s: max %.2e mm rms %.2e mm over %d columns\n",
              GetParam() ? "distorted" : "pinhole", worst_mm, std::sqrt(sum2 / compared), compared);
  EXPECT_GE(compared, 1270);
  EXPECT_LE(worst_mm, 0.01);
}

INSTANTIATE_TEST_SUITE_P(PinholeAndDistorted, Distortion, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Distorted" : "Pinhole"; });

TEST(LaserTriangulator, RowsOutsideTheTableAndNaNPeaksGiveNaN) {
  const TriangulationGeometry g = make_triangulation_geometry();
  const LaserTriangulator triangulator(g);
  StripePeaks peaks;
  peaks.column_offset_px = 1270;
  // Columns 1270…1281 (the last two beyond the sensor); all but the first three on the
  // principal row, where the camera sees the belt.
  peaks.row_px.assign(12, 511.5f);
  peaks.row_px[0] = static_cast<float>(g.roi_row_offset_px - 1);
  peaks.row_px[1] = std::numeric_limits<float>::quiet_NaN();
  peaks.row_px[2] = static_cast<float>(g.roi_row_offset_px + g.roi_height_px);
  TriangulatedStripe stripe;
  triangulator.triangulate(peaks, stripe);
  EXPECT_EQ(stripe.valid_points, 7);
  EXPECT_TRUE(std::isnan(stripe.z_mm[0]));
  EXPECT_TRUE(std::isnan(stripe.z_mm[1]));
  EXPECT_TRUE(std::isnan(stripe.z_mm[2]));
  EXPECT_NEAR(stripe.z_mm[3], 0.0, 1e-4);
  EXPECT_NEAR(stripe.z_mm[9], 0.0, 1e-4);
  EXPECT_TRUE(std::isnan(stripe.z_mm[10]));
  EXPECT_TRUE(std::isnan(stripe.z_mm[11]));
}

}  // namespace
}  // namespace cosmos
