#include "scanner/triangulation_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

namespace cosmos {

cv::Matx33d CameraIntrinsics::camera_matrix() const {
  return {fx_px, 0.0, cx_px, 0.0, fy_px, cy_px, 0.0, 0.0, 1.0};
}

cv::Matx<double, 1, 5> CameraIntrinsics::distortion_coefficients() const {
  return {k1, k2, p1, p2, k3};
}

// The forward model of cv::projectPoints (radial k1, k2, k3 and tangential p1, p2), written
// out so that projecting one point needs no OpenCV call and no allocation.
Eigen::Vector2d CameraIntrinsics::distort_and_project(const Eigen::Vector2d& normalized) const {
  const double x = normalized.x();
  const double y = normalized.y();
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  const double xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x);
  const double yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y;
  return {fx_px * xd + cx_px, fy_px * yd + cy_px};
}

bool TriangulationGeometry::project_to_image(const Eigen::Vector3d& p_scanner_mm,
                                             Eigen::Vector2d& uv_px) const noexcept {
  const Eigen::Vector3d p_camera =
      R_scanner_camera.transpose() * (p_scanner_mm - t_scanner_camera_mm);
  if (!(p_camera.z() > 0.0)) return false;
  uv_px = camera.distort_and_project(p_camera.head<2>() / p_camera.z());
  return true;
}

bool TriangulationGeometry::normalized_ray_to_laser_plane(
    const Eigen::Vector2d& normalized, Eigen::Vector3d& p_scanner_mm) const noexcept {
  const Eigen::Vector3d ray_scanner =
      R_scanner_camera * Eigen::Vector3d(normalized.x(), normalized.y(), 1.0);
  const double denominator = laser_plane.normal_scanner.dot(ray_scanner);
  // A ray grazing the sheet would put the point at a huge, meaningless distance.
  if (std::abs(denominator) < 1e-12) return false;
  const double s =
      (laser_plane.offset_mm - laser_plane.normal_scanner.dot(t_scanner_camera_mm)) / denominator;
  if (!(s > 0.0)) return false;
  p_scanner_mm = t_scanner_camera_mm + s * ray_scanner;
  return true;
}

bool TriangulationGeometry::image_to_laser_plane(const Eigen::Vector2d& uv_px,
                                                 Eigen::Vector3d& p_scanner_mm) const {
  cv::Mat image_point(1, 1, CV_64FC2, cv::Scalar(uv_px.x(), uv_px.y()));
  cv::Mat normalized_point;
  // OpenCV's default is 5 fixed-point iterations, short of convergence for strong
  // distortion; iterate until the re-projection error is negligible instead.
  cv::undistortPoints(
      image_point, normalized_point, camera.camera_matrix(), camera.distortion_coefficients(),
      cv::noArray(), cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-10));
  const auto n = normalized_point.at<cv::Vec2d>(0, 0);
  return normalized_ray_to_laser_plane({n[0], n[1]}, p_scanner_mm);
}

TriangulationGeometry make_triangulation_geometry(const TriangulationDesign& design) {
  const double angle_rad = design.triangulation_angle_deg * std::numbers::pi / 180.0;
  const double sin_a = std::sin(angle_rad);
  const double cos_a = std::cos(angle_rad);

  TriangulationGeometry g;
  g.t_scanner_camera_mm = {0.0, -design.standoff_mm * sin_a / cos_a, design.standoff_mm};
  // Camera axes in the scanner frame: x_c along the belt's x (columns run across the belt),
  // z_c from the camera centre to the origin, y_c = z_c × x_c completes a right-handed frame
  // (image rows then run downwards: higher surfaces move the stripe to lower row numbers).
  const Eigen::Vector3d x_camera = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d z_camera(0.0, sin_a, -cos_a);
  const Eigen::Vector3d y_camera = z_camera.cross(x_camera);
  g.R_scanner_camera.col(0) = x_camera;
  g.R_scanner_camera.col(1) = y_camera;
  g.R_scanner_camera.col(2) = z_camera;

  // Pinhole magnification at the belt line: the field of view spans the sensor width.
  const double distance_to_belt_mm = design.standoff_mm / cos_a;
  CameraIntrinsics& k = g.camera;
  k.width_px = design.sensor_width_px;
  k.height_px = design.sensor_height_px;
  k.fx_px = design.sensor_width_px * distance_to_belt_mm / design.field_of_view_across_mm;
  k.fy_px = k.fx_px;
  k.cx_px = 0.5 * (design.sensor_width_px - 1);
  k.cy_px = 0.5 * (design.sensor_height_px - 1);

  // The optical axis meets the belt line at the principal point; place the ROI around it.
  const int roi_height = std::clamp(design.roi_height_px, 1, design.sensor_height_px);
  const auto belt_row_in_roi =
      static_cast<int>(std::lround(design.belt_row_fraction_of_roi * roi_height));
  g.roi_height_px = roi_height;
  g.roi_row_offset_px = std::clamp(static_cast<int>(std::lround(k.cy_px)) - belt_row_in_roi, 0,
                                   design.sensor_height_px - roi_height);
  return g;
}

}  // namespace cosmos
