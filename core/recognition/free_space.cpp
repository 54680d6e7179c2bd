#include "core/recognition/free_space.hpp"

#include <cmath>

namespace cosmos {
namespace {

// Pixels beyond the image's edge still taken as its edge: a rough pose's silhouette is a
// pixel or two off.
constexpr long kEdgeTolerancePx = 2;

}  // namespace

double fraction_over_belt(const RangeImage& scene, const Eigen::Matrix3Xd& points_part_mm,
                          const RigidTransform& T_part_scene) {
  if (!scene.belt_known() || points_part_mm.cols() == 0) return 0;
  const RigidTransform T_scene_part = T_part_scene.inverse();
  const long width = scene.width(), height = scene.height();
  Eigen::Index over_belt = 0;
  for (Eigen::Index i = 0; i < points_part_mm.cols(); ++i) {
    const Eigen::Vector3d point = T_scene_part.apply(points_part_mm.col(i));
    const long column = std::lround((point.x() - scene.origin_x_mm) / scene.pixel_size_x_mm);
    const long row = std::lround((point.y() - scene.origin_y_mm) / scene.pixel_size_y_mm);
    if (column < -kEdgeTolerancePx || row < -kEdgeTolerancePx ||
        column >= width + kEdgeTolerancePx || row >= height + kEdgeTolerancePx) {
      ++over_belt;
      continue;
    }
    bool all_belt = true;
    bool any_inside = false;
    for (long r = row - 1; r <= row + 1 && all_belt; ++r)
      for (long c = column - 1; c <= column + 1 && all_belt; ++c) {
        if (c < 0 || r < 0 || c >= width || r >= height) continue;
        any_inside = true;
        all_belt = scene.belt_seen(static_cast<int>(c), static_cast<int>(r)) != 0;
      }
    over_belt += all_belt && any_inside ? 1 : 0;
  }
  return static_cast<double>(over_belt) / static_cast<double>(points_part_mm.cols());
}

}  // namespace cosmos
