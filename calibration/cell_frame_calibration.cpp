#include "calibration/cell_frame_calibration.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "calibration/rigid_fit.hpp"
#include "calibration/sphere_fit.hpp"
#include "calibration/stripe_points.hpp"

namespace cosmos {
namespace {

struct Cluster {
  Eigen::Vector2d sum_xy = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector2d centre() const { return sum_xy / static_cast<double>(points.size()); }
};

// Greedy grouping by distance across the belt's plane: the spheres stand further apart than
// their diameter.
std::vector<Cluster> group_spheres(const std::vector<Eigen::Vector3d>& points, double radius_mm) {
  std::vector<Cluster> clusters;
  for (const Eigen::Vector3d& p : points) {
    Cluster* home = nullptr;
    for (Cluster& cluster : clusters)
      if ((cluster.centre() - p.head<2>()).norm() < 1.5 * radius_mm) home = &cluster;
    if (!home) home = &clusters.emplace_back();
    home->sum_xy += p.head<2>();
    home->points.push_back(p);
  }
  return clusters;
}

}  // namespace

CellFrameResult calibrate_cell_frame(const std::vector<StripeFrame>& frames,
                                     const SpherePlate& plate,
                                     const TriangulationGeometry& geometry, double mm_per_tick,
                                     double sheet_pitch_deg,
                                     const StripeExtractionParameters& extraction,
                                     const CellFrameSettings& settings) {
  CellFrameResult result;
  char reason[240];
  // Only the caps: the sphere's flanks near the plate are seen at grazing angles.
  const double cap_floor_mm = plate.plate_height_mm + 2.0;
  const SheetPitch pitch(sheet_pitch_deg);
  for (const StripeFrame& frame : frames) {
    const double foot_y = -static_cast<double>(frame.encoder_ticks) * mm_per_tick;
    for (const Eigen::Vector3d& p :
         stripe_scanner_points(frame.image, frame.roi_top_px, geometry, extraction)) {
      const Eigen::Vector3d belt = pitch.belt_point(p.x(), foot_y, p.z());
      if (belt.z() > cap_floor_mm) result.points_belt.push_back(belt);
    }
  }
  std::vector<Cluster> clusters = group_spheres(result.points_belt, plate.radius_mm);
  std::erase_if(clusters, [&](const Cluster& c) {
    return static_cast<int>(c.points.size()) < settings.min_points_per_sphere;
  });
  const std::size_t features = plate.centres_cell_mm.size();
  if (clusters.size() != features) {
    std::snprintf(reason, sizeof reason,
                  "the scan shows %zu spheres, the target file lists %zu: the file does not match "
                  "the scan",
                  clusters.size(), features);
    result.reason = reason;
    return result;
  }
  if (features < 3) {
    result.reason = "the target file lists fewer than 3 spheres: the cell frame needs 3";
    return result;
  }
  std::vector<Eigen::Vector3d> centres;
  std::vector<double> fit_rms;
  const Eigen::Vector3d to_file_position(
      0.0, static_cast<double>(plate.encoder_ticks) * mm_per_tick, 0.0);
  for (const Cluster& cluster : clusters) {
    const SphereFit fit = fit_sphere_known_radius(cluster.points, plate.radius_mm);
    if (!fit.ok) {
      result.reason = "a sphere's points fit no sphere of the target file's radius";
      return result;
    }
    centres.push_back(fit.centre_mm + to_file_position);
    fit_rms.push_back(fit.rms_mm);
  }
  // Every pairing of fitted centres to the file's (few features: all permutations).
  std::vector<std::size_t> order(features);
  std::iota(order.begin(), order.end(), 0);
  RigidFit best;
  std::vector<std::size_t> best_order;
  double best_worst = 0.0;
  do {
    std::vector<Eigen::Vector3d> from;
    for (std::size_t i : order) from.push_back(centres[i]);
    const RigidFit fit = fit_rigid_transform(from, plate.centres_cell_mm);
    if (!fit.ok) continue;
    const double worst = *std::max_element(fit.residual_mm.begin(), fit.residual_mm.end());
    if (best_order.empty() || worst < best_worst) {
      best = fit;
      best_order = order;
      best_worst = worst;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  if (best_order.empty()) {
    result.reason = "the target file's sphere centres are collinear: they fix no frame";
    return result;
  }
  if (best_worst > settings.max_feature_residual_mm) {
    std::snprintf(reason, sizeof reason,
                  "the target file does not match the scan: its best pairing leaves a sphere "
                  "%.2f mm off (at most %.2f)",
                  best_worst, settings.max_feature_residual_mm);
    result.reason = reason;
    return result;
  }
  result.T_cell_scanner = best.T_to_from;
  for (std::size_t k = 0; k < features; ++k) {
    result.centres_scanner_mm.push_back(centres[best_order[k]]);
    result.sphere_rms_mm.push_back(fit_rms[best_order[k]]);
  }
  result.feature_residual_mm = best.residual_mm;
  result.rms_mm = best.rms_mm;
  result.ok = true;
  return result;
}

}  // namespace cosmos
