#include "calibration/laser_plane_calibration.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>

#include "calibration/camera_calibration.hpp"
#include "calibration/stripe_points.hpp"

namespace cosmos {
namespace {

// The points of one view that lie on the printed board: off it the line is on the belt.
std::vector<Eigen::Vector3d> points_on_board(const LaserView& view, const CalibrationBoard& board,
                                             const CalibratedCamera& camera) {
  const RigidTransform T_camera_board = board_pose(view.board_corners, board, camera);
  const Eigen::Vector3d normal = T_camera_board.rotation.col(2);
  const double offset = normal.dot(T_camera_board.translation_mm);
  const std::vector<Eigen::Vector3d> cast =
      rays_on_plane(normalized_points(view.stripe_points, camera), normal, offset);
  const RigidTransform T_board_camera = T_camera_board.inverse();
  const double margin = 0.5 * board.square_mm;
  std::vector<Eigen::Vector3d> kept;
  for (const Eigen::Vector3d& p : cast) {
    const Eigen::Vector3d b = T_board_camera.apply(p);
    if (b.x() > -board.square_mm + margin &&
        b.x() < board.inner_columns * board.square_mm - margin &&
        b.y() > -board.square_mm + margin && b.y() < board.inner_rows * board.square_mm - margin)
      kept.push_back(p);
  }
  return kept;
}

}  // namespace

LaserPlaneResult calibrate_laser_plane(const std::vector<LaserView>& views,
                                       const CalibrationBoard& board,
                                       const CalibratedCamera& camera,
                                       const LaserPlaneSettings& settings) {
  LaserPlaneResult result;
  char reason[200];
  std::vector<std::vector<Eigen::Vector3d>> per_view;
  for (std::size_t v = 0; v < views.size(); ++v) {
    std::vector<Eigen::Vector3d> points = points_on_board(views[v], board, camera);
    if (static_cast<int>(points.size()) < settings.min_points_per_view) {
      std::snprintf(reason, sizeof reason, "view %zu: %zu stripe points on the board, at least %d",
                    v, points.size(), settings.min_points_per_view);
      result.reason = reason;
      return result;
    }
    result.points_camera.insert(result.points_camera.end(), points.begin(), points.end());
    per_view.push_back(std::move(points));
  }
  if (static_cast<int>(views.size()) < settings.min_views) {
    std::snprintf(reason, sizeof reason, "too few views: %zu, at least %d at different heights",
                  views.size(), settings.min_views);
    result.reason = reason;
    return result;
  }
  const PlaneFit fit = fit_plane_robust(result.points_camera, settings.fit);
  if (!fit.ok) {
    result.reason = "no plane fits the stripe points";
    return result;
  }
  // The spread across the plane: the middle eigenvalue of the points' scatter.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : result.points_camera) centroid += p;
  centroid /= static_cast<double>(result.points_camera.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : result.points_camera)
    scatter += (p - centroid) * (p - centroid).transpose();
  const double spread_mm =
      std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvalues()(1) /
                static_cast<double>(result.points_camera.size()));
  if (spread_mm < settings.min_spread_mm) {
    std::snprintf(reason, sizeof reason,
                  "the stripe lines span only %.1f mm across the laser plane (at least %.1f): "
                  "move the board to more heights",
                  spread_mm, settings.min_spread_mm);
    result.reason = reason;
    return result;
  }
  // Orient the normal away from the camera: the camera centre (origin) on its negative side.
  const double sign = fit.offset_mm >= 0.0 ? 1.0 : -1.0;
  result.plane.calibrated = true;
  result.plane.normal_x = sign * fit.normal.x();
  result.plane.normal_y = sign * fit.normal.y();
  result.plane.normal_z = sign * fit.normal.z();
  result.plane.offset_mm = sign * fit.offset_mm;
  result.rms_mm = fit.rms_mm;
  result.inliers = fit.inliers;
  for (const std::vector<Eigen::Vector3d>& points : per_view) {
    double sum = 0.0;
    for (const Eigen::Vector3d& p : points) sum += fit.distance_mm(p) * fit.distance_mm(p);
    result.view_rms_mm.push_back(std::sqrt(sum / static_cast<double>(points.size())));
  }
  result.ok = true;
  return result;
}

}  // namespace cosmos
