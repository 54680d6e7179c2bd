#include "calibration/laser_plane_calibration.hpp"

#include <gtest/gtest.h>

#include "calibration/board_detection.hpp"
#include "calibration/stripe_points.hpp"
#include "sim/calibration_targets/calibration_target_simulator.hpp"
#include "tests/calibration/calibration_test_cell.hpp"

namespace cosmos {
namespace {

std::vector<LaserView> laser_views(CalibrationTargetSimulator& simulator,
                                   const CalibrationBoard& board, int count) {
  std::vector<LaserView> views;
  for (const LaserImagePair& pair : simulator.laser_views(board, count)) {
    const BoardDetection detection = detect_board(pair.board_image, board);
    EXPECT_TRUE(detection.found) << detection.reason;
    views.push_back({detection.corners,
                     stripe_image_points(pair.stripe_image, 0, simulator.extraction_parameters())});
  }
  return views;
}

TEST(LaserPlaneCalibration, RecoversTheTiltedPlaneFromSixBoardHeights) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), 5);
  const CalibrationBoard board;
  const CalibrationTruth truth = simulator.truth();
  const LaserPlaneResult result =
      calibrate_laser_plane(laser_views(simulator, board, 6), board, truth.camera);
  ASSERT_TRUE(result.ok) << result.reason;
  const Eigen::Vector3d measured(result.plane.normal_x, result.plane.normal_y,
                                 result.plane.normal_z);
  const Eigen::Vector3d expected(truth.laser.normal_x, truth.laser.normal_y, truth.laser.normal_z);
  EXPECT_LT(test::angle_deg(measured, expected), 0.1);
  // The offset where it matters: at the working point, where the optical axis meets the true
  // plane (at the camera centre, 700 mm away, a 0.01° turn already moves it 0.1 mm).
  const Eigen::Vector3d working_point(0.0, 0.0, truth.laser.offset_mm / truth.laser.normal_z);
  EXPECT_LT(std::abs(measured.dot(working_point) - result.plane.offset_mm), 0.1);
  EXPECT_LT(result.rms_mm, 0.1);
  EXPECT_EQ(result.view_rms_mm.size(), 6u);
  std::printf("normal error %.4f deg, offset at working point %.4f mm, rms %.4f mm\n",
              test::angle_deg(measured, expected),
              measured.dot(working_point) - result.plane.offset_mm, result.rms_mm);
  // The designed plane is a whole degree away: the measurement tells the two apart.
  const CalibratedLaserPlane designed =
      laser_plane_in_camera(scanner_triangulation_geometry(nominal));
  EXPECT_GT(test::angle_deg(measured, {designed.normal_x, designed.normal_y, designed.normal_z}),
            0.9);
}

TEST(LaserPlaneCalibration, RefusesTwoViewsAsTooFew) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), 6);
  const CalibrationBoard board;
  const LaserPlaneResult result =
      calibrate_laser_plane(laser_views(simulator, board, 2), board, simulator.truth().camera);
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.reason, "too few views: 2, at least 3 at different heights");
}

}  // namespace
}  // namespace cosmos
