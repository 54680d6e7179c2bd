#pragma once
// The camera's intrinsics and distortion from chessboard corners in several views (Zhang's
// method as OpenCV's calibrateCamera implements it), with each view's board pose and RMS
// reprojection error. The scanner's lens is long (a narrow field of view), so k3 and the
// tangential terms are held at zero: the corners of a few views cannot separate them from
// k1, k2 and the focal length.
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "calibration/calibration_board.hpp"
#include "core/rigid_transform.hpp"
#include "scanner/scanner_calibration.hpp"

namespace cosmos {

struct CameraCalibrationSettings {
  int min_views = 10;
  bool fix_k2 = true;
};

struct CameraCalibrationResult {
  bool ok = false;
  std::string reason;  // when not ok: one line
  CalibratedCamera camera;
  std::vector<RigidTransform> T_camera_board;  // per view
  std::vector<double> view_rms_px;
  double rms_px = 0.0;
};

CameraCalibrationResult calibrate_camera(const std::vector<std::vector<cv::Point2f>>& view_corners,
                                         const CalibrationBoard& board, cv::Size image_size,
                                         const CameraCalibrationSettings& settings = {});

// The camera model of a calibrated (or designed) camera as OpenCV matrices.
cv::Matx33d camera_matrix(const CalibratedCamera& camera);
cv::Mat distortion_coefficients(const CalibratedCamera& camera);
CalibratedCamera calibrated_camera_of(const CameraIntrinsics& intrinsics);

// The board's pose from its corners (solvePnP, iterative), and the RMS reprojection error.
RigidTransform board_pose(const std::vector<cv::Point2f>& corners, const CalibrationBoard& board,
                          const CalibratedCamera& camera, double* rms_px = nullptr);

}  // namespace cosmos
