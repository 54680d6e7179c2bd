// The nine shape categories of Fig. 3.3 and their colours, and the per-patch palette of
// csmps.png and gauss_map.png.
#include "core/render/shape_category_palette.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string_view>

namespace cosmos {
namespace {

std::string_view category_name(double shape_index) {
  return kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(shape_index))].name;
}

TEST(ShapeCategoryPalette, FollowsTheIntervalsOfFigure3_3) {
  EXPECT_EQ(category_name(0.0), "cup");
  EXPECT_EQ(category_name(1.0 / 16), "trough");
  EXPECT_EQ(category_name(0.30), "rut");
  EXPECT_EQ(category_name(0.40), "saddle rut");
  EXPECT_EQ(category_name(0.5), "saddle");
  EXPECT_EQ(category_name(0.6), "saddle ridge");
  EXPECT_EQ(category_name(0.75), "ridge");
  EXPECT_EQ(category_name(0.937), "dome");
  EXPECT_EQ(category_name(15.0 / 16), "cap");
  EXPECT_EQ(category_name(1.0), "cap");
  std::set<std::array<int, 3>> colors;
  for (const ShapeCategory& c : kShapeCategoryTable)
    colors.insert({c.color.blue, c.color.green, c.color.red});
  colors.insert({kPlanarColor.blue, kPlanarColor.green, kPlanarColor.red});
  EXPECT_EQ(colors.size(), 10u);
}

TEST(ShapeCategoryPalette, TableBoundariesAreTheOddSixteenthsInOrder) {
  EXPECT_EQ(kShapeCategoryTable.front().lower, 0.0);
  EXPECT_EQ(kShapeCategoryTable.back().upper, 1.0);
  for (int k = 0; k < kShapeCategories; ++k) {
    const ShapeCategory& category = kShapeCategoryTable[static_cast<std::size_t>(k)];
    if (k > 0) {
      EXPECT_EQ(category.lower, (2 * k - 1) / 16.0) << category.name;
      EXPECT_EQ(category.lower, kShapeCategoryTable[static_cast<std::size_t>(k - 1)].upper);
    }
    // The interval's lower end, its middle and (short of rounding at its last bit) its upper
    // end fall in the category.
    EXPECT_EQ(shape_category_index(category.lower), k) << category.name;
    EXPECT_EQ(shape_category_index((category.lower + category.upper) / 2), k) << category.name;
    if (k + 1 < kShapeCategories) {
      EXPECT_EQ(shape_category_index(category.upper - 1e-12), k) << category.name;
    }
  }
}

TEST(ShapeCategoryPalette, ColoursOfKnownCategoriesAndOutOfRangeValues) {
  // Blue for the concave end, green at the saddle, red for the convex end.
  EXPECT_EQ(shape_category_color(0.02), rgb(35, 60, 200));           // cup
  EXPECT_EQ(shape_category_color(0.5), rgb(125, 205, 55));           // saddle
  EXPECT_EQ(shape_category_color(0.75), rgb(250, 170, 40));          // ridge
  EXPECT_EQ(shape_category_color(0.97), rgb(185, 20, 35));           // cap
  EXPECT_EQ(shape_category_color(-0.3), shape_category_color(0.0));  // clamped
  EXPECT_EQ(shape_category_color(1.7), shape_category_color(1.0));
  EXPECT_EQ(shape_category_index(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(kPlanarColor, rgb(150, 150, 150));
  EXPECT_EQ(kNoDataColor, rgb(0, 0, 0));
}

// HSV with hue 0.13 + id * 0.618..., saturation 0.75 (even ids) or 0.55, value 0.80
// (id % 3 == 1) or 0.97, by hand for ids 0 and 1:
//   id 0: h6 = 0.78, sector 0: (v, t, p) = (0.97, 0.80995, 0.2425) -> (247, 207, 62)
//   id 1: h6 = 4.4882, sector 4: (t, p, v) = (0.5748, 0.36, 0.80) -> (147, 92, 204)
TEST(ShapeCategoryPalette, PatchColoursByHandAndNeverDark) {
  EXPECT_EQ(patch_color(0), rgb(247, 207, 62));
  EXPECT_EQ(patch_color(1), rgb(147, 92, 204));
  EXPECT_EQ(patch_color(-1), patch_color(1));
  std::set<std::array<int, 3>> distinct;
  for (int id = 0; id < 200; ++id) {
    const BgrColor c = patch_color(id);
    // The brightest channel is the HSV value, at least 0.80 * 255: far from the boundary
    // colour (40) and no-data black.
    EXPECT_GE(std::max({c.blue, c.green, c.red}), 204) << id;
    EXPECT_NE(c, kBoundaryColor);
    EXPECT_NE(c, kNoDataColor);
    if (id > 0) {
      EXPECT_NE(c, patch_color(id - 1)) << id;
    }
    distinct.insert({c.blue, c.green, c.red});
  }
  EXPECT_GT(distinct.size(), 190u);
}

}  // namespace
}  // namespace cosmos
