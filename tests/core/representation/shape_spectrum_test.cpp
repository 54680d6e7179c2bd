// Shape spectrum, its moments (Eqs. 4.1-4.2) and the dissimilarity (Eq. 4.3).
#include "core/representation/shape_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/core/analytic_fixture.hpp"

namespace cosmos::testing {
namespace {

TEST(ShapeSpectrum, MomentsOfAHandComputedSpectrum) {
  SpectrumParameters parameters;  // bin width 0.005
  ShapeSpectrumAccumulator accumulator(parameters);
  accumulator.add(SurfaceLabel::kCurved, 0.2512f, 3.0f);  // bin 50, centre 0.2525
  accumulator.add(SurfaceLabel::kCurved, 0.7538f, 1.0f);  // bin 150, centre 0.7525
  accumulator.add(SurfaceLabel::kPlanar, kPlanarShapeIndex, 4.0f);
  accumulator.add(SurfaceLabel::kInvalid, 0.5f, 100.0f);  // ignored
  const ShapeSpectrum spectrum = accumulator.finish();
  ASSERT_EQ(spectrum.bins.size(), 200u);
  EXPECT_DOUBLE_EQ(spectrum.visible_area_mm2, 8.0);
  EXPECT_DOUBLE_EQ(spectrum.bins[50], 3.0 / 8.0);
  EXPECT_DOUBLE_EQ(spectrum.bins[150], 1.0 / 8.0);
  EXPECT_DOUBLE_EQ(spectrum.planar_fraction, 0.5);
  const MomentVector m = spectrum_moments(spectrum);
  // Non-planar spectrum renormalized: 0.75 at 0.2525, 0.25 at 0.7525.
  const double mean = 0.75 * 0.2525 + 0.25 * 0.7525;
  EXPECT_NEAR(m[0], mean, 1e-12);
  for (int p = 2; p <= 10; ++p) {
    const double expected = 0.75 * std::pow(0.2525 - mean, p) + 0.25 * std::pow(0.7525 - mean, p);
    EXPECT_NEAR(m[p - 1], expected, 1e-12) << "m" << p;
  }
  EXPECT_DOUBLE_EQ(m[10], 0.5);
  MomentVector shifted = m;
  shifted[0] += 0.1;
  shifted[1] -= 0.2;
  EXPECT_NEAR(spectral_dissimilarity(m, shifted), 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(spectral_dissimilarity(m, m), 0.0);
}

TEST(ShapeSpectrum, ShapeIndexOneFallsInTheLastBin) {
  ShapeSpectrumAccumulator accumulator(SpectrumParameters{});
  accumulator.add(SurfaceLabel::kCurved, 1.0f, 1.0f);
  EXPECT_DOUBLE_EQ(accumulator.finish().bins.back(), 1.0);
}

TEST(ShapeSpectrum, EllipsoidSpectrumIsInvariantToRotationAboutTheViewingAxis) {
  const auto reference = analyze(analytic(AnalyticShape::kEllipsoid, 0.0, 0.0));
  for (double angle : {30.0, 90.0}) {
    const auto rotated = analyze(analytic(AnalyticShape::kEllipsoid, 0.0, angle));
    const double d = spectral_dissimilarity(reference.moments, rotated.moments);
    EXPECT_LT(d, 0.01) << angle;
    EXPECT_NEAR(rotated.spectrum.visible_area_mm2 / reference.spectrum.visible_area_mm2, 1.0, 0.02);
  }
  // And it does tell a sphere from an ellipsoid.
  const auto sphere = analyze(analytic(AnalyticShape::kSphere));
  EXPECT_GT(spectral_dissimilarity(reference.moments, sphere.moments), 1e-4);
}

}  // namespace
}  // namespace cosmos::testing
