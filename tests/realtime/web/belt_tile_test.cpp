// A part's tile of the belt strip: the view's pixels max-pooled into strip pixels, the part's
// last profile in the tile's first column (nearest the laser sheet), the loop frame's mirrored
// columns turned back so that strip rows run along +x_belt, and the tile placed across the
// belt where the part lay.
#include "realtime/web/belt_tile.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace cosmos {
namespace {

constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

// Loop columns 0..19 at x_L = -4 + 0.4 c; two grid cells per strip pixel.
BeltStripGeometry geometry() {
  return {.grid_mm = 0.4, .belt_columns = 20, .x0_loop_mm = -4.0, .decimation = 2};
}

// A 4-column, 6-row view of loop columns 10..13, empty but for what the test sets.
RangeImage part_view() {
  RangeImage image(4, 6, 0.4, 0.4);
  image.origin_x_mm = -4.0 + 10 * 0.4;
  for (std::size_t i = 0; i < image.z_mm.size(); ++i) image.z_mm[i] = kNone;
  return image;
}

TEST(BeltTile, TurnsTheLoopFrameIntoTheStripsOrientation) {
  RangeImage image = part_view();
  image.z_mm(0, 0) = 10.0f;  // first row (downstream end), loop column 10 (x_belt 0)
  image.z_mm(3, 5) = 5.0f;   // last row (upstream end), loop column 13 (x_belt -1.2 mm)
  const BeltTile tile = make_belt_tile(image, 100, geometry());
  EXPECT_EQ(tile.first_profile, 100);
  EXPECT_EQ(tile.last_profile, 105);
  ASSERT_EQ(tile.width_px, 3);
  ASSERT_EQ(tile.height_px, 2);
  // Loop columns 10..13 are strip rows (20 - 1 - c) / 2: 4.5 .. 3, so the tile starts at 3.
  EXPECT_DOUBLE_EQ(tile.top_px, 3.0);
  EXPECT_DOUBLE_EQ(tile.z_max_mm, 10.0);
  // The last profile nearest the sheet (column 0), the smaller x_belt higher up (row 0).
  EXPECT_EQ(tile.level(0, 0), 1 + 127);
  EXPECT_EQ(tile.level(2, 1), 255);
  int filled = 0;
  for (const std::uint8_t level : tile.levels) filled += level != 0;
  EXPECT_EQ(filled, 2);
}

TEST(BeltTile, KeepsTheHighestPixelOfEachBlock) {
  RangeImage image = part_view();
  image.z_mm(0, 4) = 2.0f;
  image.z_mm(1, 5) = 8.0f;  // same 2x2 block as (0, 4)
  image.z_mm(3, 0) = 4.0f;
  const BeltTile tile = make_belt_tile(image, 0, geometry());
  EXPECT_DOUBLE_EQ(tile.z_max_mm, 8.0);
  EXPECT_EQ(tile.level(0, 1), 255);
  EXPECT_EQ(tile.level(2, 0), 1 + 127);
}

TEST(BeltTile, AnEmptyViewGivesAnEmptyTile) {
  const BeltTile tile = make_belt_tile(part_view(), 0, geometry());
  EXPECT_EQ(tile.levels.size(), 6u);
  for (const std::uint8_t level : tile.levels) EXPECT_EQ(level, 0);
  EXPECT_GT(tile.z_max_mm, 0.0);  // the page divides by it
}

TEST(BeltStripGeometry, DecimatesByWholeGridCells) {
  EXPECT_EQ(BeltStripGeometry::decimation_for(1.6, 0.4), 4);
  EXPECT_EQ(BeltStripGeometry::decimation_for(0.1, 0.4), 1);
  EXPECT_EQ(BeltStripGeometry::decimation_for(1.0, 0.4), 3);  // 2.5 cells, rounded up
  const BeltStripGeometry g{.grid_mm = 0.4, .belt_columns = 641, .decimation = 4};
  EXPECT_DOUBLE_EQ(g.mm_per_pixel(), 1.6);
  EXPECT_EQ(g.belt_width_px(), 161);
}

}  // namespace
}  // namespace cosmos
