// Row-by-row COSMOS of a part equals whole-image processing of the same rows: the real-time
// cell and the model base run one code path, so the live features match the model views'.
#include "realtime/loop/incremental_cosmos.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/representation/cosmos_pipeline.hpp"

namespace cosmos {
namespace {

// A relief with bumps, a dent, a 6 mm step, a hole of missing data and sensor noise.
RangeImage relief(int width, int height, std::uint64_t seed) {
  RangeImage image(width, height, 0.4, 0.4);
  image.origin_x_mm = -10.0;
  image.origin_y_mm = 25.0;
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const double x = column * 0.4, y = row * 0.4;
      double z = 12 * std::exp(-((x - 12) * (x - 12) + (y - 14) * (y - 14)) / 60.0) -
                 6 * std::exp(-((x - 30) * (x - 30) + (y - 22) * (y - 22)) / 40.0) + 0.2 * x;
      if (x > 38) z += 6.0;
      const bool hole = (x - 20) * (x - 20) + (y - 30) * (y - 30) < 9;
      image.z_mm(column, row) =
          hole ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(z + noise(generator));
    }
  }
  return image;
}

void expect_same_as_whole_image(IncrementalCosmos& builder, const RangeImage& part,
                                const CosmosParameters& parameters) {
  builder.begin_part(part.origin_x_mm, part.origin_y_mm);
  for (int row = 0; row < part.height(); ++row) ASSERT_TRUE(builder.add_row(part.z_mm.row(row)));
  builder.finish();
  const ViewAnalysis whole = analyze_view(part, parameters);
  // The builder's fields, finished by the same code as whole-image analysis.
  ViewAnalysis incremental;
  incremental.frames = builder.frames();
  incremental.field = builder.field();
  finish_view_analysis(incremental, parameters);
  const CsmpSegmentation& segmentation = incremental.segmentation;

  double max_shape_index_difference = 0;
  int label_mismatches = 0, patch_mismatches = 0;
  for (int row = 0; row < part.height(); ++row) {
    for (int column = 0; column < part.width(); ++column) {
      const auto expected_label = whole.field.label(column, row);
      label_mismatches += builder.field().label(column, row) != expected_label;
      if (expected_label != SurfaceLabel::kInvalid)
        max_shape_index_difference = std::max(
            max_shape_index_difference, std::abs(double{builder.field().shape_index(column, row)} -
                                                 whole.field.shape_index(column, row)));
      patch_mismatches += segmentation.patch_of_pixel(column, row) !=
                          whole.segmentation.patch_of_pixel(column, row);
    }
  }
  EXPECT_EQ(label_mismatches, 0);
  EXPECT_LE(max_shape_index_difference, 1e-5);
  EXPECT_EQ(segmentation.patch_count, whole.segmentation.patch_count);
  EXPECT_EQ(patch_mismatches, 0);
  const ShapeSpectrum& spectrum = incremental.spectrum;
  ASSERT_EQ(spectrum.bins.size(), whole.spectrum.bins.size());
  for (std::size_t k = 0; k < spectrum.bins.size(); ++k)
    EXPECT_NEAR(spectrum.bins[k], whole.spectrum.bins[k], 1e-12);
  EXPECT_NEAR(spectrum.planar_fraction, whole.spectrum.planar_fraction, 1e-12);
  EXPECT_EQ(incremental.valid_pixels, whole.valid_pixels);
  EXPECT_EQ(incremental.view.patches.size(), whole.view.patches.size());
  EXPECT_GT(whole.segmentation.patch_count, 1);
}

TEST(IncrementalCosmos, EqualsWholeImageProcessing) {
  const CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 110, 160, 0.4, 0.4);
  expect_same_as_whole_image(builder, relief(110, 90, 1), parameters);
  // The same builder, reused for a longer part: nothing of the first part leaks in.
  expect_same_as_whole_image(builder, relief(110, 140, 2), parameters);
}

TEST(IncrementalCosmos, AReusedBuilderEqualsWholeImageAfterALongerWiderPart) {
  // The scan loop hands a builder to whichever part starts next: what a longer, wider part
  // left in its rows and rings must not leak into a shorter, narrower one.
  const CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 200, 160, 0.4, 0.4);
  RangeImage wide(200, 150, 0.4, 0.4);
  const RangeImage first = relief(110, 150, 5);
  for (int row = 0; row < 150; ++row)
    for (int column = 0; column < 200; ++column)
      wide.z_mm(column, row) = first.z_mm(column % 110, row) + 3.0f;
  expect_same_as_whole_image(builder, wide, parameters);
  // A ridge (a crease) down the whole part: its pixels in the last rows fit windows shifted
  // by up to half a window, which reach two rows further than centred ones.
  const RangeImage part = relief(70, 60, 6);
  RangeImage belt(200, 60, 0.4, 0.4);
  for (int row = 0; row < part.height(); ++row)
    for (int column = 0; column < part.width(); ++column)
      belt.z_mm(80 + column, row) =
          part.z_mm(column, row) + 8.0f - 0.8f * static_cast<float>(std::abs(column - 35));
  expect_same_as_whole_image(builder, belt, parameters);
}

TEST(IncrementalCosmos, EqualsWholeImageForAnyIterationCount) {
  for (int iterations : {0, 1, 2, 4}) {
    CosmosParameters parameters;
    parameters.smoothing.iterations = iterations;
    IncrementalCosmos builder(parameters, 110, 100, 0.4, 0.4);
    SCOPED_TRACE(iterations);
    expect_same_as_whole_image(builder, relief(110, 70, 3), parameters);
  }
}

TEST(IncrementalCosmos, EqualsWholeImageForAPartNarrowerThanTheBelt) {
  // Smoothing runs only between each row's first and last valid pixel: a part in the middle
  // of a wide, otherwise empty belt, its rows of varying extent, gives the same COSMOS.
  const RangeImage part = relief(70, 80, 4);
  RangeImage belt(200, 80, 0.4, 0.4);
  for (int row = 0; row < part.height(); ++row) {
    const int inset = std::abs(row - 40) / 4;  // a lozenge-ish outline
    for (int column = inset; column < part.width() - inset; ++column)
      belt.z_mm(60 + column, row) = part.z_mm(column, row);
  }
  const CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 200, 100, 0.4, 0.4);
  expect_same_as_whole_image(builder, belt, parameters);
}

TEST(IncrementalCosmos, RefusesRowsBeyondItsCapacity) {
  const CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 20, 3, 0.4, 0.4);
  builder.begin_part(0, 0);
  const std::vector<float> row(20, 1.0f);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(builder.add_row(row.data()));
  EXPECT_FALSE(builder.add_row(row.data()));
  builder.finish();
  EXPECT_EQ(builder.rows(), 3);
}

}  // namespace
}  // namespace cosmos
