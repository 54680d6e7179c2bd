// What the scene loop measures of a blob's region: its pixels, interior area, centroid and
// rows, also with pixels taken away by a mask; the necks where touching parts meet.
#include "realtime/cell/blob_regions.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace cosmos {
namespace {

// Two 30 x 30-pixel squares, 10 mm high, joined by a bridge 4 pixels wide and 10 long
// (along the rows when `along_rows`, else across them), on a 0.5 mm grid.
RangeImage two_squares(bool along_rows) {
  const int length = 30 + 10 + 30;
  RangeImage image(along_rows ? 40 : length, along_rows ? length : 40, 0.5, 0.5);
  for (int along = 0; along < length; ++along)
    for (int across = 0; across < 40; ++across) {
      const bool square = (along < 30 || along >= 40) && across >= 5 && across < 35;
      const bool bridge = along >= 30 && along < 40 && across >= 18 && across < 22;
      if (!square && !bridge) continue;
      (along_rows ? image.z_mm(across, along) : image.z_mm(along, across)) = 10.0f;
    }
  return image;
}

TEST(BlobRegions, RemainingCountsPixelsInteriorCentroidAndRows) {
  RangeImage image(20, 10, 0.5, 0.5);
  image.origin_y_mm = 100;
  for (int row = 2; row < 6; ++row)
    for (int column = 4; column < 10; ++column) image.z_mm(column, row) = 3.0f;
  const Remaining remaining = remaining_of(image);
  EXPECT_EQ(remaining.pixels, 4 * 6);
  EXPECT_DOUBLE_EQ(remaining.interior_mm2, 2 * 4 * 0.25);  // the block's inner 2 x 4 pixels
  EXPECT_NEAR(remaining.centroid_mm.x(), 0.5 * 6.5, 1e-12);
  EXPECT_NEAR(remaining.centroid_mm.y(), 100 + 0.5 * 3.5, 1e-12);
  EXPECT_NEAR(remaining.centroid_mm.z(), 3.0, 1e-12);
  EXPECT_EQ(remaining.first_row, 2);
  EXPECT_EQ(remaining.last_row, 5);
  EXPECT_EQ(sampled_points(image).size(), 2u * 3u);  // rows 2, 4; columns 4, 6, 8
}

TEST(BlobRegions, RemainingWithoutExcludedPixelsIsThatOfTheImageWithoutThem) {
  RangeImage image(20, 10, 0.5, 0.5);
  for (int row = 2; row < 8; ++row)
    for (int column = 4; column < 12; ++column) image.z_mm(column, row) = 3.0f;
  // The left half of the block taken away, by a mask or from the image itself.
  std::vector<std::uint8_t> excluded(20 * 10, 0);
  RangeImage without = image;
  for (int row = 0; row < 10; ++row)
    for (int column = 0; column < 8; ++column) {
      excluded[static_cast<std::size_t>(row) * 20 + column] = 1;
      without.z_mm(column, row) = std::numeric_limits<float>::quiet_NaN();
    }
  const Remaining masked = remaining_of(image, &excluded);
  const Remaining cut = remaining_of(without);
  EXPECT_EQ(masked.mask, cut.mask);
  EXPECT_EQ(masked.pixels, 6 * 4);
  EXPECT_DOUBLE_EQ(masked.interior_mm2, cut.interior_mm2);
  EXPECT_DOUBLE_EQ(masked.interior_mm2, 4 * 2 * 0.25);  // the inner 4 x 2 pixels
  EXPECT_EQ(masked.centroid_mm, cut.centroid_mm);
  EXPECT_EQ(masked.first_row, 2);
  EXPECT_EQ(masked.last_row, 7);
}

TEST(BlobRegions, TouchingPartsAreCutAtTheirNeckEitherWay) {
  for (const bool along_rows : {true, false}) {
    const RangeImage image = two_squares(along_rows);
    const std::vector<int> along = pixels_per(image, along_rows);
    ASSERT_EQ(along.size(), 70u);
    EXPECT_EQ(along[0], 30);
    EXPECT_EQ(along[35], 4);
    // Too close to the ends for a neck (a part is longer than 40 rows): none.
    EXPECT_TRUE(necks(along).empty()) << along_rows;
    // Twice as long: one cut, inside the bridge.
    std::vector<int> longer;
    for (const int count : along) longer.insert(longer.end(), 2, count);
    const std::vector<int> cuts = necks(longer);
    ASSERT_EQ(cuts.size(), 1u) << along_rows;
    EXPECT_GE(cuts[0], 60);
    EXPECT_LT(cuts[0], 80);
    // Across the neck's axis there is none.
    EXPECT_TRUE(necks(pixels_per(image, !along_rows)).empty()) << along_rows;
  }
}

}  // namespace
}  // namespace cosmos
