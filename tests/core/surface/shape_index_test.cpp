// Shape index and curvedness on analytic surfaces at 0.5 mm pixels, noise-free unless a test
// names its noise.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/core/analytic_fixture.hpp"

namespace cosmos::testing {
namespace {

TEST(ShapeIndexFormula, CategoriesOfTheScale) {
  EXPECT_NEAR(shape_index(0.04f, 0.04f), 1.0f, 1e-6);    // spherical cap
  EXPECT_NEAR(shape_index(-0.04f, -0.04f), 0.0f, 1e-6);  // spherical cup
  EXPECT_NEAR(shape_index(0.05f, 0.0f), 0.75f, 1e-6);    // ridge
  EXPECT_NEAR(shape_index(0.0f, -0.05f), 0.25f, 1e-6);   // rut
  EXPECT_NEAR(shape_index(0.03f, -0.03f), 0.5f, 1e-6);   // symmetric saddle
  // Against Eq. 3.2 evaluated with libm over the whole (k1 >= k2) plane.
  for (float k1 = -1.0f; k1 <= 1.0f; k1 += 0.01f)
    for (float k2 = -1.0f; k2 <= k1; k2 += 0.01f)
      EXPECT_NEAR(shape_index(k1, k2),
                  0.5 + std::atan2(double{k1} + k2, double{k1} - k2) / std::numbers::pi, 2e-6);
  EXPECT_NEAR(curvedness(1.0f, 0.0f), 1.0 / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(curvedness(1.0f, -1.0f), 1.0, 1e-6);
  // Eqs. 3.21-3.22: the sensitivity grows without bound as the curvatures vanish.
  EXPECT_NEAR(shape_index_sensitivity_mm(0.03f, 0.04f), 1.0 / (std::numbers::pi * 0.05), 1e-3);
  EXPECT_GT(shape_index_sensitivity_mm(1e-5f, 1e-5f), 1e4f);
}

TEST(ShapeIndex, SphereIsCapWithCurvednessOneOverRadius) {
  const auto surface = analytic(AnalyticShape::kSphere);
  const auto analysis = analyze(surface);
  std::vector<bool> cap, curvedness_ok;
  for_each_interior(surface, [&](std::size_t i, const AnalyticTruth&) {
    cap.push_back(analysis.field.shape_index[i] >= 0.98f && analysis.field.shape_index[i] <= 1.0f);
    curvedness_ok.push_back(std::abs(analysis.field.curvedness_per_mm[i] * 25.0 - 1.0) <= 0.03);
  });
  ASSERT_GT(cap.size(), 4000u);
  EXPECT_GE(fraction_true(cap), 0.95);
  EXPECT_GE(fraction_true(curvedness_ok), 0.95);
}

TEST(ShapeIndex, CupIsConcave) {
  const auto surface = analytic(AnalyticShape::kCup);
  const auto analysis = analyze(surface);
  std::vector<bool> cup;
  for_each_interior(surface, [&](std::size_t i, const AnalyticTruth&) {
    cup.push_back(analysis.field.shape_index[i] <= 0.02f);
  });
  ASSERT_GT(cup.size(), 1000u);
  EXPECT_GE(fraction_true(cup), 0.95);
}

TEST(ShapeIndex, CylinderIsRidge) {
  const auto surface = analytic(AnalyticShape::kCylinder);  // r = 25 mm by default
  AnalyticSurfaceSpec spec = surface.spec;
  spec.radius_mm = 20.0;
  const auto cylinder = make_analytic_surface(spec);
  const auto analysis = analyze(cylinder);
  std::vector<bool> ridge, curvedness_ok;
  const double expected_curvedness = 1.0 / (std::sqrt(2.0) * 20.0);
  for_each_interior(cylinder, [&](std::size_t i, const AnalyticTruth&) {
    ridge.push_back(std::abs(analysis.field.shape_index[i] - 0.75f) <= 0.02f);
    curvedness_ok.push_back(
        std::abs(analysis.field.curvedness_per_mm[i] / expected_curvedness - 1.0) <= 0.03);
  });
  ASSERT_GT(ridge.size(), 1000u);
  EXPECT_GE(fraction_true(ridge), 0.95);
  EXPECT_GE(fraction_true(curvedness_ok), 0.95);
}

TEST(ShapeIndex, SymmetricSaddleNearCentre) {
  const auto surface = analytic(AnalyticShape::kSaddle);
  const auto analysis = analyze(surface);
  int checked = 0;
  for (int row = 0; row < surface.range.height(); ++row) {
    for (int column = 0; column < surface.range.width(); ++column) {
      const double x = surface.range.x_mm(column), y = surface.range.y_mm(row);
      if (x * x + y * y > 3.0 * 3.0) continue;  // near the centre, where S_I = 0.5 exactly
      EXPECT_NEAR(analysis.field.shape_index(column, row), 0.5f, 0.02f) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(ShapeIndex, TiltedPlaneIsPlanar) {
  const auto surface = analytic(AnalyticShape::kPlane);
  const auto analysis = analyze(surface);
  std::vector<bool> planar;
  for_each_interior(surface, [&](std::size_t i, const AnalyticTruth&) {
    planar.push_back(analysis.field.label[i] == SurfaceLabel::kPlanar);
  });
  ASSERT_GT(planar.size(), 1000u);
  EXPECT_GE(fraction_true(planar), 0.99);
}

TEST(ShapeIndex, TorusMatchesAnalyticShapeIndex) {
  const auto surface = analytic(AnalyticShape::kTorus);
  const auto analysis = analyze(surface);
  std::vector<bool> close;
  for_each_interior(surface, [&](std::size_t i, const AnalyticTruth& truth) {
    close.push_back(std::abs(analysis.field.shape_index[i] - truth.shape_index) <= 0.03f);
  });
  ASSERT_GT(close.size(), 1000u);
  EXPECT_GE(fraction_true(close), 0.95);
}

}  // namespace
}  // namespace cosmos::testing
