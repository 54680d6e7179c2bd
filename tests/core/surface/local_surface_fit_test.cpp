// The local bicubic fit reproduces polynomials exactly, with or without missing samples, and
// never fits across a depth jump.
#include "core/surface/local_surface_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosmos {
namespace {

// z = 0.3 x + 0.1 y + 0.02 x^2 - 0.01 xy + 0.03 y^2 + 0.001 x^3 (mm) on 0.5 x 0.4 mm pixels.
double cubic(double x, double y) {
  return 0.3 * x + 0.1 * y + 0.02 * x * x - 0.01 * x * y + 0.03 * y * y + 0.001 * x * x * x;
}

RangeImage cubic_image() {
  RangeImage image(21, 21, 0.5, 0.4);
  image.origin_x_mm = -5.0;
  image.origin_y_mm = -4.0;
  for (int row = 0; row < 21; ++row)
    for (int column = 0; column < 21; ++column)
      image.z_mm(column, row) = static_cast<float>(cubic(image.x_mm(column), image.y_mm(row)));
  return image;
}

void expect_frame_of_cubic_at(const DarbouxFrameField& field, int column, int row, double x,
                              double y) {
  SurfaceDerivatives d;
  d.zx = 0.3 + 0.04 * x - 0.01 * y + 0.003 * x * x;
  d.zy = 0.1 - 0.01 * x + 0.06 * y;
  d.zxx = 0.04 + 0.006 * x;
  d.zxy = -0.01;
  d.zyy = 0.06;
  float expected[kFrameComponents];
  darboux_frame_from_derivatives(d, expected);
  const std::size_t i = field.valid.index(column, row);
  ASSERT_TRUE(field.valid[i]);
  for (int c = 0; c < kFrameComponents; ++c) EXPECT_NEAR(field.frame[c][i], expected[c], 2e-4) << c;
}

TEST(LocalSurfaceFit, CompleteWindowReproducesACubic) {
  const RangeImage image = cubic_image();
  const auto field = fit_local_surfaces(image, SurfaceFitParameters{});
  expect_frame_of_cubic_at(field, 10, 10, 0.0, 0.0);
  expect_frame_of_cubic_at(field, 13, 7, image.x_mm(13), image.y_mm(7));
}

TEST(LocalSurfaceFit, MissingSamplesStillFitExactly) {
  RangeImage image = cubic_image();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  image.z_mm(9, 9) = nan;
  image.z_mm(11, 12) = nan;
  image.z_mm(12, 10) = nan;
  const auto field = fit_local_surfaces(image, SurfaceFitParameters{});
  expect_frame_of_cubic_at(field, 10, 10, 0.0, 0.0);
  EXPECT_FALSE(field.valid(9, 9));
}

TEST(LocalSurfaceFit, DepthJumpSamplesAreLeftOut) {
  RangeImage image = cubic_image();
  for (int row = 0; row < 21; ++row)
    for (int column = 12; column < 21; ++column) image.z_mm(column, row) += 10.0f;  // a step
  const auto field = fit_local_surfaces(image, SurfaceFitParameters{});
  expect_frame_of_cubic_at(field, 10, 10, 0.0, 0.0);
  // Pixel 11 sees the step next to it: no same-side link to the right.
  EXPECT_FALSE((field.same_side(11, 10) >> 4) & 1u);
  EXPECT_TRUE((field.same_side(10, 10) >> 4) & 1u);
}

TEST(LocalSurfaceFit, TooFewSamplesMarkThePixelInvalid) {
  RangeImage image(9, 9, 0.5, 0.5);
  image.z_mm(4, 4) = 1.0f;
  image.z_mm(5, 4) = 1.0f;
  image.z_mm(6, 4) = 1.0f;  // a single line of samples does not determine a surface
  const auto field = fit_local_surfaces(image, SurfaceFitParameters{});
  EXPECT_FALSE(field.valid(5, 4));
}

TEST(LocalSurfaceFit, SphereCurvatureSignConvention) {
  SurfaceDerivatives d;
  d.zxx = d.zyy = -1.0 / 25.0;  // the top of a sphere of radius 25 mm bulging to the sensor
  float frame[kFrameComponents];
  darboux_frame_from_derivatives(d, frame);
  FrameValues values;
  for (int c = 0; c < kFrameComponents; ++c) values[c] = frame[c];
  const PrincipalCurvatures k = principal_curvatures(values);
  EXPECT_NEAR(k.kappa1, 0.04, 1e-6);
  EXPECT_NEAR(k.kappa2, 0.04, 1e-6);
}

// A table shared by the fits of a stream of images gives each the frames its own table would:
// the holes of one image and the step of the next need kernels of different patterns, and
// the second image repeats some of the first's.
TEST(LocalSurfaceFit, ASharedKernelTableFitsEachImageAsAFreshOneDoes) {
  RangeImage holes = cubic_image();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int k = 0; k < 21; k += 4) holes.z_mm(k, (3 * k) % 21) = nan;
  RangeImage step = cubic_image();
  for (int row = 0; row < 21; ++row)
    for (int column = 12; column < 21; ++column) step.z_mm(column, row) += 10.0f;
  step.z_mm(4, 4) = nan;
  const SurfaceFitParameters parameters;
  PartialWindowKernels shared = LocalSurfaceFitter::partial_window_kernels_for(parameters);
  for (const RangeImage* image : {&holes, &step, &holes}) {
    const DarbouxFrameField fresh = fit_local_surfaces(*image, parameters);
    DarbouxFrameField reused(image->width(), image->height());
    fit_local_surfaces(*image, parameters, reused, shared);
    EXPECT_EQ(reused.valid.values(), fresh.valid.values());
    EXPECT_EQ(reused.same_side.values(), fresh.same_side.values());
    for (int m = 0; m < kFrameComponents; ++m)
      EXPECT_EQ(reused.frame[m].values(), fresh.frame[m].values()) << m;
  }
}

TEST(LocalSurfaceFit, AKernelTableForAnotherWindowIsRefused) {
  SurfaceFitParameters seven;
  seven.window_size = 7;
  PartialWindowKernels table_of_seven = LocalSurfaceFitter::partial_window_kernels_for(seven);
  EXPECT_THROW(LocalSurfaceFitter(SurfaceFitParameters{}, 0.5, 0.5, 21, table_of_seven),
               std::invalid_argument);
  SurfaceFitParameters biquadratic;
  biquadratic.bicubic = false;
  PartialWindowKernels table_of_biquadratic =
      LocalSurfaceFitter::partial_window_kernels_for(biquadratic);
  EXPECT_THROW(LocalSurfaceFitter(SurfaceFitParameters{}, 0.5, 0.5, 21, table_of_biquadratic),
               std::invalid_argument);
}

}  // namespace
}  // namespace cosmos
