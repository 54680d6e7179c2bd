// Model views: each view-sphere direction turned to face the scanner, scanned like a live part,
// and its ideal orthographic reference on the same grid.
#include "sim/model_views.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iostream>

#include "sim/procedural_meshes.hpp"

namespace cosmos {
namespace {

TEST(ModelViews, ViewsFaceTheScannerAndMatchTheIdealRender) {
  const TriangleMesh box = make_box(30.0, 20.0, 12.0);
  ScannerParameters parameters;
  ModelViewRenderer renderer(box, "box", parameters, ConditioningParameters{});
  ASSERT_EQ(renderer.view_count(), 320);
  for (const int index : {0, 57, 190, 319}) {
    SCOPED_TRACE(index);
    const ModelView view = renderer.scan_view(index);
    ASSERT_GT(view.image.width(), 0);
    // The view direction points at the scanner, and the image carries that pose.
    const Eigen::Vector3d up = view.T_scanner_part.linear() * renderer.direction(index);
    EXPECT_LT((up - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
    ASSERT_TRUE(view.image.ground_truth.has_value());
    EXPECT_EQ(view.image.ground_truth->part, "box");
    EXPECT_TRUE(view.image.ground_truth->rotation == view.T_scanner_part.linear());

    const RangeImage ideal = renderer.ideal_view(index, view.image);
    std::size_t ideal_part = 0;
    std::size_t both = 0;
    double sum_squares = 0.0;
    for (int j = 0; j < ideal.height(); ++j) {
      for (int i = 0; i < ideal.width(); ++i) {
        if (!ideal.has_data(i, j) ||
            ideal.z_mm(i, j) < ConditioningParameters{}.height_threshold_mm)
          continue;
        ++ideal_part;
        if (!view.image.has_data(i, j)) continue;
        ++both;
        const double d = view.image.z_mm(i, j) - ideal.z_mm(i, j);
        sum_squares += d * d;
      }
    }
    const double rms_mm = std::sqrt(sum_squares / static_cast<double>(both));
    const double measured = static_cast<double>(both) / static_cast<double>(ideal_part);
    std::cout << "[ box view " << index << " ] " << both << " of " << ideal_part
              << " ideal pixels measured, rms " << rms_mm << " mm\n";
    // Where both see the part they agree within the noise; the scan misses only what the
    // sensor cannot see (occlusion, grazing faces).
    EXPECT_LT(rms_mm, 1.5 * parameters.z_noise_mm);
    EXPECT_GT(measured, 0.6);
  }
}

TEST(ModelViews, ViewsRepeatByteForByte) {
  ModelViewRenderer renderer(make_icosphere(10.0, 3), "ball", ScannerParameters{},
                             ConditioningParameters{}, 1);
  ASSERT_EQ(renderer.view_count(), 80);
  const ModelView a = renderer.scan_view(3);
  const ModelView again = renderer.scan_view(3);
  ASSERT_EQ(a.image.z_mm.size(), again.image.z_mm.size());
  EXPECT_EQ(std::memcmp(a.image.z_mm.data(), again.image.z_mm.data(),
                        a.image.z_mm.size() * sizeof(float)),
            0);
}

}  // namespace
}  // namespace cosmos
