#pragma once
// The laser plane in the camera frame from views of the board with the laser line across it:
// each view's board pose from its corners (camera_calibration.hpp board_pose), the stripe's
// sub-pixel points cast onto the board's plane, and one robust plane (RANSAC, then least
// squares) through the points of every view. The views must put the line at different
// heights or tilts (at least 3): one line alone leaves the plane free to turn about it.
#include <Eigen/Core>
#include <opencv2/core/types.hpp>
#include <string>
#include <vector>

#include "calibration/calibration_board.hpp"
#include "calibration/plane_fit.hpp"
#include "scanner/scanner_calibration.hpp"

namespace cosmos {

struct LaserView {
  std::vector<cv::Point2f> board_corners;  // from the board image (laser off)
  std::vector<cv::Point2f> stripe_points;  // from the stripe image (board pose unchanged)
};

struct LaserPlaneSettings {
  int min_views = 3;
  int min_points_per_view = 50;
  PlaneFitSettings fit{.inlier_distance_mm = 0.3, .iterations = 300, .seed = 1};
  // The lines must span the plane: the smallest spread of the points across it, mm.
  double min_spread_mm = 10.0;
};

struct LaserPlaneResult {
  bool ok = false;
  std::string reason;
  CalibratedLaserPlane plane;
  double rms_mm = 0.0;
  std::vector<double> view_rms_mm;             // each view's points against the plane
  std::vector<Eigen::Vector3d> points_camera;  // every view's points, for the report
  int inliers = 0;
};

LaserPlaneResult calibrate_laser_plane(const std::vector<LaserView>& views,
                                       const CalibrationBoard& board,
                                       const CalibratedCamera& camera,
                                       const LaserPlaneSettings& settings = {});

}  // namespace cosmos
