#include "calibration/stripe_points.hpp"

#include <cmath>
#include <opencv2/calib3d.hpp>

#include "calibration/camera_calibration.hpp"

namespace cosmos {

std::vector<cv::Point2f> stripe_image_points(const cv::Mat& frame, int roi_top_px,
                                             const StripeExtractionParameters& extraction) {
  LaserStripeExtractor extractor(extraction);
  StripePeaks peaks;
  std::vector<cv::Point2f> points;
  if (extractor.extract(frame, FrameRoi{roi_top_px, 0}, peaks) != StripeExtractionStatus::kOk)
    return points;
  for (int i = 0; i < peaks.width(); ++i) {
    const float row = peaks.row_px[static_cast<std::size_t>(i)];
    if (std::isfinite(row)) points.emplace_back(static_cast<float>(peaks.sensor_column_px(i)), row);
  }
  return points;
}

std::vector<Eigen::Vector2d> normalized_points(const std::vector<cv::Point2f>& pixels,
                                               const CalibratedCamera& camera) {
  std::vector<Eigen::Vector2d> normalized;
  if (pixels.empty()) return normalized;
  std::vector<cv::Point2f> undistorted;
  cv::undistortPoints(pixels, undistorted, camera_matrix(camera), distortion_coefficients(camera),
                      cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-10));
  normalized.reserve(undistorted.size());
  for (const cv::Point2f& p : undistorted) normalized.emplace_back(p.x, p.y);
  return normalized;
}

std::vector<Eigen::Vector3d> rays_on_plane(const std::vector<Eigen::Vector2d>& normalized,
                                           const Eigen::Vector3d& normal, double offset_mm) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(normalized.size());
  for (const Eigen::Vector2d& n : normalized) {
    const Eigen::Vector3d ray(n.x(), n.y(), 1.0);
    const double denominator = normal.dot(ray);
    if (std::abs(denominator) < 1e-12) continue;
    const double s = offset_mm / denominator;
    if (s > 0.0) points.push_back(s * ray);
  }
  return points;
}

}  // namespace cosmos

namespace cosmos {

std::vector<Eigen::Vector3d> stripe_scanner_points(const cv::Mat& frame, int roi_top_px,
                                                   const TriangulationGeometry& geometry,
                                                   const StripeExtractionParameters& extraction) {
  const std::vector<Eigen::Vector2d> normalized = normalized_points(
      stripe_image_points(frame, roi_top_px, extraction), calibrated_camera_of(geometry.camera));
  std::vector<Eigen::Vector3d> points;
  points.reserve(normalized.size());
  for (const Eigen::Vector2d& n : normalized) {
    Eigen::Vector3d p;
    if (geometry.normalized_ray_to_laser_plane(n, p)) points.push_back(p);
  }
  return points;
}

}  // namespace cosmos
