// The correspondence of Chen-Medioni registration (§6.4): the line through a scene point meets
// the model surface, whose tangent plane there gives the signed distance d_s (Eq. 6.5); and
// the variance of d_s (Eqs. 6.21-6.22, regression form), on planes with known geometry and on
// the free-form relief.
#include "core/registration/tangent_plane_correspondence.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "core/registration/registration_points.hpp"
#include "sim/free_form_view_pair.hpp"
#include "tests/core/registration/plane_range_image.hpp"

namespace cosmos::testing {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The plane z = tan(tilt) x + 5 over 41 x 41 pixels of 0.5 mm (x, y in [-10, 10] mm), a control
// point at every pixel with a full window.
RegistrationPoints plane_model(double tilt_deg, bool quadric = true) {
  RegistrationPointParameters parameters;
  parameters.z_noise_sigma_mm = 0.03;
  parameters.quadric_fit = quadric;
  return build_registration_points(tilted_plane(tilt_deg, 41, 0.5), parameters).points;
}

Eigen::Vector3d plane_normal(double tilt_deg) {
  return {-std::sin(tilt_deg * kDeg), 0.0, std::cos(tilt_deg * kDeg)};
}

double plane_height_mm(double tilt_deg, double x_mm) {
  return std::tan(tilt_deg * kDeg) * x_mm + 5.0;
}

// Eq. 6.5 on a plane: d_s is the perpendicular distance of the point from the plane, whatever
// the direction of the line that found the foot; positive above.
TEST(TangentPlaneCorrespondence, DistanceToAKnownPlaneIsThePerpendicularOne) {
  const RegistrationPoints model = plane_model(30.0);
  const Eigen::Vector3d n = plane_normal(30.0);
  const Eigen::Vector3d on_plane(1.3, -2.1, plane_height_mm(30.0, 1.3));
  for (double offset_mm : {0.7, -0.4, 0.0})
    for (double line_deg : {0.0, 20.0, -35.0, 50.0}) {
      const Eigen::Vector3d p = on_plane + offset_mm * n;
      // The line turned by line_deg about y from the vertical, pointing down.
      const Eigen::Vector3d direction(std::sin(line_deg * kDeg), 0.0, -std::cos(line_deg * kDeg));
      TangentPlaneCorrespondence c;
      ASSERT_EQ(find_tangent_plane(model, p, direction, 6, c), CorrespondenceStatus::kFound)
          << offset_mm << " " << line_deg;
      EXPECT_NEAR(c.distance_mm, offset_mm, 1e-5) << offset_mm << " " << line_deg;
      EXPECT_LT((c.model_normal - n).norm(), 1e-5);
      EXPECT_NEAR(c.model_slope.x(), std::tan(30.0 * kDeg), 1e-5);
      EXPECT_NEAR(c.model_slope.y(), 0.0, 1e-5);
      // The foot lies on the plane and on the line.
      EXPECT_NEAR(c.model_point_mm.z(), plane_height_mm(30.0, c.model_point_mm.x()), 1e-5);
      const Eigen::Vector3d along = c.model_point_mm - p;
      EXPECT_LT(along.cross(direction).norm(), 1e-5);
      EXPECT_NEAR(c.travel_mm, along.norm(), 1e-12);
      // A vertical line, or a point on the plane, settles at once; another line needs one
      // more step to confirm the foot.
      EXPECT_EQ(c.steps, line_deg == 0.0 || offset_mm == 0.0 ? 1 : 2);
    }
}

TEST(TangentPlaneCorrespondence, NearestModelPointIsTheCellWithTheLargestBlendWeight) {
  const RegistrationPoints model = plane_model(0.0);
  // Pixel 12, 7 is at (-10 + 6, -10 + 3.5); a point 0.2 mm right and 0.1 mm down of it.
  const double x = -10.0 + 12 * 0.5 + 0.2, y = -10.0 + 7 * 0.5 + 0.1;
  TangentPlaneCorrespondence c;
  ASSERT_EQ(find_tangent_plane(model, {x, y, 6.0}, {0, 0, -1}, 6, c), CorrespondenceStatus::kFound);
  EXPECT_EQ(c.nearest_model_point, model.point_at_cell(12, 7));
  EXPECT_NEAR(c.distance_mm, 1.0, 1e-6);
  ASSERT_EQ(find_tangent_plane(model, {x + 0.1, y + 0.2, 4.5}, {0, 0, -1}, 6, c),
            CorrespondenceStatus::kFound);
  EXPECT_EQ(c.nearest_model_point, model.point_at_cell(13, 8));
  EXPECT_NEAR(c.distance_mm, -0.5, 1e-6);
}

TEST(TangentPlaneCorrespondence, OffModelGrazingAndUnsettledLinesAreReported) {
  RangeImage image = tilted_plane(0.0, 41, 0.5);
  image.z_mm(20, 20) = std::numeric_limits<float>::quiet_NaN();
  const RegistrationPoints model =
      build_registration_points(image, {.z_noise_sigma_mm = 0.03}).points;
  TangentPlaneCorrespondence c;
  // Over the hole: no control points around (0, 0).
  EXPECT_EQ(find_tangent_plane(model, {0.1, 0.1, 6.0}, {0, 0, -1}, 6, c),
            CorrespondenceStatus::kOffModel);
  // Beyond the grid.
  EXPECT_EQ(find_tangent_plane(model, {30.0, 0.0, 6.0}, {0, 0, -1}, 6, c),
            CorrespondenceStatus::kOffModel);
  // The line meets the plane at 80 degrees from its normal: too tangential (limit ~78.5);
  // at 75 degrees it is found.
  const Eigen::Vector3d p(-5.0, 5.0, 5.1);
  const auto line_at = [](double deg) {
    return Eigen::Vector3d(std::sin(deg * kDeg), 0.0, -std::cos(deg * kDeg));
  };
  EXPECT_EQ(find_tangent_plane(model, p, line_at(80.0), 6, c), CorrespondenceStatus::kGrazing);
  EXPECT_EQ(find_tangent_plane(model, p, line_at(75.0), 6, c), CorrespondenceStatus::kFound);
  EXPECT_NEAR(c.distance_mm, 0.1, 1e-5);
  // An oblique line needs two intersections: with a budget of one, the foot has not settled.
  EXPECT_EQ(find_tangent_plane(model, p, line_at(30.0), 1, c), CorrespondenceStatus::kNotConverged);
  EXPECT_EQ(c.steps, 1);
}

// Eqs. 6.21-6.22 by hand on the plane fit (cofactor diag(1/25, 1/12.5, 1/12.5) over 5x5 pixels
// of 0.5 mm): at offsets (dx, dy) from the nearest control point of a horizontal model,
// grad = -(1, dx, dy), so sigma^2 = sigma_m^2 (1/25 + (dx^2 + dy^2) / 12.5) plus the scene's
// height variance times (n . scene z axis)^2.
TEST(TangentPlaneCorrespondence, DistanceVarianceOfAHorizontalPlaneByHand) {
  const RegistrationPoints model = plane_model(0.0, false);
  const double sigma2 = 0.03 * 0.03;
  const double dx = 0.2, dy = -0.1;
  const Eigen::Vector3d p(-10.0 + 12 * 0.5 + dx, -10.0 + 7 * 0.5 + dy, 5.4);
  TangentPlaneCorrespondence c;
  ASSERT_EQ(find_tangent_plane(model, p, {0, 0, -1}, 6, c), CorrespondenceStatus::kFound);
  ASSERT_EQ(c.nearest_model_point, model.point_at_cell(12, 7));
  const double model_term = sigma2 * (1.0 / 25 + (dx * dx + dy * dy) / 12.5);
  EXPECT_NEAR(distance_variance_mm2(model, c, p, 0.0, Eigen::Vector3d::UnitZ()), model_term, 1e-12);
  // The scene's own height variance enters along its viewing axis: cos^2 of its tilt.
  const double scene_variance = 0.0004;
  const Eigen::Vector3d tilted_axis(std::sin(40 * kDeg), 0.0, std::cos(40 * kDeg));
  EXPECT_NEAR(distance_variance_mm2(model, c, p, scene_variance, Eigen::Vector3d::UnitZ()),
              model_term + scene_variance, 1e-12);
  EXPECT_NEAR(distance_variance_mm2(model, c, p, scene_variance, tilted_axis),
              model_term + scene_variance * std::cos(40 * kDeg) * std::cos(40 * kDeg), 1e-12);
}

// On a tilted plane (slope a) at a control point (dx = dy = 0) the slope's uncertainty enters
// through d_s: grad = (-1/|N|, -d a/|N|^2, 0, ...), |N|^2 = 1 + a^2, so
// sigma^2 = sigma_m^2 (1 / (25 |N|^2) + d^2 a^2 / (12.5 |N|^4)).
TEST(TangentPlaneCorrespondence, DistanceVarianceOfATiltedPlaneGrowsWithTheDistance) {
  const RegistrationPoints model = plane_model(30.0, false);
  const double a = std::tan(30.0 * kDeg);
  const double norm2 = 1.0 + a * a;
  const double sigma2 = 0.03 * 0.03;
  const int k = model.point_at_cell(20, 20);
  ASSERT_GE(k, 0);
  const Eigen::Vector3d foot = model.position_mm.col(k);
  double previous = 0.0;
  for (double d : {0.0, 0.5, 1.5}) {
    // Vertically above the control point, so the foot (and dx, dy) stay at it.
    const Eigen::Vector3d p = foot + Eigen::Vector3d(0, 0, d * std::sqrt(norm2));
    TangentPlaneCorrespondence c;
    ASSERT_EQ(find_tangent_plane(model, p, {0, 0, -1}, 6, c), CorrespondenceStatus::kFound);
    ASSERT_EQ(c.nearest_model_point, k);
    ASSERT_NEAR(c.distance_mm, d, 1e-5);
    const double expected = sigma2 * (1.0 / (25 * norm2) + d * d * a * a / (12.5 * norm2 * norm2));
    const double variance = distance_variance_mm2(model, c, p, 0.0, Eigen::Vector3d::UnitZ());
    EXPECT_NEAR(variance, expected, 1e-9 * sigma2) << d;
    if (d > 0) {
      EXPECT_GT(variance, previous) << d;
    }
    previous = variance;
  }
}

// §6.6.1, Figs. 6.8-6.9: the predicted standard deviation of d_s (Eq. 6.21, regression
// form) matches the actual one over noise trials, and falls as the plane turns from
// horizontal to inclined (the orientation effect, §6.5.1).
TEST(TangentPlaneCorrespondence, PredictedDistanceSigmaMatchesMonteCarloAndFallsWithTilt) {
  constexpr double kSigma = 0.05;
  double previous_sigma = 1e9;
  for (double tilt : {0.0, 40.0, 65.0}) {
    const RangeImage clean = tilted_plane(tilt, 25, 0.5);
    double sum2 = 0, predicted2 = 0;
    int samples = 0;
    for (int trial = 0; trial < 150; ++trial) {
      RangeImage model_image = clean, scene_image = clean;
      add_z_noise(model_image, kSigma, 1000 + trial);
      add_z_noise(scene_image, kSigma, 5000 + trial);
      RegistrationPointParameters parameters;
      parameters.z_noise_sigma_mm = kSigma;
      parameters.stride_px = 6;  // independent scene windows
      const auto model =
          build_registration_points(model_image, {.z_noise_sigma_mm = kSigma}).points;
      const auto scene = build_registration_points(scene_image, parameters).points;
      for (int i = 0; i < scene.size(); ++i) {
        TangentPlaneCorrespondence c;
        // Offset the line foot by a third of a pixel so the blend is exercised.
        const Eigen::Vector3d p = scene.position_mm.col(i) + Eigen::Vector3d(0.17, 0.17, 0);
        const Eigen::Vector3d p_on = p + Eigen::Vector3d(0, 0, std::tan(tilt * kDeg) * 0.17);
        ASSERT_EQ(find_tangent_plane(model, p_on, scene.normal.col(i), 6, c),
                  CorrespondenceStatus::kFound);
        sum2 += c.distance_mm * c.distance_mm;
        predicted2 += distance_variance_mm2(model, c, p_on,
                                            kSigma * kSigma * scene.fit_cofactor(kHeight, kHeight),
                                            Eigen::Vector3d::UnitZ());
        ++samples;
      }
    }
    const double actual = std::sqrt(sum2 / samples), predicted = std::sqrt(predicted2 / samples);
    std::printf("tilt %4.0f deg: sigma_ds actual %.5f mm, predicted %.5f mm\n", tilt, actual,
                predicted);
    EXPECT_NEAR(predicted / actual, 1.0, 0.1) << tilt;
    EXPECT_LT(actual, previous_sigma);
    previous_sigma = actual;
  }
}

TEST(TangentPlaneCorrespondence, NormalLineMeetsTheSurfaceAtTheKnownPoint) {
  const RangeImage image = render_free_form_part(RigidTransform::identity(), FreeFormPartSpec{});
  const auto model = build_registration_points(image, {.z_noise_sigma_mm = 0.01}).points;
  int checked = 0;
  for (double x = -25; x <= 25; x += 5.3)
    for (double y = -12; y <= 12; y += 4.1) {
      // A point 0.8 mm above the surface along the true normal, line along that normal.
      const Eigen::Vector2d g = free_form_gradient(x, y);
      const Eigen::Vector3d normal = Eigen::Vector3d(-g.x(), -g.y(), 1).normalized();
      if (normal.z() < 0.5) continue;
      const Eigen::Vector3d surface(x, y, free_form_height_mm(x, y));
      TangentPlaneCorrespondence c;
      ASSERT_EQ(find_tangent_plane(model, surface + 0.8 * normal, -normal, 6, c),
                CorrespondenceStatus::kFound);
      EXPECT_NEAR(c.distance_mm, 0.8, 2e-3) << x << " " << y;
      EXPECT_LT((c.model_point_mm - surface).norm(), 5e-3) << x << " " << y;
      // The quadric's slopes carry the third-derivative bias of a 2 mm window on the steep
      // flanks (the position does not: the foot is found by the blended heights).
      EXPECT_LT((c.model_normal - normal).norm(), 0.02) << x << " " << y;
      EXPECT_LE(c.steps, 6);
      ++checked;
    }
  EXPECT_GT(checked, 30);
  TangentPlaneCorrespondence c;
  EXPECT_EQ(find_tangent_plane(model, {200, 0, 0}, {0, 0, 1}, 6, c),
            CorrespondenceStatus::kOffModel);
  EXPECT_EQ(find_tangent_plane(model, {0, 0, 30}, {1, 0, 0}, 6, c), CorrespondenceStatus::kGrazing);
}

}  // namespace
}  // namespace cosmos::testing
