// The pictures of `cosmos inspect`, on a hand-made ViewAnalysis (hand_made_view.hpp): colours
// at known pixels, placement, and the files written.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "core/render/csmp_picture.hpp"
#include "core/render/field_layout.hpp"
#include "core/render/gauss_map_picture.hpp"
#include "core/render/range_picture.hpp"
#include "core/render/shape_category_palette.hpp"
#include "core/render/shape_index_picture.hpp"
#include "core/render/spectrum_picture.hpp"
#include "core/render/view_pictures.hpp"
#include "tests/core/hand_made_view.hpp"

namespace cosmos::testing {
namespace {

BgrColor at_pixel(const BgrPicture& picture, const FieldLayout& layout, int column, int row) {
  return picture(layout.centre_x_px(column), layout.centre_y_px(row));
}

int count_color(const BgrPicture& picture, BgrColor color) {
  int count = 0;
  for (const BgrColor& c : picture.values()) count += c == color ? 1 : 0;
  return count;
}

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16 and 20).
std::array<int, 2> png_size(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::vector<unsigned char> head(24);
  file.read(reinterpret_cast<char*>(head.data()), 24);
  const auto be32 = [&](int at) {
    return int(head[at]) << 24 | int(head[at + 1]) << 16 | int(head[at + 2]) << 8 |
           int(head[at + 3]);
  };
  return {be32(16), be32(20)};
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), {}};
}

TEST(ShapeCategoryPalette, FollowsTheIntervalsOfFigure3_3) {
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(0.0))].name, "cup");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(1.0 / 16))].name,
            "trough");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(0.30))].name, "rut");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(0.40))].name,
            "saddle rut");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(0.5))].name,
            "saddle");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(0.6))].name,
            "saddle ridge");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(0.75))].name,
            "ridge");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(0.937))].name,
            "dome");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(15.0 / 16))].name,
            "cap");
  EXPECT_EQ(kShapeCategoryTable[static_cast<std::size_t>(shape_category_index(1.0))].name, "cap");
  std::set<std::array<int, 3>> colors;
  for (const ShapeCategory& c : kShapeCategoryTable)
    colors.insert({c.color.blue, c.color.green, c.color.red});
  colors.insert({kPlanarColor.blue, kPlanarColor.green, kPlanarColor.red});
  EXPECT_EQ(colors.size(), 10u);
}

TEST(FieldLayout, UpscalesSmallFieldsAndKeepsThePixelAspect) {
  const FieldLayout square = field_layout(kHandWidth, kHandHeight, 0.5, 0.5);
  EXPECT_EQ(square.scale_x, 50);  // 8 rows * 50 = 400 px, the minimum short side
  EXPECT_EQ(square.scale_y, 50);
  const FieldLayout coarse_rows = field_layout(100, 10, 0.1, 0.4);
  EXPECT_EQ(coarse_rows.scale_x, 10);
  EXPECT_EQ(coarse_rows.scale_y, 40);
  const FieldLayout large = field_layout(2000, 1500, 0.2, 0.2);
  EXPECT_EQ(large.scale_x, 1);
  EXPECT_EQ(large.scale_y, 1);
}

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

TEST(CsmpPicture, OneDistinctColourPerPatchWithDarkBoundaries) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_csmp_picture(analysis.segmentation, kHandPixelMm, kHandPixelMm);
  const FieldLayout layout = field_layout(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  // A corner pixel of each patch, away from the id label at its centroid.
  const std::array<std::array<int, 3>, 4> corner_of_patch{
      {{0, 1, 0}, {1, 8, 0}, {2, 8, 7}, {3, 11, 7}}};
  std::set<std::array<int, 3>> colors;
  for (const auto& [patch, column, row] : corner_of_patch) {
    const BgrColor color = at_pixel(picture, layout, column, row);
    EXPECT_EQ(color, patch_color(patch)) << "patch " << patch;
    EXPECT_NE(color, kBoundaryColor);
    EXPECT_NE(color, kNoDataColor);
    colors.insert({color.blue, color.green, color.red});
  }
  EXPECT_EQ(colors.size(), analysis.view.patches.size());
  EXPECT_EQ(at_pixel(picture, layout, 0, 0), kNoDataColor);
  // Pixel (4, 0) of patch 0 touches patch 1 on its right: its right edge is boundary.
  const int right_edge_x = layout.origin_x_px + 5 * layout.scale_x - 1;
  EXPECT_EQ(picture(right_edge_x, layout.centre_y_px(0)), kBoundaryColor);
  EXPECT_EQ(picture(right_edge_x + 1, layout.centre_y_px(0)), kBoundaryColor);
  // Its left edge touches no data: no boundary there.
  EXPECT_EQ(picture(layout.origin_x_px + layout.scale_x, layout.centre_y_px(0)), patch_color(0));

  const std::vector<PatchPixelCentroid> centroids =
      patch_pixel_centroids(analysis.segmentation.patch_of_pixel);
  ASSERT_EQ(centroids.size(), 4u);
  EXPECT_DOUBLE_EQ(centroids[0].column, 2.5);
  EXPECT_DOUBLE_EQ(centroids[0].row, 3.5);
  EXPECT_EQ(centroids[0].pixels, 32);
  EXPECT_DOUBLE_EQ(centroids[2].row, 5.5);
}

