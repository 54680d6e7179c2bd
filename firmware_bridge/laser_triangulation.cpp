#include "firmware_bridge/laser_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

namespace cosmos {
namespace {
constexpr float kNoPoint = std::numeric_limits<float>::quiet_NaN();
}  // namespace

LaserTriangulator::LaserTriangulator(const TriangulationGeometry& geometry, int first_row_px,
                                     int row_count)
    : geometry_(geometry), first_row_px_(first_row_px), row_count_(std::max(row_count, 1)) {
  const LaserPlane& plane = geometry_.laser_plane;
  plane_normal_camera_ = geometry_.R_scanner_camera.transpose() * plane.normal_scanner;
  plane_distance_mm_ = plane.offset_mm - plane.normal_scanner.dot(geometry_.t_scanner_camera_mm);

  const int columns = std::max(geometry_.camera.width_px, 0);
  const std::size_t size = static_cast<std::size_t>(columns) * static_cast<std::size_t>(row_count_);
  table_.resize(size);
  if (size == 0) return;
  cv::Mat image_points(static_cast<int>(size), 1, CV_64FC2);
  for (int c = 0; c < columns; ++c) {
    for (int r = 0; r < row_count_; ++r) {
      image_points.at<cv::Vec2d>(c * row_count_ + r) = {static_cast<double>(c),
                                                        static_cast<double>(first_row_px_ + r)};
    }
  }
  cv::Mat normalized_points;
  // Iterated to convergence: OpenCV's default of 5 fixed-point steps is enough for mild
  // distortion but not for a strong (wide-angle) lens, and the table is built only once.
  cv::undistortPoints(
      image_points, normalized_points, geometry_.camera.camera_matrix(),
      geometry_.camera.distortion_coefficients(), cv::noArray(), cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-10));
  for (std::size_t i = 0; i < size; ++i) {
    const auto n = normalized_points.at<cv::Vec2d>(static_cast<int>(i));
    table_[i] = {static_cast<float>(n[0]), static_cast<float>(n[1])};
  }
}

LaserTriangulator::LaserTriangulator(const TriangulationGeometry& geometry)
    : LaserTriangulator(geometry, geometry.roi_row_offset_px, geometry.roi_height_px) {}

void LaserTriangulator::reserve(int max_columns, TriangulatedStripe& stripe) const {
  const auto n = static_cast<std::size_t>(std::max(max_columns, 0));
  stripe.x_mm.reserve(n);
  stripe.z_mm.reserve(n);
}

void LaserTriangulator::triangulate(const StripePeaks& peaks,
                                    TriangulatedStripe& stripe) const noexcept {
  const auto width = static_cast<std::size_t>(peaks.width());
  stripe.x_mm.resize(width);
  stripe.z_mm.resize(width);
  const int table_columns = geometry_.camera.width_px;
  const double last_row = row_count_ - 1;
  const Eigen::Matrix3d& R_scanner_camera = geometry_.R_scanner_camera;
  const Eigen::Vector3d& t_scanner_camera_mm = geometry_.t_scanner_camera_mm;
  int valid = 0;
  for (std::size_t i = 0; i < width; ++i) {
    stripe.x_mm[i] = kNoPoint;
    stripe.z_mm[i] = kNoPoint;
    const double row = static_cast<double>(peaks.row_px[i]) - first_row_px_;
    const int column = peaks.column_offset_px + static_cast<int>(i);
    // NaN rows fail both comparisons and are skipped here too.
    if (!(row >= 0.0 && row <= last_row) || column < 0 || column >= table_columns) continue;
    // Linear in the row between two table rows: exact without distortion, and the
    // undistortion map is smooth enough that its curvature over one pixel is negligible.
    const int row0 = std::min(static_cast<int>(row), std::max(row_count_ - 2, 0));
    const double t = row - row0;
    const NormalizedRay* entry =
        &table_[static_cast<std::size_t>(column) * static_cast<std::size_t>(row_count_) +
                static_cast<std::size_t>(row0)];
    const NormalizedRay& a = entry[0];
    const NormalizedRay& b = row_count_ > 1 ? entry[1] : entry[0];
    const Eigen::Vector3d ray_camera(a.x + t * (static_cast<double>(b.x) - a.x),
                                     a.y + t * (static_cast<double>(b.y) - a.y), 1.0);
    const double denominator = plane_normal_camera_.dot(ray_camera);
    // A ray grazing the sheet, or meeting it behind the camera, has no meaningful point.
    if (!(std::abs(denominator) > 1e-12)) continue;
    const double s = plane_distance_mm_ / denominator;
    if (!(s > 0.0)) continue;
    const auto x =
        static_cast<float>(t_scanner_camera_mm.x() + s * R_scanner_camera.row(0).dot(ray_camera));
    const auto z =
        static_cast<float>(t_scanner_camera_mm.z() + s * R_scanner_camera.row(2).dot(ray_camera));
    stripe.x_mm[i] = x;
    stripe.z_mm[i] = z;
    ++valid;
  }
  stripe.valid_points = valid;
}

}  // namespace cosmos
