#include "calibration/camera_calibration.hpp"

#include <cmath>
#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

namespace cosmos {
namespace {

RigidTransform transform_of(const cv::Mat& rvec, const cv::Mat& tvec) {
  cv::Mat rotation;
  cv::Rodrigues(rvec, rotation);
  RigidTransform T;
  cv::cv2eigen(rotation, T.rotation);
  cv::Mat translation;
  tvec.convertTo(translation, CV_64F);
  T.translation_mm = Eigen::Vector3d(translation.at<double>(0), translation.at<double>(1),
                                     translation.at<double>(2));
  return T;
}

double reprojection_rms(const std::vector<cv::Point3f>& object,
                        const std::vector<cv::Point2f>& seen, const cv::Mat& rvec,
                        const cv::Mat& tvec, const cv::Matx33d& k, const cv::Mat& distortion) {
  std::vector<cv::Point2f> projected;
  cv::projectPoints(object, rvec, tvec, k, distortion, projected);
  double sum = 0.0;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const cv::Point2f d = projected[i] - seen[i];
    sum += d.dot(d);
  }
  return std::sqrt(sum / static_cast<double>(seen.size()));
}

}  // namespace

cv::Matx33d camera_matrix(const CalibratedCamera& c) {
  return {c.fx_px, 0.0, c.cx_px, 0.0, c.fy_px, c.cy_px, 0.0, 0.0, 1.0};
}

cv::Mat distortion_coefficients(const CalibratedCamera& c) {
  return (cv::Mat_<double>(1, 5) << c.k1, c.k2, c.p1, c.p2, c.k3);
}

CalibratedCamera calibrated_camera_of(const CameraIntrinsics& k) {
  CalibratedCamera camera;
  camera.calibrated = true;
  camera.fx_px = k.fx_px;
  camera.fy_px = k.fy_px;
  camera.cx_px = k.cx_px;
  camera.cy_px = k.cy_px;
  camera.k1 = k.k1;
  camera.k2 = k.k2;
  camera.p1 = k.p1;
  camera.p2 = k.p2;
  camera.k3 = k.k3;
  return camera;
}

CameraCalibrationResult calibrate_camera(const std::vector<std::vector<cv::Point2f>>& view_corners,
                                         const CalibrationBoard& board, cv::Size image_size,
                                         const CameraCalibrationSettings& settings) {
  CameraCalibrationResult result;
  if (static_cast<int>(view_corners.size()) < settings.min_views) {
    char reason[160];
    std::snprintf(reason, sizeof reason, "too few views: %zu boards found, at least %d needed",
                  view_corners.size(), settings.min_views);
    result.reason = reason;
    return result;
  }
  const std::vector<cv::Point3f> object = board.object_points();
  const std::vector<std::vector<cv::Point3f>> objects(view_corners.size(), object);
  cv::Mat k = cv::Mat::eye(3, 3, CV_64F);
  cv::Mat distortion = cv::Mat::zeros(1, 5, CV_64F);
  std::vector<cv::Mat> rvecs;
  std::vector<cv::Mat> tvecs;
  int flags = cv::CALIB_FIX_K3 | cv::CALIB_ZERO_TANGENT_DIST;
  if (settings.fix_k2) flags |= cv::CALIB_FIX_K2;
  result.rms_px = cv::calibrateCamera(
      objects, view_corners, image_size, k, distortion, rvecs, tvecs, flags,
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
  CalibratedCamera& camera = result.camera;
  camera.calibrated = true;
  camera.fx_px = k.at<double>(0, 0);
  camera.fy_px = k.at<double>(1, 1);
  camera.cx_px = k.at<double>(0, 2);
  camera.cy_px = k.at<double>(1, 2);
  camera.k1 = distortion.at<double>(0);
  camera.k2 = distortion.at<double>(1);
  camera.p1 = distortion.at<double>(2);
  camera.p2 = distortion.at<double>(3);
  camera.k3 = distortion.at<double>(4);
  const cv::Matx33d kx = camera_matrix(camera);
  for (std::size_t v = 0; v < view_corners.size(); ++v) {
    result.T_camera_board.push_back(transform_of(rvecs[v], tvecs[v]));
    result.view_rms_px.push_back(
        reprojection_rms(object, view_corners[v], rvecs[v], tvecs[v], kx, distortion));
  }
  result.ok = std::isfinite(result.rms_px);
  if (!result.ok) result.reason = "calibrateCamera did not converge";
  return result;
}

RigidTransform board_pose(const std::vector<cv::Point2f>& corners, const CalibrationBoard& board,
                          const CalibratedCamera& camera, double* rms_px) {
  const std::vector<cv::Point3f> object = board.object_points();
  cv::Mat rvec;
  cv::Mat tvec;
  const cv::Matx33d k = camera_matrix(camera);
  const cv::Mat distortion = distortion_coefficients(camera);
  cv::solvePnP(object, corners, k, distortion, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE);
  if (rms_px) *rms_px = reprojection_rms(object, corners, rvec, tvec, k, distortion);
  return transform_of(rvec, tvec);
}

}  // namespace cosmos
