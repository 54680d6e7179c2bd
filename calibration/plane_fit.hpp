#pragma once
// A plane through 3D points, robust to outliers: RANSAC on point triples (seeded), then a
// least-squares refit (the smallest eigenvector of the inliers' scatter) and a second inlier
// pass at the refined plane. The laser-plane and belt calibrations use it on triangulated
// stripe points, where a stray reflection or a misread column must not tilt the plane.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace cosmos {

struct PlaneFitSettings {
  double inlier_distance_mm = 0.3;  // RANSAC inlier band
  int iterations = 200;
  std::uint64_t seed = 1;
};

struct PlaneFit {
  bool ok = false;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit
  double offset_mm = 0.0;                             // normal · p = offset on the plane
  double rms_mm = 0.0;                                // point-to-plane, inliers
  int inliers = 0;

  double distance_mm(const Eigen::Vector3d& p) const { return normal.dot(p) - offset_mm; }
};

// ok false with fewer than 3 points or when every triple is degenerate.
PlaneFit fit_plane_robust(const std::vector<Eigen::Vector3d>& points,
                          const PlaneFitSettings& settings = {});

// The least-squares plane of all `points` (no outlier rejection).
PlaneFit fit_plane_least_squares(const std::vector<Eigen::Vector3d>& points);

}  // namespace cosmos
