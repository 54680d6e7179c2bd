#include "core/recognition/free_space.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

double fraction_over_belt(const RangeImage& scene, const Eigen::Matrix3Xd& points_part_mm,
                          const RigidTransform& T_part_scene) {
  if (!scene.belt_known() || points_part_mm.cols() == 0) return 0;
  const RigidTransform T_scene_part = T_part_scene.inverse();
  const long width = scene.width(), height = scene.height();
  Eigen::Index over_belt = 0;
  for (Eigen::Index i = 0; i < points_part_mm.cols(); ++i) {
    const Eigen::Vector3d point = T_scene_part.apply(points_part_mm.col(i));
    // Beyond the image, what its nearest border pixel saw.
    const long column = std::clamp(scene.column_at(point.x()), 0L, width - 1);
    const long row = std::clamp(scene.row_at(point.y()), 0L, height - 1);
    bool all_belt = true;
    for (long r = std::max(0L, row - 1); r <= std::min(height - 1, row + 1) && all_belt; ++r)
      for (long c = std::max(0L, column - 1); c <= std::min(width - 1, column + 1) && all_belt; ++c)
        all_belt = scene.belt_seen(static_cast<int>(c), static_cast<int>(r)) != 0;
    over_belt += all_belt ? 1 : 0;
  }
  return static_cast<double>(over_belt) / static_cast<double>(points_part_mm.cols());
}

}  // namespace cosmos
