// csmps.png: every CSMP (§3.5.2) in its own colour, dark boundaries between patches, ids at
// label anchors inside their patches, on the hand-made view (hand_made_view.hpp).
#include "core/render/csmp_picture.hpp"

#include <gtest/gtest.h>

#include <array>
#include <set>
#include <vector>

#include "core/render/field_layout.hpp"
#include "core/render/shape_category_palette.hpp"
#include "tests/core/hand_made_view.hpp"
#include "tests/core/render/picture_probe.hpp"

namespace cosmos::testing {
namespace {

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

// At 50 picture pixels per image pixel the boundary strip is 50 / 10 = 5, capped at 3 px: the
// three picture columns left of the patch 0 / patch 1 edge are dark, the fourth is not; and a
// boundary runs along rows as well (patch 1 above patch 2).
TEST(CsmpPicture, BoundaryStripsAreThreePixelsWideAtThisScale) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_csmp_picture(analysis.segmentation, kHandPixelMm, kHandPixelMm);
  const FieldLayout layout = field_layout(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  ASSERT_EQ(layout.scale_x, 50);
  const int y = layout.centre_y_px(6);
  const int edge_x = layout.origin_x_px + 5 * layout.scale_x - 1;  // last column of pixel 4
  for (int dx = 0; dx < 3; ++dx) EXPECT_EQ(picture(edge_x - dx, y), kBoundaryColor) << dx;
  EXPECT_EQ(picture(edge_x - 3, y), patch_color(0));
  for (int dx = 1; dx <= 3; ++dx) EXPECT_EQ(picture(edge_x + dx, y), kBoundaryColor) << dx;
  EXPECT_EQ(picture(edge_x + 4, y), patch_color(2));
  // Rows 3 (patch 1) and 4 (patch 2) of column 6.
  const int x = layout.centre_x_px(6);
  const int row_edge_y = layout.origin_y_px + 4 * layout.scale_y - 1;
  EXPECT_EQ(picture(x, row_edge_y - 2), kBoundaryColor);
  EXPECT_EQ(picture(x, row_edge_y - 3), patch_color(1));
  EXPECT_EQ(picture(x, row_edge_y + 3), kBoundaryColor);
  EXPECT_EQ(picture(x, row_edge_y + 4), patch_color(2));
}

// The field (600 x 400 px after the 12 px margin), the right margin and a 40 px caption.
TEST(CsmpPicture, SizeFromTheLayoutAndAnEmptySegmentationGivesTheEmptyCanvas) {
  const ViewAnalysis analysis = hand_made_view_analysis();
  const BgrPicture picture = render_csmp_picture(analysis.segmentation, kHandPixelMm, kHandPixelMm);
  EXPECT_EQ(picture.width(), 12 + 600 + 12);
  EXPECT_EQ(picture.height(), 12 + 400 + 40);
  // A field narrower than the caption needs keeps the 360 px minimum width.
  CsmpSegmentation narrow;
  narrow.patch_of_pixel = PixelGrid<std::int32_t>(2, 100, 0);
  const BgrPicture tall = render_csmp_picture(narrow, 1.0, 1.0);
  EXPECT_EQ(tall.width(), 360);
  EXPECT_EQ(render_csmp_picture(CsmpSegmentation{}, 0.5, 0.5).width(), kMinFieldSidePx);
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

TEST(CsmpPicture, CentroidsSkipUnusedIdsAndNoPatchPixels) {
  PixelGrid<std::int32_t> labels(4, 2, kNoPatch);
  labels(0, 0) = 5;
  labels(1, 0) = 5;
  labels(3, 1) = 2;
  const std::vector<PatchPixelCentroid> centroids = patch_pixel_centroids(labels);
  ASSERT_EQ(centroids.size(), 2u);
  EXPECT_EQ(centroids[0].patch, 2);
  EXPECT_EQ(centroids[0].pixels, 1);
  EXPECT_DOUBLE_EQ(centroids[0].column, 3.0);
  EXPECT_EQ(centroids[1].patch, 5);
  EXPECT_DOUBLE_EQ(centroids[1].column, 0.5);
  EXPECT_DOUBLE_EQ(centroids[1].row, 0.0);
  EXPECT_TRUE(patch_pixel_centroids(PixelGrid<std::int32_t>(3, 3, kNoPatch)).empty());
}

}  // namespace
}  // namespace cosmos::testing
