// range.png: depth colour-mapped with turbo over the finite z range (near the sensor, high z,
// red), no data black, a colour bar beside the field; on the hand-made range image
// (hand_made_view.hpp: column 0 empty, z = 100 + column mm elsewhere).
#include "core/render/range_picture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/render/field_layout.hpp"
#include "core/render/shape_category_palette.hpp"
#include "tests/core/hand_made_view.hpp"
#include "tests/core/render/picture_probe.hpp"

namespace cosmos::testing {
namespace {

TEST(RangePicture, NoDataIsBlackAndDepthIsColourMapped) {
  const RangeImage image = hand_made_range_image();
  const BgrPicture picture = render_range_picture(image);
  const FieldLayout layout = field_layout(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  EXPECT_EQ(at_pixel(picture, layout, 0, 0), kNoDataColor);
  // Nearest and farthest depths take the two ends of the colour map: different colours.
  EXPECT_NE(at_pixel(picture, layout, 1, 0), at_pixel(picture, layout, 11, 0));
  EXPECT_EQ(at_pixel(picture, layout, 5, 0), at_pixel(picture, layout, 5, 7));
}

// z runs from 101 (column 1, the far end of turbo: blue) to 111 mm (column 11, near: red);
// column 6 is halfway, level round(0.5 * 255) = 128.
TEST(RangePicture, NearIsRedFarIsBlueAndTheMiddleIsTheMiddleOfTheMap) {
  const RangeImage image = hand_made_range_image();
  const BgrPicture picture = render_range_picture(image);
  const FieldLayout layout = field_layout(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  const BgrColor far = at_pixel(picture, layout, 1, 3);
  const BgrColor near = at_pixel(picture, layout, 11, 3);
  EXPECT_GT(far.blue, far.red);
  EXPECT_GT(near.red, near.blue);
  // Every pixel of a column has its column's colour; neighbouring columns differ.
  for (int column = 1; column < kHandWidth; ++column) {
    for (int row = 1; row < kHandHeight; ++row)
      EXPECT_EQ(at_pixel(picture, layout, column, row), at_pixel(picture, layout, column, 0));
    if (column > 1) {
      EXPECT_NE(at_pixel(picture, layout, column, 0), at_pixel(picture, layout, column - 1, 0));
    }
  }
  // A flat scene has no span: its one depth takes the middle of the map, column 6's colour.
  RangeImage flat = image;
  for (float& z : flat.z_mm.values())
    if (std::isfinite(z)) z = 42.0f;
  EXPECT_EQ(at_pixel(render_range_picture(flat), layout, 3, 3), at_pixel(picture, layout, 6, 3));
}

// The field (600 x 400 px after the 12 px margin) and a 150 px panel for the colour bar, which
// runs from level 255 at its top (y 42) to 0 at its bottom (y 402), 20 px right of the field,
// in the field's colours.
TEST(RangePicture, SizeFromTheLayoutAndTheColourBarUsesTheSameMap) {
  const RangeImage image = hand_made_range_image();
  const BgrPicture picture = render_range_picture(image);
  const FieldLayout layout = field_layout(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  EXPECT_EQ(picture.width(), 12 + 600 + 150);
  EXPECT_EQ(picture.height(), 12 + 400 + 12);
  const int bar_x = 12 + 600 + 20 + 13;
  // Level round(255 (402 - y) / 360) of the bar against column c's round(25.5 (c - 1)):
  // 51 at y = 330 (column 3), 128 at y = 221 (column 6), 153 at y = 186 (column 7), 204 at
  // y = 114 (column 9).
  EXPECT_EQ(picture(bar_x, 330), at_pixel(picture, layout, 3, 0));
  EXPECT_EQ(picture(bar_x, 221), at_pixel(picture, layout, 6, 0));
  EXPECT_EQ(picture(bar_x, 186), at_pixel(picture, layout, 7, 0));
  EXPECT_EQ(picture(bar_x, 114), at_pixel(picture, layout, 9, 0));
}

TEST(RangePicture, AnImageWithoutDataIsBlackAndAnEmptyOneTheEmptyCanvas) {
  RangeImage blank(6, 4, 0.5, 0.5);
  for (float& z : blank.z_mm.values()) z = std::numeric_limits<float>::quiet_NaN();
  const BgrPicture picture = render_range_picture(blank);
  const FieldLayout layout = field_layout(6, 4, 0.5, 0.5);
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 6; ++column)
      EXPECT_EQ(at_pixel(picture, layout, column, row), kNoDataColor);
  const BgrPicture empty = render_range_picture(RangeImage{});
  EXPECT_EQ(empty.width(), kMinFieldSidePx);
  EXPECT_EQ(empty.height(), kMinFieldSidePx);
}

}  // namespace
}  // namespace cosmos::testing
