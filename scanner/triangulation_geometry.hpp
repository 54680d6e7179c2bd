#pragma once
// The geometry of a laser-line triangulation sensor: a pinhole camera with OpenCV lens
// distortion, its pose in the scanner frame, and the laser sheet as a plane in the scanner
// frame. From it, an image point on the stripe maps to one 3D point (ray ∩ laser plane),
// and a 3D point maps to the image point where the camera sees it.
//
// Scanner frame (shared with core/profile.hpp): x across the belt, y along the belt
// (direction of travel), z up, millimetres. The designed geometry puts the origin on the
// belt surface, in the laser sheet, at the middle of the belt.
//
// Image coordinates follow OpenCV: u = sensor column, v = sensor row (full-sensor pixels,
// not ROI pixels), pixel centres at integer coordinates.
#include <Eigen/Core>
#include <opencv2/core/matx.hpp>

namespace cosmos {

// OpenCV camera model: K = [fx 0 cx; 0 fy cy; 0 0 1] and distortion (k1, k2, p1, p2, k3).
struct CameraIntrinsics {
  double fx_px = 1000.0;
  double fy_px = 1000.0;
  double cx_px = 639.5;
  double cy_px = 511.5;
  double k1 = 0.0;
  double k2 = 0.0;
  double p1 = 0.0;
  double p2 = 0.0;
  double k3 = 0.0;
  int width_px = 1280;
  int height_px = 1024;

  bool has_distortion() const {
    return k1 != 0.0 || k2 != 0.0 || p1 != 0.0 || p2 != 0.0 || k3 != 0.0;
  }
  cv::Matx33d camera_matrix() const;
  cv::Matx<double, 1, 5> distortion_coefficients() const;
  // Normalized (undistorted) camera coordinates (x/z, y/z) → distorted pixel (u, v).
  Eigen::Vector2d distort_and_project(const Eigen::Vector2d& normalized) const;
};

// The laser sheet: points p (scanner frame, mm) with normal_scanner · p = offset_mm.
// The default is the vertical plane y = 0 across the belt.
struct LaserPlane {
  Eigen::Vector3d normal_scanner = Eigen::Vector3d::UnitY();
  double offset_mm = 0.0;
};

struct TriangulationGeometry {
  CameraIntrinsics camera;
  // p_scanner = R_scanner_camera * p_camera + t_scanner_camera_mm (t = camera centre).
  Eigen::Matrix3d R_scanner_camera = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t_scanner_camera_mm = Eigen::Vector3d::Zero();
  LaserPlane laser_plane;
  // The rows the camera delivers (region of interest), in sensor rows.
  int roi_row_offset_px = 0;
  int roi_height_px = 1024;

  // Where the camera sees scanner-frame point p (with lens distortion). False when p is not
  // in front of the camera. Does not check that (u, v) lies on the sensor.
  bool project_to_image(const Eigen::Vector3d& p_scanner_mm, Eigen::Vector2d& uv_px) const noexcept;

  // The laser-plane point seen along the ray of undistorted normalized coordinates
  // (x/z, y/z). False when the ray is parallel to the plane or meets it behind the camera.
  bool normalized_ray_to_laser_plane(const Eigen::Vector2d& normalized,
                                     Eigen::Vector3d& p_scanner_mm) const noexcept;

  // Image point → laser-plane point, undistorting with cv::undistortPoints (iterated to
  // convergence). Allocates inside OpenCV: for set-up and tests, not per frame (the per-frame
  // path is LaserTriangulator's lookup table).
  bool image_to_laser_plane(const Eigen::Vector2d& uv_px, Eigen::Vector3d& p_scanner_mm) const;
};

// The few numbers a sensor designer chooses; make_triangulation_geometry() derives a
// consistent camera from them so tests and the simulator need no calibration file.
struct TriangulationDesign {
  // Angle between the laser sheet (vertical) and the camera's optical axis, in the y–z
  // plane: larger gives more height resolution and more occlusion.
  double triangulation_angle_deg = 30.0;
  // Height of the camera centre above the belt.
  double standoff_mm = 300.0;
  // Width of belt (at belt height, on the laser line) imaged across the sensor width.
  double field_of_view_across_mm = 256.0;
  int sensor_width_px = 1280;
  int sensor_height_px = 1024;
  int roi_height_px = 256;
  // Where the belt's laser line falls inside the ROI, as a fraction of its height from the
  // top: heights above the belt move the stripe up the image, so 0.75 leaves three quarters
  // of the rows for the part and a quarter for below-belt margin.
  double belt_row_fraction_of_roi = 0.75;
};

// Camera upstream (−y) of the laser sheet, above the belt, optical axis through the scanner
// origin tilted by the triangulation angle from the vertical; sensor columns along +x, square
// pixels, principal point at the sensor centre, no distortion.
TriangulationGeometry make_triangulation_geometry(const TriangulationDesign& design = {});

}  // namespace cosmos
