#include "core/recognition/free_space.hpp"

#include <algorithm>
#include <cmath>

namespace cosmos {

double fraction_over_belt(const RangeImage& scene, const Eigen::Matrix3Xd& points_part_mm,
                          const RigidTransform& T_part_scene, int margin_px,
                          BeyondTheImage beyond) {
  if (!scene.belt_known() || points_part_mm.cols() == 0) return 0;
  const RigidTransform T_scene_part = T_part_scene.inverse();
  const long width = scene.width(), height = scene.height();
  const auto belt_at = [&](long column, long row) {
    if (column < 0 || row < 0 || column >= width || row >= height) return true;
    return scene.belt_seen(static_cast<int>(column), static_cast<int>(row)) != 0;
  };
  Eigen::Index over_belt = 0;
  for (Eigen::Index i = 0; i < points_part_mm.cols(); ++i) {
    const Eigen::Vector3d point = T_scene_part.apply(points_part_mm.col(i));
    long column = scene.column_at(point.x());
    long row = scene.row_at(point.y());
    if (beyond == BeyondTheImage::kBorderPixel) {
      column = std::clamp(column, 0L, width - 1);
      row = std::clamp(row, 0L, height - 1);
    }
    bool all_belt = true;
    for (long r = row - margin_px; r <= row + margin_px && all_belt; ++r)
      for (long c = column - margin_px; c <= column + margin_px && all_belt; ++c)
        all_belt = belt_at(c, r);
    over_belt += all_belt ? 1 : 0;
  }
  return static_cast<double>(over_belt) / static_cast<double>(points_part_mm.cols());
}

}  // namespace cosmos
