// The COSMOS of one view (§3.2.2, core/representation/cosmos_view.hpp) built from a hand-made
// segmentation of a 9 x 4 field whose per-patch sums are known: areas, orientations G0
// (Eq. 3.7), mean shape index and curvedness (Eq. 3.16), centroids, the connectivity list V
// (Eq. 3.10) with its boundary strengths, and the Gauss-map points of G1/G2 (Eqs. 3.14-3.15).
#include "core/representation/cosmos_view.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

constexpr int kWidth = 9;
constexpr int kHeight = 4;

//   columns 0-2  patch 0, area 0.25 per pixel; column 0: normal +z, S_I 0.80, curvedness 0.1;
//                columns 1-2: normal (0, 0.6, 0.8), S_I 0.95, curvedness 0.2
//   columns 3-5  patch 1, planar, area 0.5 per pixel, normal (0.6, 0, 0.8)
//   columns 6-8  patch 2 but pixel (6, 3), which has no patch: area 0.25 per pixel, S_I
//                `patch2_shape_index`, curvedness 0.3, normal `patch2_normal`
// Pixel (column, row) lies at (0.5 column, 0.5 row, 10 + column) mm. Every pixel is linked to
// every neighbour inside the field except (2, 0) and (3, 0), across a depth jump.
struct HandView {
  DarbouxFrameField frames{kWidth, kHeight};
  ShapeIndexField field = make_shape_index_field(kWidth, kHeight);
  CsmpSegmentation segmentation;
};

int patch_of(int column, int row) {
  if (column == 6 && row == 3) return kNoPatch;
  return column / 3;
}

HandView hand_view(const Eigen::Vector3d& patch2_normal, float patch2_shape_index) {
  HandView view;
  view.segmentation.patch_count = 3;
  view.segmentation.patch_of_pixel = PixelGrid<std::int32_t>(kWidth, kHeight, kNoPatch);
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const std::size_t i = view.field.label.index(column, row);
      std::uint8_t mask = 0;
      for (int k = 0; k < 8; ++k)
        if (view.field.label.contains(column + kNeighborOffsets[k].column,
                                      row + kNeighborOffsets[k].row))
          mask |= static_cast<std::uint8_t>(1u << k);
      view.field.same_side[i] = view.frames.same_side[i] = mask;
      view.frames.position_mm[0][i] = 0.5f * column;
      view.frames.position_mm[1][i] = 0.5f * row;
      view.frames.position_mm[2][i] = 10.0f + column;
      const int patch = patch_of(column, row);
      view.segmentation.patch_of_pixel[i] = patch;
      if (patch == kNoPatch) continue;
      Eigen::Vector3d normal;
      float shape_index = 0, curvedness = 0, area = 0.25f;
      SurfaceLabel label = SurfaceLabel::kCurved;
      if (patch == 0) {
        normal = column == 0 ? Eigen::Vector3d(0, 0, 1) : Eigen::Vector3d(0, 0.6, 0.8);
        shape_index = column == 0 ? 0.80f : 0.95f;
        curvedness = column == 0 ? 0.1f : 0.2f;
      } else if (patch == 1) {
        normal = {0.6, 0, 0.8};
        shape_index = kPlanarShapeIndex;
        area = 0.5f;
        label = SurfaceLabel::kPlanar;
      } else {
        normal = patch2_normal;
        shape_index = patch2_shape_index;
        curvedness = 0.3f;
      }
      view.field.label[i] = label;
      view.field.shape_index[i] = shape_index;
      view.field.curvedness_per_mm[i] = curvedness;
      view.field.area_mm2[i] = area;
      view.frames.valid[i] = 1;
      for (int c = 0; c < 3; ++c) view.frames.frame[kNx + c][i] = static_cast<float>(normal[c]);
    }
  view.field.same_side(2, 0) &= static_cast<std::uint8_t>(~(1u << 4));  // right
  view.field.same_side(3, 0) &= static_cast<std::uint8_t>(~(1u << 3));  // left
  return view;
}

// Patch 0's G0: the area-weighted mean of 4 normals +z and 8 normals (0, 0.6, 0.8).
Eigen::Vector3d patch0_orientation() { return Eigen::Vector3d(0, 1.2, 2.6).normalized(); }

// patch0_orientation() turned by `deg` about x.
Eigen::Vector3d turned_from_patch0(double deg) {
  return Eigen::AngleAxisd(deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitX()) *
         patch0_orientation();
}

CosmosView build(const HandView& view) {
  return build_cosmos_view(view.frames, view.field, view.segmentation);
}

