// Registration control points (§6.5.1, §6.7.1): the local least-squares fit of Eq. 6.7 (plane,
// or plane plus quadratic terms) at every stride-th pixel with a full smooth window, its
// normal, residual and covariance factor, on analytic planes, paraboloids and spheres.
#include "core/registration/registration_points.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "core/surface/local_surface_fit.hpp"
#include "sim/analytic_surface.hpp"
#include "sim/free_form_view_pair.hpp"
#include "tests/core/registration/plane_range_image.hpp"

namespace cosmos::testing {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(RegistrationPoints, PlaneFitGivesTheNormalAndTheRegressionCovariance) {
  RangeImage image = tilted_plane(30.0, 41, 0.5);
  image.z_mm(20, 20) = std::numeric_limits<float>::quiet_NaN();     // a hole
  for (int row = 0; row < 41; ++row) image.z_mm(30, row) += 10.0f;  // a depth-jump strip
  RegistrationPointParameters parameters;
  parameters.stride_px = 2;
  parameters.z_noise_sigma_mm = 0.03;
  for (bool quadric : {false, true}) {
    parameters.quadric_fit = quadric;
    const RegistrationPointsResult result = build_registration_points(image, parameters);
    ASSERT_EQ(result.status, RegistrationPointsStatus::kOk);
    const RegistrationPoints& points = result.points;
    EXPECT_EQ(points.grid_width, 21);
    const Eigen::Vector3d expected_normal(-std::sin(30 * kDeg), 0, std::cos(30 * kDeg));
    for (int i = 0; i < points.size(); ++i) {
      ASSERT_LT((points.normal.col(i) - expected_normal).norm(), 1e-5);
      ASSERT_NEAR(points.position_mm(2, i), std::tan(30 * kDeg) * points.position_mm(0, i) + 5.0,
                  1e-4);
      ASSERT_LT(points.residual_rms_mm(i), 1e-4);
    }
    // No 5x5 window may contain the hole (pixel 20, 20) or a step next to column 30.
    EXPECT_EQ(points.point_at_cell(10, 10), -1);
    EXPECT_EQ(points.point_at_cell(9, 9), -1);
    EXPECT_EQ(points.point_at_cell(14, 4), -1);
    EXPECT_EQ(points.point_at_cell(16, 4), -1);
    EXPECT_GE(points.point_at_cell(4, 4), 0);
    EXPECT_GE(points.point_at_cell(13, 4), 0);
    // Cells 1..19 in each direction have full windows; minus the 3x3 cells whose windows hold
    // the hole and the 3 columns of cells (pixels 28, 30, 32) whose windows hold the step.
    EXPECT_EQ(points.size(), 19 * 19 - 9 - 3 * 19);
    EXPECT_DOUBLE_EQ(points.z_noise_sigma_mm, 0.03);
  }
  // The plane's (A^T A) over 5x5 pixels of 0.5 mm is diag(25, sum dx^2, sum dy^2) =
  // diag(25, 12.5, 12.5).
  parameters.quadric_fit = false;
  const RegistrationPoints plane = build_registration_points(image, parameters).points;
  EXPECT_NEAR(plane.fit_cofactor(kHeight, kHeight), 1 / 25.0, 1e-12);
  EXPECT_NEAR(plane.fit_cofactor(kSlopeX, kSlopeX), 1 / 12.5, 1e-12);
  EXPECT_NEAR(plane.fit_cofactor(kHeight, kSlopeX), 0.0, 1e-12);
  EXPECT_EQ(plane.fit_cofactor(kCurveXX, kCurveXX), 0.0);
}

// The quadric's covariance factor is (A^T A)^-1 of Eq. 6.7's design matrix with the rows
// (1, dx, dy, dx^2, dx dy, dy^2) of the whole window, written out here from surface_basis.
TEST(RegistrationPoints, QuadricCofactorIsTheInverseOfTheWindowInformationMatrix) {
  const RangeImage image = tilted_plane(10.0, 21, 0.4);
  RegistrationPointParameters parameters;
  parameters.window_size = 7;
  parameters.z_noise_sigma_mm = 0.02;
  const RegistrationPoints points = build_registration_points(image, parameters).points;
  ASSERT_GT(points.size(), 0);
  Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients> information =
      Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients>::Zero();
  for (int dr = -3; dr <= 3; ++dr)
    for (int dc = -3; dc <= 3; ++dc) {
      const SurfaceVector row = surface_basis(dc * 0.4, dr * 0.4);
      information += row * row.transpose();
    }
  const Eigen::Matrix<double, kSurfaceCoefficients, kSurfaceCoefficients> expected =
      information.inverse();
  EXPECT_LT((points.fit_cofactor - expected).norm(), 1e-9 * expected.norm());
  // The quadratic terms make the height less certain than the plane's 1/49.
  EXPECT_GT(points.fit_cofactor(kHeight, kHeight), 1.0 / 49.0 * 1.5);
  // Over a symmetric window the slopes are uncorrelated with everything else.
  EXPECT_NEAR(points.fit_cofactor(kSlopeX, kHeight), 0.0, 1e-12);
  EXPECT_NEAR(points.fit_cofactor(kSlopeX, kCurveXX), 0.0, 1e-12);
  EXPECT_NEAR(points.fit_cofactor(kSlopeX, kSlopeY), 0.0, 1e-12);
}

TEST(RegistrationPoints, QuadricHeightIsUnbiasedOnACurvedSurfaceWherePlaneIsNot) {
  // A paraboloid z = (x^2 + y^2) / (2 R), R = 10 mm: the plane's height at the pixel is the
  // window mean, (1/R) * (window second moment 0.5 mm^2) = 0.05 mm too high.
  RangeImage image(21, 21, 0.5, 0.5);
  image.origin_x_mm = image.origin_y_mm = -5.0;
  for (int row = 0; row < 21; ++row)
    for (int column = 0; column < 21; ++column) {
      const double x = image.x_mm(column), y = image.y_mm(row);
      image.z_mm(column, row) = static_cast<float>((x * x + y * y) / 20.0);
    }
  RegistrationPointParameters parameters;
  parameters.z_noise_sigma_mm = 0.1;  // keeps the curved plane fits
  const auto quadric = build_registration_points(image, parameters).points;
  parameters.quadric_fit = false;
  const auto plane = build_registration_points(image, parameters).points;
  const int q = quadric.point_at_cell(10, 10), p = plane.point_at_cell(10, 10);
  ASSERT_GE(q, 0);
  ASSERT_GE(p, 0);
  EXPECT_NEAR(quadric.position_mm(2, q), 0.0, 1e-5);
  EXPECT_NEAR(plane.position_mm(2, p), 0.05, 1e-5);
  // The quadric's coefficients are the paraboloid's: z = (dx^2 + dy^2) / 20 at the apex.
  EXPECT_NEAR(quadric.surface(kCurveXX, q), 1.0 / 20, 1e-6);
  EXPECT_NEAR(quadric.surface(kCurveYY, q), 1.0 / 20, 1e-6);
  EXPECT_NEAR(quadric.surface(kCurveXY, q), 0.0, 1e-6);
  EXPECT_EQ(plane.surface(kCurveXX, p), 0.0);
}

// A sphere of radius 25 mm: every control point's normal, fitted height and quadratic
// coefficients against the closed form z = sqrt(R^2 - x^2 - y^2) at its pixel.
TEST(RegistrationPoints, SphereControlPointsFollowTheClosedFormSurface) {
  AnalyticSurfaceSpec spec;
  spec.shape = AnalyticShape::kSphere;
  spec.radius_mm = 25.0;
  const AnalyticSurface sphere = make_analytic_surface(spec);
  RegistrationPointParameters parameters;
  parameters.stride_px = 2;
  parameters.z_noise_sigma_mm = 0.01;
  const RegistrationPointsResult result = build_registration_points(sphere.range, parameters);
  ASSERT_EQ(result.status, RegistrationPointsStatus::kOk);
  const RegistrationPoints& points = result.points;
  ASSERT_GT(points.size(), 1000);
  // Within 45 degrees of the apex the 2 mm window sees a nearly quadratic surface; towards the
  // rim (up to the 75 degree tilt limit) the higher-order terms grow, and so does the error.
  double worst_normal = 0, worst_height_mm = 0, worst_curvature = 0;
  double worst_normal_rim = 0, worst_height_rim_mm = 0;
  int near_apex = 0;
  for (int v = 0; v < points.grid_height; ++v)
    for (int u = 0; u < points.grid_width; ++u) {
      const int i = points.point_at_cell(u, v);
      if (i < 0) continue;
      const AnalyticTruth& truth = sphere.truth(2 * u, 2 * v);
      ASSERT_TRUE(truth.valid);
      EXPECT_DOUBLE_EQ(points.position_mm(0, i), sphere.range.x_mm(2 * u));
      EXPECT_DOUBLE_EQ(points.position_mm(1, i), sphere.range.y_mm(2 * v));
      const double normal_error = (points.normal.col(i) - truth.normal.cast<double>()).norm();
      const double height_error_mm = std::abs(points.position_mm(2, i) - truth.z_mm);
      worst_normal_rim = std::max(worst_normal_rim, normal_error);
      worst_height_rim_mm = std::max(worst_height_rim_mm, height_error_mm);
      const double x = points.position_mm(0, i), y = points.position_mm(1, i);
      const double w2 = 625.0 - x * x - y * y;
      if (w2 < 625.0 * 0.5) continue;  // beyond 45 degrees from the apex
      ++near_apex;
      worst_normal = std::max(worst_normal, normal_error);
      worst_height_mm = std::max(worst_height_mm, height_error_mm);
      const double w3 = w2 * std::sqrt(w2);
      // Taylor coefficients of z at (x, y): z_xx / 2, z_xy, z_yy / 2.
      worst_curvature = std::max(
          {worst_curvature, std::abs(points.surface(kCurveXX, i) + 0.5 * (625.0 - y * y) / w3),
           std::abs(points.surface(kCurveXY, i) + x * y / w3),
           std::abs(points.surface(kCurveYY, i) + 0.5 * (625.0 - x * x) / w3)});
    }
  std::printf(
      "sphere within 45 deg (%d points): normal %.2e, height %.2e mm, curvature %.2e 1/mm; "
      "all: normal %.2e, height %.2e mm\n",
      near_apex, worst_normal, worst_height_mm, worst_curvature, worst_normal_rim,
      worst_height_rim_mm);
  EXPECT_GT(near_apex, 500);
  EXPECT_LT(worst_normal, 3e-3);  // the cubic terms bias the window's slopes
  EXPECT_LT(worst_height_mm, 2e-4);
  EXPECT_LT(worst_curvature, 1e-3);  // the apex value is 1 / (2 R) = 0.02
  EXPECT_LT(worst_normal_rim, 0.03);
  EXPECT_LT(worst_height_rim_mm, 0.02);
}

// §6.7.1: steeper surface than max_tilt_deg is not taken.
TEST(RegistrationPoints, TiltLimitDropsExactlyTheSteeperPoints) {
  AnalyticSurfaceSpec spec;
  spec.shape = AnalyticShape::kSphere;
  const AnalyticSurface sphere = make_analytic_surface(spec);
  RegistrationPointParameters parameters;
  parameters.stride_px = 2;
  parameters.z_noise_sigma_mm = 0.01;
  parameters.max_tilt_deg = 40.0;
  const RegistrationPoints points = build_registration_points(sphere.range, parameters).points;
  parameters.max_tilt_deg = 89.0;
  const RegistrationPoints all = build_registration_points(sphere.range, parameters).points;
  ASSERT_GT(all.size(), points.size());
  const double min_normal_z = std::cos(40.0 * kDeg);
  int steep_dropped = 0, kept = 0;
  for (int v = 0; v < all.grid_height; ++v)
    for (int u = 0; u < all.grid_width; ++u) {
      const int i = all.point_at_cell(u, v);
      if (i < 0) continue;
      const bool steep = all.normal(2, i) < min_normal_z;
      EXPECT_EQ(points.point_at_cell(u, v) >= 0, !steep) << u << ", " << v;
      steep_dropped += steep;
      kept += !steep;
    }
  EXPECT_GT(steep_dropped, 100);
  EXPECT_EQ(points.size(), kept);
}

TEST(RegistrationPoints, NoiseIsEstimatedFromThePlaneResiduals) {
  RangeImage image = tilted_plane(20.0, 81, 0.5);
  add_z_noise(image, 0.04, 7);
  const RegistrationPointsResult result = build_registration_points(image, {});
  ASSERT_EQ(result.status, RegistrationPointsStatus::kOk);
  EXPECT_NEAR(result.points.z_noise_sigma_mm, 0.04, 0.004);
  RegistrationPointParameters bad;
  bad.window_size = 4;
  EXPECT_EQ(build_registration_points(image, bad).status,
            RegistrationPointsStatus::kInvalidParameters);
}

// A rough strip (noise ten times the rest) is taken for a crease: above 3 times the median
// residual, its windows are not control points (§6.7.1 local smoothness).
TEST(RegistrationPoints, RoughWindowsAreLeftOut) {
  RangeImage image = tilted_plane(0.0, 61, 0.5);
  add_z_noise(image, 0.01, 5);
  RangeImage rough = image;
  add_z_noise(rough, 0.1, 6);
  for (int row = 0; row < 61; ++row)
    for (int column = 40; column < 61; ++column) image.z_mm(column, row) = rough.z_mm(column, row);
  const RegistrationPoints points = build_registration_points(image, {.stride_px = 2}).points;
  EXPECT_NEAR(points.z_noise_sigma_mm, 0.01, 0.002);
  int smooth_kept = 0, rough_kept = 0;
  for (int i = 0; i < points.size(); ++i) {
    const double x = points.position_mm(0, i);
    const double first_rough_x = image.x_mm(40);
    if (x < first_rough_x - 1.0) ++smooth_kept;  // whole window smooth
    if (x > first_rough_x + 1.0) ++rough_kept;   // whole window rough
  }
  EXPECT_GT(smooth_kept, 300);
  EXPECT_EQ(rough_kept, 0);
}

TEST(RegistrationPoints, TooFewPointsAndBadParametersAreReported) {
  // A 6 x 6 image has full 5x5 windows at 2 x 2 pixels only: fewer than the 6 parameters.
  const RangeImage tiny = tilted_plane(0.0, 6, 0.5);
  EXPECT_EQ(build_registration_points(tiny, {}).status, RegistrationPointsStatus::kTooFewPoints);
  const RangeImage image = tilted_plane(0.0, 21, 0.5);
  EXPECT_EQ(build_registration_points(image, {}).status, RegistrationPointsStatus::kOk);
  for (const RegistrationPointParameters& bad :
       {RegistrationPointParameters{.stride_px = 0}, RegistrationPointParameters{.window_size = 1},
        RegistrationPointParameters{.depth_jump_mm = 0.0},
        RegistrationPointParameters{.max_residual_noise_ratio = 0.0},
        RegistrationPointParameters{.max_tilt_deg = 90.0},
        RegistrationPointParameters{.z_noise_sigma_mm = -0.1}})
    EXPECT_EQ(build_registration_points(image, bad).status,
              RegistrationPointsStatus::kInvalidParameters);
}

TEST(RegistrationPoints, SelectAndSpreadSubsetsKeepEachPointsValues) {
  const RegistrationPoints points =
      build_registration_points(tilted_plane(15.0, 23, 0.5), {.z_noise_sigma_mm = 0.02}).points;
  ASSERT_EQ(points.size(), 19 * 19);
  const RegistrationPoints chosen = select_points(points, {7, 3, 300});
  ASSERT_EQ(chosen.size(), 3);
  const int source[] = {7, 3, 300};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(chosen.position_mm.col(k), points.position_mm.col(source[k]));
    EXPECT_EQ(chosen.normal.col(k), points.normal.col(source[k]));
    EXPECT_EQ(chosen.surface.col(k), points.surface.col(source[k]));
    EXPECT_EQ(chosen.residual_rms_mm(k), points.residual_rms_mm(source[k]));
  }
  EXPECT_EQ(chosen.fit_cofactor, points.fit_cofactor);
  EXPECT_EQ(chosen.z_noise_sigma_mm, 0.02);
  EXPECT_EQ(chosen.grid_width, 0);  // scene points: no model-side grid
  // 361 points, about 100 wanted: every 3rd, 0, 3, ..., 360.
  const RegistrationPoints spread = spread_subset(points, 100);
  ASSERT_EQ(spread.size(), 121);
  for (int k = 0; k < spread.size(); ++k)
    ASSERT_EQ(spread.position_mm.col(k), points.position_mm.col(3 * k));
  EXPECT_EQ(spread_subset(points, 1000).size(), points.size());
}

