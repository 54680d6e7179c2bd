#include "core/recognition/explained_surface.hpp"

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
