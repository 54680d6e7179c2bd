// shape_index.png: each pixel in its Fig. 3.3 category colour, planar grey, invalid black, and
// the legend beside the field, on the hand-made view (hand_made_view.hpp).
#include "core/render/shape_index_picture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/render/field_layout.hpp"
#include "core/render/shape_category_palette.hpp"
#include "tests/core/hand_made_view.hpp"
#include "tests/core/render/picture_probe.hpp"

namespace cosmos::testing {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(ShapeIndexPicture, ColoursCategoriesPlanarAndInvalid) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_shape_index_picture(analysis.field, kHandPixelMm, kHandPixelMm);
  const FieldLayout layout = field_layout(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  ASSERT_GE(picture.width(), layout.origin_x_px + layout.display_width_px());
  ASSERT_GE(picture.height(), layout.origin_y_px + layout.display_height_px());
  EXPECT_EQ(at_pixel(picture, layout, 2, 3), kShapeCategoryTable[8].color);   // S_I 0.97: cap
  EXPECT_EQ(at_pixel(picture, layout, 6, 1), kShapeCategoryTable[4].color);   // S_I 0.50: saddle
  EXPECT_EQ(at_pixel(picture, layout, 10, 6), kShapeCategoryTable[0].color);  // S_I 0.03: cup
  EXPECT_EQ(at_pixel(picture, layout, 6, 6), kPlanarColor);
  EXPECT_EQ(at_pixel(picture, layout, 0, 4), kNoDataColor);
}

TEST(ShapeIndexPicture, PixelColourFollowsTheLabelFirst) {
  EXPECT_EQ(shape_index_pixel_color(SurfaceLabel::kCurved, 0.6f), kShapeCategoryTable[5].color);
  EXPECT_EQ(shape_index_pixel_color(SurfaceLabel::kPlanar, 0.6f), kPlanarColor);
  EXPECT_EQ(shape_index_pixel_color(SurfaceLabel::kPlanar, kNaN), kPlanarColor);
  EXPECT_EQ(shape_index_pixel_color(SurfaceLabel::kCurved, kNaN), kNoDataColor);
  EXPECT_EQ(shape_index_pixel_color(SurfaceLabel::kInvalid, 0.6f), kNoDataColor);
}

// The picture is the field (12 x 8 pixels at 50 px each, 12 px margin) plus a 300 px legend;
// its height is the field's 400 px, taller than the legend, plus the margins. The legend lists
// the categories from cap (top) down to cup, then planar and no data, rows 26 px apart,
// starting 30 px below the field's top, its swatches 24 px right of the field.
TEST(ShapeIndexPicture, SizeFromTheLayoutAndTheLegendSwatchesInOrder) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_shape_index_picture(analysis.field, kHandPixelMm, kHandPixelMm);
  EXPECT_EQ(picture.width(), 12 + 600 + 300);
  EXPECT_EQ(picture.height(), 12 + 400 + 12);
  const int swatch_x = 12 + 600 + 24 + 12;  // the middle of a 24 px swatch
  const auto swatch_y = [](int row) { return 12 + 30 + 26 * row + 8; };
  for (int row = 0; row < kShapeCategories; ++row)
    EXPECT_EQ(picture(swatch_x, swatch_y(row)),
              kShapeCategoryTable[static_cast<std::size_t>(kShapeCategories - 1 - row)].color)
        << "legend row " << row;
  const int planar_y = swatch_y(kShapeCategories) + 6;
  EXPECT_EQ(picture(swatch_x, planar_y), kPlanarColor);
  EXPECT_EQ(picture(swatch_x, planar_y + 26), kNoDataColor);
}

TEST(ShapeIndexPicture, FieldWithoutShapeIndicesPaintsCurvedPixelsBlack) {
  ViewAnalysis analysis = hand_made_view_analysis();
  analysis.field.shape_index = PixelGrid<float>();  // labels only
  const BgrPicture picture = render_shape_index_picture(analysis.field, kHandPixelMm, kHandPixelMm);
  const FieldLayout layout = field_layout(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  EXPECT_EQ(at_pixel(picture, layout, 2, 3), kNoDataColor);
  EXPECT_EQ(at_pixel(picture, layout, 6, 6), kPlanarColor);
}

TEST(ShapeIndexPicture, EmptyFieldGivesTheEmptyCanvas) {
  const BgrPicture picture = render_shape_index_picture(ShapeIndexField{}, 0.5, 0.5);
  EXPECT_EQ(picture.width(), kMinFieldSidePx);
  EXPECT_EQ(picture.height(), kMinFieldSidePx);
  EXPECT_EQ(picture(5, kMinFieldSidePx - 5), rgb(255, 255, 255));
}

}  // namespace
}  // namespace cosmos::testing
