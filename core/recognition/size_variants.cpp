#include "core/recognition/size_variants.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

bool same_shape_scaled(const ModelPart& a, const ModelPart& b, double corner_tolerance) {
  if (a.hull_vertices_mm.empty() || a.hull_vertices_mm.size() != b.hull_vertices_mm.size() ||
      !(a.diameter_mm > 0) || !(b.diameter_mm > 0))
    return false;
  const double scale = b.diameter_mm / a.diameter_mm;
  const double tolerance_mm = corner_tolerance * std::max(a.diameter_mm, b.diameter_mm);
  const double tolerance2 = tolerance_mm * tolerance_mm;
  for (const Eigen::Vector3d& corner : a.hull_vertices_mm) {
    const Eigen::Vector3d scaled = scale * corner;
    bool found = false;
    for (const Eigen::Vector3d& other : b.hull_vertices_mm)
      if ((other - scaled).squaredNorm() <= tolerance2) {
        found = true;
        break;
      }
    if (!found) return false;
  }
  return true;
}

std::vector<std::vector<int>> find_size_variants(const ModelBase& base,
                                                 const SizeVariantParameters& parameters) {
  const std::size_t count = base.parts.size();
  std::vector<std::vector<int>> variants(count);
  for (std::size_t a = 0; a < count; ++a)
    for (std::size_t b = a + 1; b < count; ++b)
      if (std::abs(base.parts[a].diameter_mm - base.parts[b].diameter_mm) >=
              parameters.min_diameter_difference_mm &&
          (base.parts[a].mesh == base.parts[b].mesh ||
           same_shape_scaled(base.parts[a], base.parts[b], parameters.corner_tolerance))) {
        variants[a].push_back(static_cast<int>(b));
        variants[b].push_back(static_cast<int>(a));
      }
  for (std::vector<int>& family : variants) std::sort(family.begin(), family.end());
  return variants;
}

std::vector<RigidTransform> scaled_size_starts(std::span<const RigidTransform> T_part_scene,
                                               double scale,
                                               const Eigen::Vector3d& scene_centroid_mm) {
  std::vector<RigidTransform> starts;
  starts.reserve(2 * T_part_scene.size());
  for (const RigidTransform& pose : T_part_scene) {
    const Eigen::Vector3d centroid_in_part = pose.apply(scene_centroid_mm);
    RigidTransform scaled = pose;
    scaled.translation_mm += (scale - 1.0) * centroid_in_part;
    starts.push_back(scaled);
    starts.push_back(pose);
  }
  return starts;
}

}  // namespace cosmos
