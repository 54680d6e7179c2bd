#include "core/recognition/part_support.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cosmos {

int part_surface_distances(const RegistrationPoints& scene, const ModelBase& base,
                           std::span<const int> part_views, int matched,
                           const RigidTransform& T_model_scene,
                           const RegistrationParameters& registration,
                           const PartSupportParameters& parameters, ModelSurfaces& surfaces,
                           std::vector<double>& nearest_mm, const TaskRunner& tasks) {
  nearest_mm.clear();
  if (scene.size() == 0) return 0;
  RegistrationParameters strict = registration;
  strict.max_correspondence_distance_mm = parameters.inlier_distance_mm;
  const ModelBaseView& view = base.views[static_cast<std::size_t>(matched)];
  std::vector<double> distance_mm;
  correspondence_distances(scene, surfaces.points(matched), T_model_scene, strict, nearest_mm,
                           tasks);
  int views_used = 1;

  const RigidTransform T_part_scene = view.T_scanner_part.inverse() * T_model_scene;
  const double min_cosine = std::cos(parameters.neighbour_view_angle_deg * std::numbers::pi / 180);
  std::vector<std::pair<double, int>> neighbours;  // (-cosine, view): nearest first
  for (const int v : part_views) {
    if (v == matched) continue;
    const double cosine =
        base.views[static_cast<std::size_t>(v)].direction_part.dot(view.direction_part);
    if (cosine >= min_cosine) neighbours.emplace_back(-cosine, v);
  }
  std::sort(neighbours.begin(), neighbours.end());
  if (neighbours.size() > static_cast<std::size_t>(parameters.max_neighbour_views))
    neighbours.resize(static_cast<std::size_t>(parameters.max_neighbour_views));
  // Each further view is asked only about the points no view has explained yet: a point
  // within the inlier distance keeps the distance of the first view that explained it.
  std::vector<int> unexplained;
  for (const auto& [negative_cosine, v] : neighbours) {
    unexplained.clear();
    for (std::size_t i = 0; i < nearest_mm.size(); ++i)
      if (!(nearest_mm[i] <= parameters.inlier_distance_mm))
        unexplained.push_back(static_cast<int>(i));
    if (unexplained.empty()) break;
    const ModelBaseView& other = base.views[static_cast<std::size_t>(v)];
    correspondence_distances(select_points(scene, unexplained), surfaces.points(v),
                             other.T_scanner_part * T_part_scene, strict, distance_mm, tasks);
    for (std::size_t k = 0; k < unexplained.size(); ++k) {
      double& nearest = nearest_mm[static_cast<std::size_t>(unexplained[k])];
      nearest = std::min(nearest, distance_mm[k]);
    }
    ++views_used;
  }
  return views_used;
}

PartSupport measure_part_support(const RegistrationPoints& scene, const ModelBase& base,
                                 std::span<const int> part_views, int matched,
                                 const RigidTransform& T_model_scene,
                                 const RegistrationParameters& registration,
                                 const PartSupportParameters& parameters, ModelSurfaces& surfaces,
                                 const TaskRunner& tasks) {
  PartSupport support;
  if (scene.size() == 0) return support;
  std::vector<double> nearest_mm;
  support.views_used =
      part_surface_distances(scene, base, part_views, matched, T_model_scene, registration,
                             parameters, surfaces, nearest_mm, tasks);
  int inliers = 0;
  double sum_squares = 0;
  for (double d : nearest_mm) {
    if (!(d <= parameters.inlier_distance_mm)) continue;
    ++inliers;
    sum_squares += d * d;
  }
  support.inlier_fraction = static_cast<double>(inliers) / scene.size();
  support.rms_mm = inliers > 0 ? std::sqrt(sum_squares / inliers) : 0.0;
  return support;
}

}  // namespace cosmos
