// Row-by-row COSMOS of a part equals whole-image processing of the same rows: the real-time
// cell and the model base run one code path, so the live features match the model views'.
#include "realtime/loop/incremental_cosmos.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "core/representation/cosmos_pipeline.hpp"
#include "tests/realtime/loop/identical_rows.hpp"

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

// Enough blocks for any part of these tests.
RowBlockPool& test_pool() {
  static RowBlockPool pool(64, 16 * PartRows::record_bytes(200));
  return pool;
}

void expect_same_as_whole_image(IncrementalCosmos& builder, const RangeImage& part,
                                const CosmosParameters& parameters) {
  builder.begin_part(part.origin_x_mm, part.origin_y_mm);
  for (int row = 0; row < part.height(); ++row)
    ASSERT_EQ(builder.add_row(part.z_mm.row(row)), AddRowResult::kAdded);
  builder.finish();
  const ViewAnalysis whole = analyze_view(part, parameters);
  // The builder's fields, finished by the same code as whole-image analysis.
  ViewAnalysis incremental;
  incremental.frames = builder.whole_frames();
  incremental.field = builder.whole_field();
  const ShapeIndexField& field = incremental.field;
  finish_view_analysis(incremental, parameters);
  const CsmpSegmentation& segmentation = incremental.segmentation;

  double max_shape_index_difference = 0;
  int label_mismatches = 0, patch_mismatches = 0;
  for (int row = 0; row < part.height(); ++row) {
    for (int column = 0; column < part.width(); ++column) {
      const auto expected_label = whole.field.label(column, row);
      label_mismatches += field.label(column, row) != expected_label;
      if (expected_label != SurfaceLabel::kInvalid)
        max_shape_index_difference =
            std::max(max_shape_index_difference, std::abs(double{field.shape_index(column, row)} -
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
  // Every frame component and position equals the whole image's.
  int frame_mismatches = 0;
  for (std::size_t pixel = 0; pixel < whole.frames.valid.size(); ++pixel) {
    frame_mismatches += incremental.frames.valid[pixel] != whole.frames.valid[pixel];
    for (int c = 0; c < kFrameComponents; ++c)
      frame_mismatches += incremental.frames.frame[c][pixel] != whole.frames.frame[c][pixel];
    for (int a = 0; a < 3; ++a)
      frame_mismatches +=
          incremental.frames.position_mm[a][pixel] != whole.frames.position_mm[a][pixel];
  }
  EXPECT_EQ(frame_mismatches, 0);
  builder.release_rows();
}

TEST(IncrementalCosmos, EqualsWholeImageProcessing) {
  const CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 110, 160, 0.4, 0.4, test_pool());
  expect_same_as_whole_image(builder, relief(110, 90, 1), parameters);
  // The same builder, reused for a longer part: nothing of the first part leaks in.
  expect_same_as_whole_image(builder, relief(110, 140, 2), parameters);
}

TEST(IncrementalCosmos, AReusedBuilderEqualsWholeImageAfterALongerWiderPart) {
  // The scan loop hands a builder to whichever part starts next: what a longer, wider part
  // left in its rows and rings must not leak into a shorter, narrower one.
  const CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 200, 160, 0.4, 0.4, test_pool());
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
    IncrementalCosmos builder(parameters, 110, 100, 0.4, 0.4, test_pool());
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
  IncrementalCosmos builder(parameters, 200, 100, 0.4, 0.4, test_pool());
  expect_same_as_whole_image(builder, belt, parameters);
}

// A part in the middle of a belt `width` wide (NaN beside it).
RangeImage on_belt(const RangeImage& part, int width, int first_column) {
  RangeImage belt(width, part.height(), part.pixel_size_x_mm, part.pixel_size_y_mm);
  belt.origin_x_mm = part.origin_x_mm;
  belt.origin_y_mm = part.origin_y_mm;
  for (int row = 0; row < part.height(); ++row)
    std::copy(part.z_mm.row(row), part.z_mm.row(row) + part.width(),
              belt.z_mm.row(row) + first_column);
  return belt;
}

void build(IncrementalCosmos& builder, const RangeImage& part) {
  builder.begin_part(part.origin_x_mm, part.origin_y_mm);
  for (int row = 0; row < part.height(); ++row)
    ASSERT_EQ(builder.add_row(part.z_mm.row(row)), AddRowResult::kAdded);
  builder.finish();
}

// Every plane of every row, bit for bit.
void expect_identical_rows(const IncrementalCosmos& a, const IncrementalCosmos& b) {
  ASSERT_EQ(a.rows(), b.rows());
  testing::expect_identical_rows(a, b, a.rows());
}

TEST(IncrementalCosmos, ABuilderReusedAfterALongPartAndAShortOneEqualsAFreshOne) {
  // The long part's rows move through the working window several times; the short one ends
  // with the window's rows barely used. Neither may leave anything in the next part.
  const CosmosParameters parameters;
  IncrementalCosmos reused(parameters, 200, 400, 0.4, 0.4, test_pool());
  build(reused, relief(200, 300, 11));
  reused.release_rows();
  build(reused, on_belt(relief(150, 12, 12), 200, 10));
  reused.release_rows();
  const RangeImage part = on_belt(relief(110, 140, 13), 200, 45);
  build(reused, part);
  IncrementalCosmos fresh(parameters, 200, 400, 0.4, 0.4, test_pool());
  build(fresh, part);
  expect_identical_rows(reused, fresh);
  EXPECT_GT(reused.rows(), IncrementalCosmos::fit_window_rows(parameters));
  // Only the part's columns are kept.
  EXPECT_EQ(reused.row(70).column_begin, 45);
  EXPECT_EQ(reused.row(70).column_end, 155);
}

TEST(IncrementalCosmos, ARowThePoolHasNoRoomForChangesNothing) {
  const CosmosParameters parameters;
  RowBlockPool pool(1, 2 * PartRows::record_bytes(20));
  IncrementalCosmos builder(parameters, 20, 10, 0.4, 0.4, pool);
  builder.begin_part(0, 0);
  const std::vector<float> row(20, 1.0f);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(builder.add_row(row.data()), AddRowResult::kAdded);
  EXPECT_EQ(builder.add_row(row.data()), AddRowResult::kNoMemory);
  EXPECT_EQ(builder.rows(), 2);
  // A row without samples needs no room.
  const std::vector<float> empty(20, std::numeric_limits<float>::quiet_NaN());
  EXPECT_EQ(builder.add_row(empty.data()), AddRowResult::kAdded);
  builder.release_rows();
  EXPECT_EQ(pool.blocks_in_use(), 0);
  builder.begin_part(0, 0);
  EXPECT_EQ(builder.add_row(row.data()), AddRowResult::kAdded);
}

// The belt flags of each row are kept over the whole width (a shadow beside the part is told
// from the belt by them), across a 64-column word boundary, and start over with the next part.
TEST(IncrementalCosmos, KeepsEachRowsBeltFlagsForTheWholeWidth) {
  const CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 100, 10, 0.4, 0.4, test_pool());
  builder.begin_part(0, 0);
  std::vector<float> row(100, std::numeric_limits<float>::quiet_NaN());
  for (int column = 40; column < 70; ++column) row[static_cast<std::size_t>(column)] = 5.0f;
  for (int r = 0; r < 3; ++r) {
    std::vector<std::uint8_t> belt(100, 0);
    for (int column = 0; column < 100; ++column)
      belt[static_cast<std::size_t>(column)] = (column < 40 || column >= 70 + r) ? 1 : 0;
    ASSERT_EQ(builder.add_row(row.data(), belt.data()), AddRowResult::kAdded);
  }
  ASSERT_EQ(builder.add_row(row.data()), AddRowResult::kAdded);  // no flags: no belt
  for (int r = 0; r < 3; ++r)
    for (int column = 0; column < 100; ++column)
      EXPECT_EQ(builder.belt_seen(column, r), column < 40 || column >= 70 + r)
          << r << " " << column;
  for (int column = 0; column < 100; ++column) EXPECT_FALSE(builder.belt_seen(column, 3));
  const RangeImage image = builder.whole_image();
  ASSERT_TRUE(image.belt_known());
  EXPECT_EQ(image.belt_seen(39, 1), 1);
  EXPECT_EQ(image.belt_seen(70, 1), 0);
  EXPECT_EQ(image.belt_seen(71, 1), 1);
  builder.release_rows();
  builder.begin_part(0, 0);
  ASSERT_EQ(builder.add_row(row.data()), AddRowResult::kAdded);
  EXPECT_FALSE(builder.belt_seen(0, 0));
}

TEST(IncrementalCosmos, RefusesRowsBeyondItsCapacity) {
  const CosmosParameters parameters;
  IncrementalCosmos builder(parameters, 20, 3, 0.4, 0.4, test_pool());
  builder.begin_part(0, 0);
  const std::vector<float> row(20, 1.0f);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(builder.add_row(row.data()), AddRowResult::kAdded);
  EXPECT_EQ(builder.add_row(row.data()), AddRowResult::kTooLong);
  builder.finish();
  EXPECT_EQ(builder.rows(), 3);
}

}  // namespace
}  // namespace cosmos