// A flat face of 20 x 20 points 1 mm apart and, beyond one of its corners, a small raised
// feature of 3 points: the quick fits' subset reaches the face's corners and the feature; an
// even subset of as many points lies on the face alone.
TEST(RegistrationPoints, FarthestPointSubsetReachesTheEndsAndTheSmallFeatures) {
  RegistrationPoints points;
  points.position_mm.resize(3, 403);
  points.normal.resize(3, 403);
  points.surface.setZero(kSurfaceCoefficients, 403);
  points.residual_rms_mm.setZero(403);
  for (int i = 0; i < 400; ++i) points.position_mm.col(i) << i % 20, i / 20, 0;
  for (int i = 400; i < 403; ++i) points.position_mm.col(i) << 22 + (i - 400), 21, 5;
  points.normal.setZero();
  points.normal.row(2).setOnes();

  const std::vector<int> source = farthest_point_indices(points, 12);
  ASSERT_EQ(source.size(), 12u);
  EXPECT_TRUE(std::is_sorted(source.begin(), source.end()));  // grid order
  EXPECT_EQ(std::adjacent_find(source.begin(), source.end()), source.end());
  for (const int corner : {0, 399})  // the face's two ends farthest apart
    EXPECT_NE(std::find(source.begin(), source.end(), corner), source.end()) << corner;
  EXPECT_NE(std::find_if(source.begin(), source.end(), [](int i) { return i >= 400; }),
            source.end());
  const RegistrationPoints subset = select_points(points, source);
  // No two chosen points closer than the face's spacing times a few: spread over the scene.
  double closest_mm = std::numeric_limits<double>::infinity();
  for (int a = 0; a < subset.size(); ++a)
    for (int b = a + 1; b < subset.size(); ++b)
      closest_mm =
          std::min(closest_mm, (subset.position_mm.col(a) - subset.position_mm.col(b)).norm());
  EXPECT_GE(closest_mm, 4.0);
  // And every point of the scene lies near one of them.
  const auto farthest_from_subset_mm = [&](const RegistrationPoints& chosen) {
    double farthest_mm = 0;
    for (int i = 0; i < points.size(); ++i) {
      double nearest_mm = std::numeric_limits<double>::infinity();
      for (int k = 0; k < chosen.size(); ++k)
        nearest_mm =
            std::min(nearest_mm, (points.position_mm.col(i) - chosen.position_mm.col(k)).norm());
      farthest_mm = std::max(farthest_mm, nearest_mm);
    }
    return farthest_mm;
  };
  EXPECT_LE(farthest_from_subset_mm(subset), 6.0);

  const RegistrationPoints even = spread_subset(points, 12);
  EXPECT_EQ((even.position_mm.row(2).array() > 0).count(), 0);
  EXPECT_GT(farthest_from_subset_mm(even), 7.0);
  EXPECT_EQ(farthest_point_indices(points, 403).size(), 403u);
  EXPECT_EQ(farthest_point_indices(points, 1000).size(), 403u);
  EXPECT_TRUE(farthest_point_indices(points, 0).empty());
  EXPECT_TRUE(farthest_point_indices(RegistrationPoints{}, 12).empty());
}