TEST(CsmpPicture, LabelsARingInsideTheRingNotAtItsCentroid) {
  // Patch 0 is a ring around patch 1: its pixel centroid (4, 4) lies in patch 1.
  PixelGrid<std::int32_t> labels(9, 9, 0);
  for (int row = 3; row <= 5; ++row) {
    for (int column = 3; column <= 5; ++column) labels(column, row) = 1;
  }
  const std::vector<PatchPixelCentroid> centroids = patch_pixel_centroids(labels);
  ASSERT_EQ(centroids.size(), 2u);
  EXPECT_DOUBLE_EQ(centroids[0].column, 4.0);
  EXPECT_DOUBLE_EQ(centroids[0].row, 4.0);
  const int column = static_cast<int>(centroids[0].label_column);
  const int row = static_cast<int>(centroids[0].label_row);
  EXPECT_EQ(labels(column, row), 0) << column << ", " << row;
  EXPECT_DOUBLE_EQ(centroids[1].label_column, 4.0);  // convex: the centroid itself
  EXPECT_DOUBLE_EQ(centroids[1].label_row, 4.0);
}

TEST(GaussMapPicture, PlacesDiscsAtTheirNormals) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_gauss_map_picture(analysis.view);
  ASSERT_EQ(picture.width(), kGaussMapSizePx);
  ASSERT_EQ(picture.height(), kGaussMapSizePx);
  const int centre = kGaussMapSizePx / 2;
  // Patch 0 faces the sensor (+z): its disc, the largest (radius 0.14 R = 35 px), is centred.
  EXPECT_EQ(picture(centre, centre), patch_color(0));
  EXPECT_EQ(picture(centre, centre - 28), patch_color(0));
  EXPECT_EQ(picture(centre, centre + 28), patch_color(0));
  EXPECT_NE(picture(centre, centre - 40), patch_color(0));
  // Patch 1 faces +x by 0.6: 0.6 R to the right of the centre.
  const Eigen::Vector2d right = gauss_map_position_px({0.6, 0, 0.8});
  EXPECT_DOUBLE_EQ(right.x(), centre + 0.6 * kGaussMapRadiusPx);
  EXPECT_EQ(picture(static_cast<int>(right.x()), static_cast<int>(right.y())), patch_color(1));
  // Patch 2 faces -y: above the centre (+y is drawn downwards).
  EXPECT_EQ(picture(centre, centre - 150), patch_color(2));
  EXPECT_EQ(picture(4, centre), rgb(255, 255, 255));
}

TEST(SpectrumPicture, HasBarsInCategoryColoursAndAPlanarBar) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_spectrum_picture(analysis.spectrum, analysis.moments);
  EXPECT_EQ(picture.width(), kSpectrumWidthPx);
  EXPECT_EQ(picture.height(), kSpectrumHeightPx);
  // The tallest bin (36 % of the area, S_I 0.97) fills a column of the plot in cap colour; the
  // dome name under the axis is the only dome-coloured ink.
  EXPECT_GT(count_color(picture, kShapeCategoryTable[8].color), 550);  // ~318 px high, 2-3 wide
  EXPECT_GT(count_color(picture, kShapeCategoryTable[0].color), 400);  // ~239 px high
  EXPECT_LT(count_color(picture, kShapeCategoryTable[7].color), 200);
  EXPECT_GT(count_color(picture, kPlanarColor), 1500);  // 18 % on a 350 px axis, 50 px wide
}

TEST(ViewPictures, WritesFiveDeterministicPngs) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const RangeImage image = hand_made_range_image();
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "cosmos_render_test" / "out";
  std::filesystem::remove_all(dir.parent_path());
  write_view_pictures(image, analysis, dir);
  const std::string first_range = file_bytes(dir / "range.png");
  write_view_pictures(image, analysis, dir);
  EXPECT_EQ(file_bytes(dir / "range.png"), first_range);

  const auto expect_size = [&](const char* name, const BgrPicture& picture) {
    ASSERT_TRUE(std::filesystem::exists(dir / name)) << name;
    EXPECT_EQ(png_size(dir / name), (std::array<int, 2>{picture.width(), picture.height()}))
        << name;
  };
  expect_size("range.png", render_range_picture(image));
  expect_size("shape_index.png",
              render_shape_index_picture(analysis.field, kHandPixelMm, kHandPixelMm));
  expect_size("csmps.png", render_csmp_picture(analysis.segmentation, kHandPixelMm, kHandPixelMm));
  expect_size("gauss_map.png", render_gauss_map_picture(analysis.view));
  expect_size("spectrum.png", render_spectrum_picture(analysis.spectrum, analysis.moments));
  std::filesystem::remove_all(dir.parent_path());
}

TEST(RangePicture, NoDataIsBlackAndDepthIsColourMapped) {
  const RangeImage image = hand_made_range_image();
  const BgrPicture picture = render_range_picture(image);
  const FieldLayout layout = field_layout(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  EXPECT_EQ(at_pixel(picture, layout, 0, 0), kNoDataColor);
  // Nearest and farthest depths take the two ends of the colour map: different colours.
  EXPECT_NE(at_pixel(picture, layout, 1, 0), at_pixel(picture, layout, 11, 0));
  EXPECT_EQ(at_pixel(picture, layout, 5, 0), at_pixel(picture, layout, 5, 7));
}

}  // namespace
}  // namespace cosmos::testing
