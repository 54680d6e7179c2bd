#include "core/recognition/explained_surface.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

std::vector<std::uint8_t> explained_pixels(const RangeImage& scene, const PartDistanceField& part,
                                           const RigidTransform& T_scene_part, double distance_mm) {
  const int width = scene.width();
  const int height = scene.height();
  std::vector<std::uint8_t> explained(static_cast<std::size_t>(width) * height, 0);
  if (part.empty()) return explained;
  const RigidTransform T_part_scene = T_scene_part.inverse();
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const float z = scene.z_mm(column, row);
      if (std::isnan(z)) continue;
      const Eigen::Vector3d point(scene.x_mm(column), scene.y_mm(row), z);
      if (part.distance_mm(T_part_scene.apply(point)) <= distance_mm)
        explained[static_cast<std::size_t>(row) * width + column] = 1;
    }
  }
  return explained;
}

std::vector<std::uint8_t> footprint_pixels(const RangeImage& scene,
                                           const std::vector<std::uint8_t>& pixels,
                                           const PartDistanceField& part,
                                           const RigidTransform& T_scene_part, double reach_mm,
                                           double distance_mm) {
  const int width = scene.width();
  const int height = scene.height();
  std::vector<std::uint8_t> under(static_cast<std::size_t>(width) * height, 0);
  if (part.empty()) return under;
  const RigidTransform T_part_scene = T_scene_part.inverse();
  const Eigen::Vector3d z_part = T_part_scene.rotation.col(2);
  // The smallest step keeps a line that grazes the surface from stalling the trace.
  const double min_step_mm = 0.25 * part.voxel_mm();
  const double top_z_mm = T_scene_part.translation_mm.z() + reach_mm;
  const double bottom_z_mm = T_scene_part.translation_mm.z() - reach_mm;
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const std::size_t at = static_cast<std::size_t>(row) * width + column;
      if (!pixels[at]) continue;
      const Eigen::Vector3d top_part =
          T_part_scene.apply(Eigen::Vector3d(scene.x_mm(column), scene.y_mm(row), top_z_mm));
      for (double depth_mm = 0; depth_mm <= top_z_mm - bottom_z_mm;) {
        const double d = part.distance_mm(top_part - depth_mm * z_part);
        if (d <= distance_mm) {
          under[at] = 1;
          break;
        }
        depth_mm += std::max(d - distance_mm, min_step_mm);
      }
    }
  }
  return under;
}

std::int64_t interior_pixels(const std::vector<std::uint8_t>& mask, int width, int height) {
  std::int64_t interior = 0;
  const auto at = [&](int column, int row) {
    return column >= 0 && row >= 0 && column < width && row < height &&
           mask[static_cast<std::size_t>(row) * width + column] != 0;
  };
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      if (!at(column, row)) continue;
      bool inside = true;
      for (int dr = -1; dr <= 1 && inside; ++dr)
        for (int dc = -1; dc <= 1 && inside; ++dc) inside = at(column + dc, row + dr);
      interior += inside ? 1 : 0;
    }
  }
  return interior;
}

}  // namespace cosmos
