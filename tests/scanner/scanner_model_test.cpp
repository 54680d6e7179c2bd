// What the scanner's keys make of its geometry for the recognizer: where it measures from.
#include "scanner/scanner_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace cosmos {
namespace {

TEST(ScannerSight, TheCameraSitsUpstreamAtTheTriangulationAngleAndTheFanAboveTheBelt) {
  ScannerParameters scanner;
  scanner.triangulation_angle_deg = 30;
  scanner.camera_height_mm = 600;
  scanner.laser_height_mm = 500;
  const ScannerSight sight = scanner_sight(scanner);
  EXPECT_NEAR(sight.camera_mm.x(), 0, 1e-6);
  EXPECT_NEAR(sight.camera_mm.y(), -600 * std::tan(30 * std::numbers::pi / 180), 1e-6);
  EXPECT_NEAR(sight.camera_mm.z(), 600, 1e-6);
  EXPECT_DOUBLE_EQ(sight.laser_height_mm, 500);
  scanner.laser_model = LaserModel::kParallel;
  EXPECT_DOUBLE_EQ(scanner_sight(scanner).laser_height_mm, 0);
}

// A slope facing downstream steeper than the camera's angle is out of its sight; the same slope
// facing upstream, or one the fan lights from above, is measured.
TEST(ScannerSight, ASurfaceIsMeasurableOnlyFacingBothTheCameraAndTheLaser) {
  const ScannerSight sight = scanner_sight(ScannerParameters{});
  const auto facing = [](double deg_downstream) {
    const double a = deg_downstream * std::numbers::pi / 180;
    return Eigen::Vector3d(0, std::sin(a), std::cos(a));
  };
  const Eigen::Vector3d on_belt(0, 0, 10);
  EXPECT_TRUE(sight.measurable(on_belt, facing(0)));
  EXPECT_TRUE(sight.measurable(on_belt, facing(55)));
  EXPECT_FALSE(sight.measurable(on_belt, facing(65)));
  EXPECT_TRUE(sight.measurable(on_belt, facing(-80)));
  EXPECT_FALSE(sight.measurable(on_belt, Eigen::Vector3d(0, 0, -1)));
  // Beside the belt centre the fan comes in sideways: a wall facing the centre line is lit, one
  // facing outwards is not.
  const Eigen::Vector3d aside(100, 0, 10);
  EXPECT_TRUE(sight.measurable(aside, Eigen::Vector3d(-1, 0, 0.05).normalized()));
  EXPECT_FALSE(sight.measurable(aside, Eigen::Vector3d(1, 0, 0.05).normalized()));
}

}  // namespace
}  // namespace cosmos