TEST(RegistrationPoints, DarbouxFrameNormalsReplaceThePlaneNormalsWhereValid) {
  const RangeImage image = render_free_form_part(RigidTransform::identity(), FreeFormPartSpec{});
  const DarbouxFrameField frames = fit_local_surfaces(image, SurfaceFitParameters{});
  const auto with_frames = build_registration_points(image, {.stride_px = 3}, &frames).points;
  const auto without = build_registration_points(image, {.stride_px = 3}).points;
  ASSERT_EQ(with_frames.size(), without.size());
  double max_error_with = 0, max_error_without = 0;
  for (int i = 0; i < with_frames.size(); ++i) {
    const Eigen::Vector2d g =
        free_form_gradient(with_frames.position_mm(0, i), with_frames.position_mm(1, i));
    const Eigen::Vector3d truth = Eigen::Vector3d(-g.x(), -g.y(), 1).normalized();
    max_error_with = std::max(max_error_with, (with_frames.normal.col(i) - truth).norm());
    max_error_without = std::max(max_error_without, (without.normal.col(i) - truth).norm());
  }
  std::printf("max normal error: Darboux frames %.4f, quadric fit %.4f\n", max_error_with,
              max_error_without);
  EXPECT_LT(max_error_with, 0.01);
  EXPECT_LT(max_error_without, 0.03);
}

}  // namespace
}  // namespace cosmos::testing
