#include "calibration/camera_calibration.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "calibration/board_detection.hpp"
#include "sim/calibration_targets/calibration_target_simulator.hpp"
#include "tests/calibration/calibration_test_cell.hpp"

namespace cosmos {
namespace {

TEST(CameraCalibration, RecoversTheTrueLensFromTwelveSimulatedBoardImages) {
  const ScannerParameters nominal = test::small_sensor_scanner();
  CalibrationTargetSimulator simulator(nominal, test::mis_mounted_cell(), 3);
  const CalibrationBoard board;
  std::vector<std::vector<cv::Point2f>> corners;
  for (const BoardImage& view : simulator.board_images(board, 12)) {
    const BoardDetection detection = detect_board(view.image, board);
    ASSERT_TRUE(detection.found) << detection.reason;
    corners.push_back(detection.corners);
  }
  const CameraCalibrationResult result =
      calibrate_camera(corners, board, {nominal.sensor_width_px, nominal.sensor_height_px});
  ASSERT_TRUE(result.ok) << result.reason;
  const CalibratedCamera truth = simulator.truth().camera;
  EXPECT_NEAR(result.camera.fx_px / truth.fx_px, 1.0, 0.005);
  EXPECT_NEAR(result.camera.fy_px / truth.fy_px, 1.0, 0.005);
  EXPECT_NEAR(result.camera.cx_px, truth.cx_px, 2.0);
  EXPECT_NEAR(result.camera.cy_px, truth.cy_px, 2.0);
  EXPECT_NEAR(result.camera.k1, truth.k1, 0.1 * std::abs(truth.k1));
  EXPECT_LT(result.rms_px, 0.3);
  ASSERT_EQ(result.view_rms_px.size(), 12u);
  std::printf("fx %.2f (%.2f) cx %.2f (%.2f) cy %.2f (%.2f) k1 %.4f (%.4f) k2 %.4f rms %.3f\n",
              result.camera.fx_px, truth.fx_px, result.camera.cx_px, truth.cx_px,
              result.camera.cy_px, truth.cy_px, result.camera.k1, truth.k1, result.camera.k2,
              result.rms_px);
}

TEST(CameraCalibration, RefusesTooFewViewsWithTheCount) {
  const CalibrationBoard board;
  const std::vector<std::vector<cv::Point2f>> corners(4, std::vector<cv::Point2f>(54));
  const CameraCalibrationResult result = calibrate_camera(corners, board, {1280, 1024});
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.reason, "too few views: 4 boards found, at least 10 needed");
}

TEST(BoardDetection, SaysWhyAnImageWithoutTheBoardHasNone) {
  const cv::Mat belt(256, 320, CV_8UC1, cv::Scalar(77));
  const BoardDetection detection = detect_board(belt, CalibrationBoard{});
  EXPECT_FALSE(detection.found);
  EXPECT_EQ(detection.reason, "no 9x6 chessboard found");
}

}  // namespace
}  // namespace cosmos
