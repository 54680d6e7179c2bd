// Where a per-pixel field lands in its picture: integer upscaling to a short side of at least
// 400 px (long side at most 3000), blocks shaped by the physical pixel aspect.
#include "core/render/field_layout.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

TEST(FieldLayout, UpscalesSmallFieldsAndKeepsThePixelAspect) {
  const FieldLayout square = field_layout(12, 8, 0.5, 0.5);
  EXPECT_EQ(square.scale_x, 50);  // 8 rows * 50 = 400 px, the minimum short side
  EXPECT_EQ(square.scale_y, 50);
  const FieldLayout coarse_rows = field_layout(100, 10, 0.1, 0.4);
  EXPECT_EQ(coarse_rows.scale_x, 10);
  EXPECT_EQ(coarse_rows.scale_y, 40);
  const FieldLayout large = field_layout(2000, 1500, 0.2, 0.2);
  EXPECT_EQ(large.scale_x, 1);
  EXPECT_EQ(large.scale_y, 1);
}

TEST(FieldLayout, PixelCentresAndDisplaySizeFollowTheScales) {
  const FieldLayout layout = field_layout(12, 8, 0.5, 0.5);
  EXPECT_EQ(layout.width, 12);
  EXPECT_EQ(layout.height, 8);
  EXPECT_EQ(layout.display_width_px(), 600);
  EXPECT_EQ(layout.display_height_px(), 400);
  EXPECT_EQ(layout.origin_x_px, kFieldMarginPx);
  EXPECT_EQ(layout.origin_y_px, kFieldMarginPx);
  EXPECT_EQ(layout.centre_x_px(0), 12 + 25);
  EXPECT_EQ(layout.centre_x_px(11), 12 + 11 * 50 + 25);
  EXPECT_EQ(layout.centre_y_px(7), 12 + 7 * 50 + 25);
}

TEST(FieldLayout, FinerRowsThanColumnsWidenTheBlocks) {
  // dy / dx = 0.25: the rows are the finer axis; 10 x 100 pixels reach 400 px across at
  // 40 x 10 picture pixels per image pixel.
  const FieldLayout layout = field_layout(10, 100, 0.4, 0.1);
  EXPECT_EQ(layout.scale_x, 40);
  EXPECT_EQ(layout.scale_y, 10);
  EXPECT_EQ(layout.display_width_px(), 400);
  EXPECT_EQ(layout.display_height_px(), 1000);
}

TEST(FieldLayout, LongSideLimitAndAspectCapWin) {
  // 10 x 1000 pixels: scale 3 gives 3000 px, scale 4 would exceed the long-side limit, so the
  // short side stays at 30 px.
  const FieldLayout narrow = field_layout(10, 1000, 0.5, 0.5);
  EXPECT_EQ(narrow.scale_x, 3);
  EXPECT_EQ(narrow.scale_y, 3);
  EXPECT_LE(narrow.display_height_px(), kMaxFieldSidePx);
  // An aspect of 20 is drawn as 8: 40 x 5 pixels at 10 x 80.
  const FieldLayout squashed = field_layout(40, 5, 0.1, 2.0);
  EXPECT_EQ(squashed.scale_x, 10);
  EXPECT_EQ(squashed.scale_y, 80);
  // Unusable pixel sizes are drawn square.
  const FieldLayout unknown = field_layout(12, 8, 0.0, -1.0);
  EXPECT_EQ(unknown.scale_x, unknown.scale_y);
}

TEST(FieldLayout, EmptyFieldsHaveNoSize) {
  const FieldLayout empty = field_layout(0, 50, 0.5, 0.5);
  EXPECT_EQ(empty.display_width_px(), 0);
  EXPECT_EQ(empty.scale_x, 1);
  EXPECT_EQ(field_layout(-3, 8, 0.5, 0.5).width, 0);
}

}  // namespace
}  // namespace cosmos