TEST(CosmosView, PatchAreasOrientationsAndMeansAreTheAreaWeightedSums) {
  const CosmosView cosmos = build(hand_view(turned_from_patch0(1.0), 0.902f));
  ASSERT_EQ(cosmos.patches.size(), 3u);
  const Csmp &p0 = cosmos.patches[0], &p1 = cosmos.patches[1], &p2 = cosmos.patches[2];
  EXPECT_EQ(p0.id, 0);
  EXPECT_EQ(p2.id, 2);
  EXPECT_NEAR(p0.area_mm2, 3.0, 1e-9);
  EXPECT_NEAR(p1.area_mm2, 6.0, 1e-9);
  EXPECT_NEAR(p2.area_mm2, 2.75, 1e-9);
  EXPECT_NEAR(cosmos.visible_area_mm2, 11.75, 1e-9);
  EXPECT_EQ(p0.pixels, 12);
  EXPECT_EQ(p2.pixels, 11);
  EXPECT_LT((p0.mean_normal - patch0_orientation()).norm(), 1e-6);
  EXPECT_LT((p1.mean_normal - Eigen::Vector3d(0.6, 0, 0.8)).norm(), 1e-6);
  EXPECT_LT((p2.mean_normal - turned_from_patch0(1.0)).norm(), 1e-6);
  // (4 * 0.80 + 8 * 0.95) / 12 and (4 * 0.1 + 8 * 0.2) / 12.
  EXPECT_NEAR(p0.shape_index, 0.9, 1e-6);
  EXPECT_NEAR(p0.shape_index_min, 0.80, 1e-6);
  EXPECT_NEAR(p0.shape_index_max, 0.95, 1e-6);
  EXPECT_NEAR(p0.mean_curvedness_per_mm, 1.0 / 6.0, 1e-6);
  EXPECT_FALSE(p0.planar);
  EXPECT_TRUE(p1.planar);
  EXPECT_NEAR(p1.shape_index, kPlanarShapeIndex, 1e-9);
  EXPECT_NEAR(p2.shape_index, 0.902, 1e-6);
  EXPECT_LT((p0.centroid_mm - Eigen::Vector3d(0.5, 0.75, 11.0)).norm(), 1e-6);
  // Patch 2 without pixel (6, 3): 3, 4 and 4 pixels in columns 6, 7, 8; 3, 3, 3, 2 in rows.
  EXPECT_LT((p2.centroid_mm - Eigen::Vector3d(39.0 / 11, 7.5 / 11, 10 + 78.0 / 11)).norm(), 1e-6);
}

TEST(CosmosView, ConnectivityCountsTheLinkedPixelPairsAcrossEachBoundary) {
  const CosmosView cosmos = build(hand_view(turned_from_patch0(1.0), 0.902f));
  // 0-1: 4 horizontal and 6 diagonal pairs across columns 2|3, less the unlinked (2, 0)-(3, 0).
  // 1-2: across columns 5|6 without pixel (6, 3): 3 horizontal and 5 diagonal pairs.
  ASSERT_EQ(cosmos.patches[0].neighbors.size(), 1u);
  EXPECT_EQ(cosmos.patches[0].neighbors[0].patch, 1);
  EXPECT_EQ(cosmos.patches[0].neighbors[0].shared_boundary_pixels, 9);
  ASSERT_EQ(cosmos.patches[1].neighbors.size(), 2u);
  EXPECT_EQ(cosmos.patches[1].neighbors[0].patch, 0);  // ascending id
  EXPECT_EQ(cosmos.patches[1].neighbors[0].shared_boundary_pixels, 9);
  EXPECT_EQ(cosmos.patches[1].neighbors[1].patch, 2);
  EXPECT_EQ(cosmos.patches[1].neighbors[1].shared_boundary_pixels, 8);
  ASSERT_EQ(cosmos.patches[2].neighbors.size(), 1u);
  EXPECT_EQ(cosmos.patches[2].neighbors[0].patch, 1);
  EXPECT_EQ(cosmos.patches[2].neighbors[0].shared_boundary_pixels, 8);
}

TEST(CosmosView, PatchesOfOneOrientationAndShapeIndexShareOneSupportTerm) {
  // Patch 2 lies 1 degree from patch 0 (within the 2 degree Gauss-map point) with S_I 0.002
  // away (within the 0.005 of one term).
  const CosmosView cosmos = build(hand_view(turned_from_patch0(1.0), 0.902f));
  ASSERT_EQ(cosmos.gauss_map.size(), 2u);
  const GaussMapPoint& shared = cosmos.gauss_map[0];
  EXPECT_LT((shared.direction - patch0_orientation()).norm(), 1e-6);  // the first patch's G0
  ASSERT_EQ(shared.terms.size(), 1u);
  EXPECT_EQ(shared.terms[0].patches, (std::vector<int>{0, 2}));
  EXPECT_NEAR(shared.terms[0].shape_index, 0.9, 1e-6);
  EXPECT_NEAR(shared.terms[0].area_mm2, 3.0 + 2.75, 1e-6);
  EXPECT_NEAR(shared.terms[0].curvedness_area, 3.0 / 6.0 + 0.3 * 2.75, 1e-6);
  const GaussMapPoint& planar = cosmos.gauss_map[1];
  EXPECT_LT((planar.direction - Eigen::Vector3d(0.6, 0, 0.8)).norm(), 1e-6);
  ASSERT_EQ(planar.terms.size(), 1u);
  EXPECT_EQ(planar.terms[0].patches, (std::vector<int>{1}));
  EXPECT_NEAR(planar.terms[0].area_mm2, 6.0, 1e-6);
  EXPECT_NEAR(planar.terms[0].curvedness_area, 0.0, 1e-9);
}

TEST(CosmosView, OtherShapeIndexOrOrientationGivesItsOwnTermOrPoint) {
  const CosmosView other_shape = build(hand_view(turned_from_patch0(1.0), 0.95f));
  ASSERT_EQ(other_shape.gauss_map.size(), 2u);
  ASSERT_EQ(other_shape.gauss_map[0].terms.size(), 2u);
  EXPECT_EQ(other_shape.gauss_map[0].terms[0].patches, (std::vector<int>{0}));
  EXPECT_EQ(other_shape.gauss_map[0].terms[1].patches, (std::vector<int>{2}));
  EXPECT_NEAR(other_shape.gauss_map[0].terms[1].area_mm2, 2.75, 1e-6);

  const CosmosView other_orientation = build(hand_view(turned_from_patch0(3.0), 0.902f));
  ASSERT_EQ(other_orientation.gauss_map.size(), 3u);
  EXPECT_LT((other_orientation.gauss_map[2].direction - turned_from_patch0(3.0)).norm(), 1e-6);
  EXPECT_EQ(other_orientation.gauss_map[2].terms[0].patches, (std::vector<int>{2}));
}

}  // namespace
}  // namespace cosmos
