#pragma once
// A ViewAnalysis built by hand for the render and JSON tests, independent of analyze_view:
// a 12 x 8 grid of 0.5 mm pixels,
//   column 0          no data (invalid, no patch)
//   columns 1-4       patch 0, S_I 0.97 (cap),    normal +z,           32 px,  8 mm^2
//   columns 5-8, 0-3  patch 1, S_I 0.50 (saddle), normal (0.6, 0, 0.8), 16 px, 4 mm^2
//   columns 5-8, 4-7  patch 2, planar,            normal (0, -0.6, 0.8), 16 px, 4 mm^2
//   columns 9-11      patch 3, S_I 0.03 (cup),    normal (-0.6, 0, 0.8), 24 px, 6 mm^2
// with adjacency 0-1, 0-2, 1-2, 1-3, 2-3, and the matching spectrum (visible area 22 mm^2).
#include <cmath>
#include <limits>

#include "core/representation/cosmos_pipeline.hpp"

namespace cosmos::testing {

inline constexpr int kHandWidth = 12;
inline constexpr int kHandHeight = 8;
inline constexpr double kHandPixelMm = 0.5;

inline int hand_patch_of(int column, int row) {
  if (column == 0) return kNoPatch;
  if (column <= 4) return 0;
  if (column <= 8) return row <= 3 ? 1 : 2;
  return 3;
}

inline RangeImage hand_made_range_image() {
  RangeImage image(kHandWidth, kHandHeight, kHandPixelMm, kHandPixelMm);
  for (int row = 0; row < kHandHeight; ++row) {
    for (int column = 1; column < kHandWidth; ++column) image.z_mm(column, row) = 100.0f + column;
  }
  return image;
}

inline Csmp hand_patch(int id, double area_mm2, double shape_index, Eigen::Vector3d normal,
                       int pixels, std::vector<int> neighbor_ids) {
  Csmp patch;
  patch.id = id;
  patch.area_mm2 = area_mm2;
  patch.mean_normal = normal;
  patch.shape_index = shape_index;
  patch.shape_index_min = shape_index - (shape_index > 1 ? 0 : 0.01);
  patch.shape_index_max = shape_index + (shape_index > 1 ? 0 : 0.01);
  patch.mean_curvedness_per_mm = shape_index > 1 ? 0 : 0.1 * (id + 1);
  patch.centroid_mm = {id * 1.0, 2.0, 100.0 + id};
  patch.pixels = pixels;
  patch.planar = shape_index > 1;
  for (int other : neighbor_ids) patch.neighbors.push_back({other, 4});
  return patch;
}

inline ViewAnalysis hand_made_view_analysis() {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  constexpr float kShapeIndexOfPatch[4] = {0.97f, 0.50f, kPlanarShapeIndex, 0.03f};
  constexpr double kPixelAreaMm2 = kHandPixelMm * kHandPixelMm;

  ViewAnalysis analysis;
  ShapeIndexField& field = analysis.field;
  field.label = PixelGrid<SurfaceLabel>(kHandWidth, kHandHeight, SurfaceLabel::kInvalid);
  field.shape_index = PixelGrid<float>(kHandWidth, kHandHeight, kNaN);
  field.curvedness_per_mm = PixelGrid<float>(kHandWidth, kHandHeight, 0.0f);
  field.area_mm2 = PixelGrid<float>(kHandWidth, kHandHeight, 0.0f);
  analysis.segmentation.patch_of_pixel = PixelGrid<std::int32_t>(kHandWidth, kHandHeight, kNoPatch);
  for (int row = 0; row < kHandHeight; ++row) {
    for (int column = 0; column < kHandWidth; ++column) {
      const int patch = hand_patch_of(column, row);
      if (patch == kNoPatch) continue;
      const float s = kShapeIndexOfPatch[patch];
      field.label(column, row) = s > 1 ? SurfaceLabel::kPlanar : SurfaceLabel::kCurved;
      field.shape_index(column, row) = s;
      field.area_mm2(column, row) = static_cast<float>(kPixelAreaMm2);
      analysis.segmentation.patch_of_pixel(column, row) = patch;
    }
  }
  analysis.segmentation.patch_count = 4;
  analysis.segmentation.shape_diameter_limit = 0.25;

  analysis.view.patches = {
      hand_patch(0, 8.0, 0.97, {0, 0, 1}, 32, {1, 2}),
      hand_patch(1, 4.0, 0.50, {0.6, 0, 0.8}, 16, {0, 2, 3}),
      hand_patch(2, 4.0, kPlanarShapeIndex, {0, -0.6, 0.8}, 16, {0, 1, 3}),
      hand_patch(3, 6.0, 0.03, {-0.6, 0, 0.8}, 24, {1, 2}),
  };
  analysis.view.visible_area_mm2 = 22.0;

  analysis.spectrum.bin_width = 0.005;
  analysis.spectrum.bins.assign(200, 0.0);
  analysis.spectrum.bins[194] = 8.0 / 22;  // S_I 0.97
  analysis.spectrum.bins[100] = 4.0 / 22;  // S_I 0.50
  analysis.spectrum.bins[6] = 6.0 / 22;    // S_I 0.03
  analysis.spectrum.planar_fraction = 4.0 / 22;
  analysis.spectrum.visible_area_mm2 = 22.0;

  analysis.moments = {0.5,     0.14, -0.01, 0.03, 0.0,
                      0.0,     0.0,  0.0,   0.0,  std::numeric_limits<double>::quiet_NaN(),
                      4.0 / 22};
  analysis.valid_pixels = 88;
  return analysis;
}

}  // namespace cosmos::testing
