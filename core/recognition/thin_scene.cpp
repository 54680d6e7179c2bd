#include "core/recognition/thin_scene.hpp"

#include <algorithm>

namespace cosmos {

RegistrationPoints range_points(const RangeImage& scene, int max_points) {
  const std::size_t count = scene.count_valid();
  const std::size_t step =
      std::max<std::size_t>(1, (count + static_cast<std::size_t>(max_points) - 1) /
                                   static_cast<std::size_t>(std::max(max_points, 1)));
  const auto kept = static_cast<Eigen::Index>((count + step - 1) / step);
  RegistrationPoints points;
  points.position_mm.resize(3, kept);
  points.normal.resize(3, kept);
  points.surface = decltype(points.surface)::Zero(kSurfaceCoefficients, kept);
  points.residual_rms_mm = Eigen::VectorXd::Zero(kept);
  std::size_t seen = 0;
  Eigen::Index k = 0;
  for (int row = 0; row < scene.height(); ++row)
    for (int column = 0; column < scene.width(); ++column) {
      if (!scene.has_data(column, row)) continue;
      if (seen++ % step != 0) continue;
      points.position_mm.col(k) = scene.point_mm(column, row);
      points.normal.col(k) = Eigen::Vector3d::UnitZ();
      ++k;
    }
  return points;
}

}  // namespace cosmos
