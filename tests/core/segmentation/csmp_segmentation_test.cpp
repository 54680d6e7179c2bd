// CSMPs by constrained region growing (§3.5.2) on analytic surfaces and hand-made fields.
#include "core/segmentation/csmp_segmentation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/core/analytic_fixture.hpp"

namespace cosmos::testing {
namespace {

// A hand-made field: one row of curved pixels with the given shape indices, all adjacent.
ShapeIndexField row_field(const std::vector<float>& shape_indices) {
  const int width = static_cast<int>(shape_indices.size());
  ShapeIndexField field;
  field.label = PixelGrid<SurfaceLabel>(width, 1, SurfaceLabel::kCurved);
  field.shape_index = PixelGrid<float>(width, 1, 0.0f);
  field.curvedness_per_mm = PixelGrid<float>(width, 1, 0.1f);
  field.area_mm2 = PixelGrid<float>(width, 1, 1.0f);
  field.same_side = PixelGrid<std::uint8_t>(width, 1, 0);
  for (int i = 0; i < width; ++i) {
    field.shape_index[i] = shape_indices[i];
    if (i > 0) field.same_side[i] |= 1u << 3;          // left
    if (i + 1 < width) field.same_side[i] |= 1u << 4;  // right
  }
  return field;
}

TEST(CsmpSegmentation, MergesLeastDiameterFirstUpToTheLimit) {
  // Two plateaus (0.30-0.40 and 0.80-0.90) joined by a step: a limit of 0.25 keeps them apart.
  const auto field = row_field({0.30f, 0.32f, 0.35f, 0.40f, 0.80f, 0.85f, 0.90f, 0.88f});
  SegmentationParameters parameters;
  parameters.max_patches = 0;
  parameters.min_patch_area_fraction = 0;
  const auto segmentation = segment_csmps(DarbouxFrameField(field.width(), 1), field, parameters);
  ASSERT_EQ(segmentation.patch_count, 2);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(segmentation.patch_of_pixel[i], 0);
  for (int i = 4; i < 8; ++i) EXPECT_EQ(segmentation.patch_of_pixel[i], 1);
}

TEST(CsmpSegmentation, AdaptiveLimitCapsThePatchCount) {
  std::vector<float> ramp;
  for (int i = 0; i < 40; ++i) ramp.push_back(0.1f * (i / 4));  // ten plateaus 0.1 apart
  const auto field = row_field(ramp);
  SegmentationParameters parameters;
  parameters.shape_diameter_limit = 0.05;
  parameters.min_patch_area_fraction = 0;
  parameters.max_patches = 0;
  EXPECT_EQ(segment_csmps(DarbouxFrameField(field.width(), 1), field, parameters).patch_count, 10);
  parameters.max_patches = 3;
  const auto adaptive = segment_csmps(DarbouxFrameField(field.width(), 1), field, parameters);
  EXPECT_LE(adaptive.patch_count, 3);
  EXPECT_GT(adaptive.shape_diameter_limit, 0.05);
}

TEST(CsmpSegmentation, CapsuleGivesTwoCapsAndARidge) {
  const auto surface = analytic(AnalyticShape::kCapsule);
  const auto analysis = analyze(surface);
  auto patches = analysis.view.patches;
  ASSERT_GE(patches.size(), 3u);
  std::sort(patches.begin(), patches.end(),
            [](const Csmp& a, const Csmp& b) { return a.area_mm2 > b.area_mm2; });
  double valid_area = 0;
  for (float a : analysis.field.area_mm2.values()) valid_area += a;
  // Which analytic region does each of the three largest patches cover mostly?
  std::vector<int> region_of_patch;
  for (int k = 0; k < 3; ++k) {
    int votes[3] = {0, 0, 0};
    for (std::size_t i = 0; i < analysis.segmentation.patch_of_pixel.size(); ++i)
      if (analysis.segmentation.patch_of_pixel[i] == patches[k].id)
        ++votes[surface.truth[i].region];
    region_of_patch.push_back(static_cast<int>(std::max_element(votes, votes + 3) - votes));
  }
  std::vector<int> sorted_regions = region_of_patch;
  std::sort(sorted_regions.begin(), sorted_regions.end());
  ASSERT_EQ(sorted_regions, (std::vector<int>{0, 1, 2}));
  double covered = 0;
  for (int k = 0; k < 3; ++k) {
    const int region = region_of_patch[k];
    if (region == 1) {
      EXPECT_NEAR(patches[k].shape_index, 0.75, 0.03);
    } else {
      EXPECT_GE(patches[k].shape_index, 0.95);
    }
    const double expected_area = analytic_region_area_mm2(surface, region);
    EXPECT_NEAR(patches[k].area_mm2 / expected_area, 1.0, 0.08) << "region " << region;
    covered += patches[k].area_mm2;
  }
  EXPECT_GE(covered / valid_area, 0.90);
}

TEST(CsmpSegmentation, BoxCornerGivesThreeAdjacentPlanes) {
  const auto surface = analytic(AnalyticShape::kBoxCorner);
  const auto analysis = analyze(surface);
  const auto truth_normals = box_corner_face_normals(surface.spec);
  std::vector<const Csmp*> planar;
  for (const Csmp& patch : analysis.view.patches)
    if (patch.planar) planar.push_back(&patch);
  ASSERT_EQ(planar.size(), 3u);
  std::vector<bool> matched(3, false);
  for (const Csmp* patch : planar) {
    double best_deg = 180;
    int best = -1;
    for (int f = 0; f < 3; ++f) {
      const double deg = std::acos(std::clamp(
                             patch->mean_normal.dot(truth_normals[f].cast<double>()), -1.0, 1.0)) *
                         180.0 / std::numbers::pi;
      if (deg < best_deg) best_deg = deg, best = f;
    }
    EXPECT_LE(best_deg, 2.0);
    matched[best] = true;
    for (const Csmp* other : planar) {
      if (other == patch) continue;
      const bool adjacent =
          std::any_of(patch->neighbors.begin(), patch->neighbors.end(),
                      [&](const PatchNeighbor& n) { return n.patch == other->id; });
      EXPECT_TRUE(adjacent) << patch->id << " and " << other->id;
    }
  }
  EXPECT_EQ(std::count(matched.begin(), matched.end(), true), 3);
}

TEST(CsmpSegmentation, PatchesEmptiedByRefinementAreDroppedAndTheRestKeepTheirOrder) {
  CsmpSegmentation segmentation;
  segmentation.patch_count = 4;
  segmentation.patch_of_pixel = PixelGrid<std::int32_t>(3, 2, kNoPatch);
  // Patch 1 lost every pixel to its neighbours.
  const std::int32_t ids[] = {0, 0, 2, kNoPatch, 3, 2};
  for (std::size_t i = 0; i < 6; ++i) segmentation.patch_of_pixel[i] = ids[i];
  drop_emptied_patches(segmentation);
  EXPECT_EQ(segmentation.patch_count, 3);
  const std::int32_t expected[] = {0, 0, 1, kNoPatch, 2, 1};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(segmentation.patch_of_pixel[i], expected[i]) << i;
}

TEST(CsmpSegmentation, NoPatchIsLeftWithoutPixels) {
  for (std::int32_t count : {0, 2}) {
    CsmpSegmentation segmentation;
    segmentation.patch_count = count;
    segmentation.patch_of_pixel = PixelGrid<std::int32_t>(2, 1, count == 0 ? kNoPatch : 1);
    segmentation.patch_of_pixel[0] = count == 0 ? kNoPatch : 0;
    drop_emptied_patches(segmentation);
    EXPECT_EQ(segmentation.patch_count, count);
  }
}

}  // namespace
}  // namespace cosmos::testing
