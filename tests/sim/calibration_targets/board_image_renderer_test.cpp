#include "sim/calibration_targets/board_image_renderer.hpp"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>

#include "calibration/board_detection.hpp"
#include "scanner/simulated_mounting.hpp"

namespace cosmos {
namespace {

ScannerParameters small_sensor() {
  ScannerParameters scanner;
  scanner.sensor_width_px = 640;
  scanner.sensor_height_px = 512;
  scanner.roi_height_px = 256;
  return scanner;
}

TEST(BoardImageRenderer, CornersAreDetectedWhereTheTrueLensProjectsThem) {
  SimulatedMounting truth;
  truth.k1 = -0.2;
  truth.principal_shift_u_px = 5.0;
  const TriangulationGeometry geometry = true_triangulation_geometry(small_sensor(), truth);
  const BoardImageRenderer renderer(geometry, CameraFrameParameters{});
  const CalibrationBoard board;
  // Square to the camera, 700 mm in front of it, turned 20° about its columns.
  RigidTransform T_camera_board;
  T_camera_board.rotation = rotation_from_xyz_angles_deg(20.0, 0.0, 3.0);
  T_camera_board.translation_mm = Eigen::Vector3d(-60.0, -40.0, 700.0);
  const cv::Mat image = renderer.render(board, T_camera_board, 17);
  const BoardDetection detection = detect_board(image, board);
  ASSERT_TRUE(detection.found) << detection.reason;
  // The board has a half-turn symmetry: the detector may list the corners from either end.
  const std::vector<cv::Point3f> corners = board.object_points();
  double worst_px[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector3d p =
        T_camera_board.apply(Eigen::Vector3d(corners[i].x, corners[i].y, corners[i].z));
    const Eigen::Vector2d uv = geometry.camera.distort_and_project(p.head<2>() / p.z());
    for (int order = 0; order < 2; ++order) {
      const cv::Point2f& seen = detection.corners[order ? corners.size() - 1 - i : i];
      worst_px[order] = std::max(worst_px[order], (uv - Eigen::Vector2d(seen.x, seen.y)).norm());
    }
  }
  EXPECT_LT(std::min(worst_px[0], worst_px[1]), 0.4);
  EXPECT_LT(detection.edge_width_px, 3.0);
}

TEST(BoardImageRenderer, TheSameSeedDrawsTheSameImage) {
  const TriangulationGeometry geometry = true_triangulation_geometry(small_sensor(), {});
  const BoardImageRenderer renderer(geometry, CameraFrameParameters{});
  RigidTransform T_camera_board;
  T_camera_board.translation_mm = Eigen::Vector3d(-60.0, -40.0, 700.0);
  const cv::Mat a = renderer.render(CalibrationBoard{}, T_camera_board, 5);
  const cv::Mat b = renderer.render(CalibrationBoard{}, T_camera_board, 5);
  const cv::Mat c = renderer.render(CalibrationBoard{}, T_camera_board, 6);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_L1), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_L1), 0.0);
}

}  // namespace
}  // namespace cosmos
