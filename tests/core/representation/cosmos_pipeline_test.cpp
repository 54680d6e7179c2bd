// The chapter-3 pipeline of one view (Fig. 3.22, core/representation/cosmos_pipeline.hpp) on
// noise-free analytic surfaces at 0.5 mm pixels: which pixels are valid, the patches and their
// orientations, and where the shape spectrum puts the area, against closed-form values.
#include "core/representation/cosmos_pipeline.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include "tests/core/analytic_fixture.hpp"

namespace cosmos::testing {
namespace {

double spectrum_mass(const ShapeSpectrum& spectrum, int first_bin, int last_bin) {
  double mass = 0;
  for (int bin = first_bin; bin <= last_bin; ++bin)
    mass += spectrum.bins[static_cast<std::size_t>(bin)];
  return mass;
}

int peak_bin(const ShapeSpectrum& spectrum) {
  return static_cast<int>(std::max_element(spectrum.bins.begin(), spectrum.bins.end()) -
                          spectrum.bins.begin());
}

TEST(CosmosPipeline, TiltedPlaneIsOnePlanarPatchCoveringEveryFittedPixel) {
  // z = tan(20 deg) x over |x|, |y| <= 25 mm: 101 x 101 samples. Only the four corner pixels
  // see fewer than the 12 samples a fit needs (3 x 3 of their 5 x 5 window).
  const AnalyticSurface surface = analytic(AnalyticShape::kPlane);
  const ViewAnalysis analysis = analyze(surface);
  const double tilt = 20.0 * std::numbers::pi / 180.0;
  ASSERT_EQ(surface.range.count_valid(), 101u * 101u);
  EXPECT_EQ(analysis.valid_pixels, 101u * 101u - 4u);
  ASSERT_EQ(analysis.view.patches.size(), 1u);
  const Csmp& plane = analysis.view.patches[0];
  EXPECT_TRUE(plane.planar);
  EXPECT_EQ(plane.pixels, 101 * 101 - 4);
  EXPECT_LT((plane.mean_normal - Eigen::Vector3d(-std::sin(tilt), 0, std::cos(tilt))).norm(), 1e-5);
  // Each pixel's cell covers dx dy / n_z of the plane.
  const double area_mm2 = (101.0 * 101.0 - 4.0) * 0.25 / std::cos(tilt);
  EXPECT_NEAR(plane.area_mm2 / area_mm2, 1.0, 1e-5);
  EXPECT_NEAR(analysis.spectrum.visible_area_mm2 / area_mm2, 1.0, 1e-5);
  EXPECT_DOUBLE_EQ(analysis.spectrum.planar_fraction, 1.0);
  EXPECT_DOUBLE_EQ(spectrum_mass(analysis.spectrum, 0, 199), 0.0);
  EXPECT_DOUBLE_EQ(analysis.moments[kSpectrumMoments], 1.0);
}

TEST(CosmosPipeline, SphereIsOneCapWhoseSpectrumPeaksInTheLastBin) {
  const AnalyticSurface surface = analytic(AnalyticShape::kSphere);  // R = 25 mm
  const ViewAnalysis analysis = analyze(surface);
  // Valid: every sample but the grazing rim (normals beyond 85 degrees are never valid) and a
  // few rim pixels with too few samples.
  std::size_t grazing = 0;
  for (const AnalyticTruth& truth : surface.truth.values())
    grazing += truth.valid && truth.normal.z() < std::cos(85.0 * std::numbers::pi / 180.0);
  ASSERT_GT(grazing, 0u);
  EXPECT_LE(analysis.valid_pixels, surface.range.count_valid() - grazing);
  EXPECT_GE(analysis.valid_pixels, 0.98 * surface.range.count_valid());
  ASSERT_EQ(analysis.view.patches.size(), 1u);
  const Csmp& cap = analysis.view.patches[0];
  EXPECT_FALSE(cap.planar);
  EXPECT_GE(cap.shape_index, 0.99);
  EXPECT_LT((cap.mean_normal - Eigen::Vector3d::UnitZ()).norm(), 1e-4);  // by symmetry
  // Curvedness 1/R (Eq. 3.3), a little high from the steep rim, whose cells weigh most.
  EXPECT_NEAR(cap.mean_curvedness_per_mm * 25.0, 1.0, 0.05);
  // S_I = 1 falls in the last bin: most of the area there, nearly all of it above 0.98.
  EXPECT_EQ(peak_bin(analysis.spectrum), 199);
  EXPECT_GE(spectrum_mass(analysis.spectrum, 196, 199), 0.97);
  EXPECT_DOUBLE_EQ(analysis.spectrum.planar_fraction, 0.0);
  EXPECT_GT(analysis.moments[0], 0.99);
  // The visible area is what the exact normals give the same pixels' cells (the fitted
  // normals give 2.5 % more).
  double exact_area_mm2 = 0;
  for (std::size_t i = 0; i < surface.truth.size(); ++i)
    if (analysis.field.label[i] != SurfaceLabel::kInvalid)
      exact_area_mm2 += 0.25 / surface.truth[i].normal.z();
  EXPECT_NEAR(analysis.spectrum.visible_area_mm2 / exact_area_mm2, 1.0, 0.04);
  EXPECT_NEAR(cap.area_mm2 / exact_area_mm2, 1.0, 0.04);
}

TEST(CosmosPipeline, CylinderSpectrumPeaksAtTheRidgeShapeIndex) {
  const AnalyticSurface surface = analytic(AnalyticShape::kCylinder);
  const ViewAnalysis analysis = analyze(surface);
  ASSERT_EQ(analysis.view.patches.size(), 1u);
  EXPECT_NEAR(analysis.view.patches[0].shape_index, 0.75, 0.005);
  EXPECT_LT((analysis.view.patches[0].mean_normal - Eigen::Vector3d::UnitZ()).norm(), 1e-4);
  // 0.75 is the edge between bins 149 and 150.
  const int peak = peak_bin(analysis.spectrum);
  EXPECT_TRUE(peak == 149 || peak == 150) << peak;
  EXPECT_GE(spectrum_mass(analysis.spectrum, 149, 150), 0.99);
  EXPECT_NEAR(analysis.moments[0], 0.75, 0.005);
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expect_same_analysis(const ViewAnalysis& reused, const ViewAnalysis& fresh) {
  for (int m = 0; m < kFrameComponents; ++m)
    EXPECT_TRUE(same_bits(reused.frames.frame[m].values(), fresh.frames.frame[m].values())) << m;
  EXPECT_TRUE(same_bits(reused.frames.valid.values(), fresh.frames.valid.values()));
  EXPECT_TRUE(same_bits(reused.field.shape_index.values(), fresh.field.shape_index.values()));
  EXPECT_TRUE(
      same_bits(reused.field.curvedness_per_mm.values(), fresh.field.curvedness_per_mm.values()));
  EXPECT_EQ(reused.view.patches.size(), fresh.view.patches.size());
  EXPECT_EQ(reused.valid_pixels, fresh.valid_pixels);
  for (std::size_t k = 0; k < fresh.moments.size(); ++k)
    EXPECT_EQ(reused.moments[k], fresh.moments[k]) << k;
}

TEST(CosmosPipeline, AnalysesSharingAWorkspaceEqualFreshOnesBitForBit) {
  // Rims, corners and noise leave many windows partial, each image its own patterns and some
  // of the last one's; the window changes once, so the workspace's table must too.
  const std::vector<AnalyticSurface> surfaces = {
      analytic(AnalyticShape::kSphere, 0.01), analytic(AnalyticShape::kBoxCorner, 0.01, 30),
      analytic(AnalyticShape::kTorus, 0.01), analytic(AnalyticShape::kSphere, 0.01)};
  ViewAnalysisWorkspace workspace;
  CosmosParameters parameters;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    SCOPED_TRACE(i);
    parameters.fit.window_size = i == 2 ? 7 : 5;
    const ViewAnalysis fresh = analyze_view(surfaces[i].range, parameters);
    ASSERT_GT(surfaces[i].range.count_valid(), fresh.valid_pixels);  // some windows partial
    expect_same_analysis(analyze_view(surfaces[i].range, parameters, workspace), fresh);
  }
}

}  // namespace
}  // namespace cosmos::testing
