// The range points a thin scene is searched with (thin_scene.hpp range_points), on the plate
// scene: every pixel with data, evenly thinned to at most the number asked for, where the
// pixel is, facing the sensor.
#include "core/recognition/thin_scene.hpp"

#include <gtest/gtest.h>

#include "tests/core/recognition/plate_scene.hpp"

namespace cosmos {
namespace {

using testing::kPlateHeightMm;
using testing::plate_scene;

TEST(ThinScene, EveryPixelWithDataIsARangePointWhenFewEnough) {
  const RegistrationPoints points = range_points(plate_scene(), 5000);
  ASSERT_EQ(points.size(), 40 * 40);  // the plate's 20 x 20 mm of 0.5 mm pixels
  // Row-major from the plate's first pixel.
  EXPECT_DOUBLE_EQ(points.position_mm(0, 0), 10.0);
  EXPECT_DOUBLE_EQ(points.position_mm(1, 0), 10.0);
  EXPECT_DOUBLE_EQ(points.position_mm(0, 1), 10.5);
  EXPECT_DOUBLE_EQ(points.position_mm(1, 40), 10.5);
  for (int i = 0; i < points.size(); ++i) {
    EXPECT_DOUBLE_EQ(points.position_mm(2, i), kPlateHeightMm);
    EXPECT_EQ(points.normal.col(i), Eigen::Vector3d::UnitZ());
  }
}

TEST(ThinScene, ManyPixelsAreThinnedEvenlyToAtMostTheNumberAsked) {
  const RegistrationPoints points = range_points(plate_scene(), 400);
  ASSERT_EQ(points.size(), 400);  // every 4th of 1,600
  EXPECT_DOUBLE_EQ(points.position_mm(0, 1) - points.position_mm(0, 0), 2.0);
  EXPECT_LE(range_points(plate_scene(), 7).size(), 7);
  EXPECT_GE(range_points(plate_scene(), 7).size(), 6);
}

TEST(ThinScene, AnEmptySceneHasNoRangePoints) {
  RangeImage scene = plate_scene();
  for (float& z : scene.z_mm.values()) z = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(range_points(scene, 400).size(), 0);
}

}  // namespace
}  // namespace cosmos
