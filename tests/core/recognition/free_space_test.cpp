// The free-space constraint (free_space.hpp) on a hand-made scene (plate_scene.hpp) whose
// pixels off the plate measured the belt, and part points laid out on a 1 mm grid.
#include "core/recognition/free_space.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tests/core/recognition/plate_scene.hpp"

namespace cosmos {
namespace {

using testing::kPlateHeightMm;

RangeImage plate_scene(double shadow_from_mm = 1e9) {
  return testing::plate_scene_on_belt(shadow_from_mm);
}

// Points every 1 mm over [x0, x0 + 20) x [12, 28) at the plate's height.
Eigen::Matrix3Xd grid_points(double x0_mm) {
  std::vector<Eigen::Vector3d> positions;
  for (double y = 12; y < 28; y += 1)
    for (double x = x0_mm; x < x0_mm + 20; x += 1) positions.emplace_back(x, y, kPlateHeightMm);
  Eigen::Matrix3Xd points(3, static_cast<Eigen::Index>(positions.size()));
  for (std::size_t i = 0; i < positions.size(); ++i)
    points.col(static_cast<Eigen::Index>(i)) = positions[i];
  return points;
}

RigidTransform shifted_x(double x_mm) {
  RigidTransform T;
  T.translation_mm.x() = x_mm;
  return T;
}

TEST(FreeSpace, APartOnItsOwnSilhouetteLiesOverNoBelt) {
  EXPECT_DOUBLE_EQ(fraction_over_belt(plate_scene(), grid_points(10), RigidTransform::identity()),
                   0.0);
  // The same points in a part frame 10 mm off: T_part_scene places them back on the plate.
  EXPECT_DOUBLE_EQ(fraction_over_belt(plate_scene(), grid_points(0), shifted_x(-10)), 0.0);
}

TEST(FreeSpace, APartReachingOutLiesOverTheBeltItReaches) {
  // Shifted 10 mm: x in [20, 40). Columns x = 20..30 have plate within a pixel (x = 29.5 mm
  // beside x = 30); x = 31..39, 9 of 20 columns, lie over measured belt.
  EXPECT_NEAR(fraction_over_belt(plate_scene(), grid_points(20), RigidTransform::identity()),
              9.0 / 20, 1e-12);
}

TEST(FreeSpace, AWiderMarginForgivesAPoseThatFarOff) {
  // With 3 pixels (1.5 mm) of margin x = 31 has plate within reach (x = 29.5 mm): only
  // x = 32..39, 8 of 20 columns, lie over the belt.
  EXPECT_NEAR(fraction_over_belt(plate_scene(), grid_points(20), RigidTransform::identity(), 3),
              8.0 / 20, 1e-12);
}

TEST(FreeSpace, OverAShadowNothingIsKnown) {
  // Belt measured only for x < 34 mm: of x = 31..39 only 31..33 lie over it (the neighbourhood
  // of x = 34 reaches the shadow at 34 mm).
  EXPECT_NEAR(fraction_over_belt(plate_scene(34), grid_points(20), RigidTransform::identity()),
              3.0 / 20, 1e-12);
}

TEST(FreeSpace, BeyondTheImageItsBorderTells) {
  // x in [35, 55): x = 35..39 lie over measured belt, x = 40.. beyond the image, whose border
  // there measured the belt: all of it over the belt.
  EXPECT_DOUBLE_EQ(fraction_over_belt(plate_scene(), grid_points(35), RigidTransform::identity()),
                   1.0);
  // With the border column a shadow (x >= 39.5 mm), nothing beyond it counts: x = 35..38 only
  // (the neighbourhood of x = 39 reaches the shadow at 39.5 mm).
  EXPECT_NEAR(fraction_over_belt(plate_scene(39.5), grid_points(35), RigidTransform::identity()),
              4.0 / 20, 1e-12);
}

TEST(FreeSpace, BeyondTheImageTheBeltWhenAsked) {
  // The border column a shadow, as above, but beyond the image counted as belt: x = 35..38
  // and x = 41..54 (x = 40 has the shadow at 39.5 mm within its pixel's reach), 18 of 20.
  EXPECT_NEAR(fraction_over_belt(plate_scene(39.5), grid_points(35), RigidTransform::identity(), 1,
                                 BeyondTheImage::kBelt),
              18.0 / 20, 1e-12);
}

TEST(FreeSpace, WithoutABeltMaskNothingCounts) {
  RangeImage scene = plate_scene();
  scene.belt_seen = PixelGrid<std::uint8_t>();
  EXPECT_DOUBLE_EQ(fraction_over_belt(scene, grid_points(35), RigidTransform::identity()), 0.0);
}

}  // namespace
}  // namespace cosmos
