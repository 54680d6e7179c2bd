#include "core/registration/part_surface_voxels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/registration/occupied_cell_runs.hpp"

namespace cosmos {

PartSurfaceVoxels part_surface_voxels(const std::vector<Eigen::Vector3d>& points_part_mm,
                                      const PartDistanceFieldParameters& parameters) {
  PartSurfaceVoxels voxels;
  if (!(parameters.voxel_mm > 0) || !std::isfinite(parameters.margin_mm) ||
      parameters.margin_mm < 0)
    return voxels;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  std::size_t finite_points = 0;
  for (const Eigen::Vector3d& p : points_part_mm) {
    if (!p.allFinite()) continue;
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
    ++finite_points;
  }
  if (finite_points == 0) return voxels;
  const Eigen::Vector3d extent_mm =
      (high - low).array() + 2 * parameters.margin_mm;  // may overflow to infinity
  if (!extent_mm.allFinite()) return voxels;
  // The grid is bounded whatever the points: a part far larger than any real one gets
  // coarser voxels, never an unbounded allocation (the voxel count is computed in double
  // so that it cannot overflow).
  double voxel_mm = parameters.voxel_mm;
  const auto voxel_count = [&](double voxel) {
    double count = 1;
    for (int axis = 0; axis < 3; ++axis)
      count *= std::max(2.0, 1 + std::ceil(extent_mm[axis] / voxel));
    return count;
  };
  const double limit = static_cast<double>(kMaxSurfaceVoxels);
  if (voxel_count(voxel_mm) > limit)
    voxel_mm *= std::cbrt(voxel_count(voxel_mm) / limit);  // about right, then a few steps
  while (voxel_count(voxel_mm) > limit) voxel_mm *= 1.25;
  voxels.voxel_mm = voxel_mm;
  voxels.origin_mm = low - Eigen::Vector3d::Constant(parameters.margin_mm);
  // At least 2 voxels per axis: the field's interpolation reads each base voxel's +1
  // neighbours.
  for (int axis = 0; axis < 3; ++axis)
    voxels.size[static_cast<std::size_t>(axis)] =
        std::max(2, 1 + static_cast<int>(std::ceil(extent_mm[axis] / voxel_mm)));
  const auto voxel_of = [&](double u, int axis) {
    return static_cast<std::size_t>(std::clamp(
        std::lround(u), 0L, static_cast<long>(voxels.size[static_cast<std::size_t>(axis)] - 1)));
  };
  const auto width = static_cast<std::size_t>(voxels.size[0]);
  const auto depth = static_cast<std::size_t>(voxels.size[1]);
  std::vector<std::uint8_t> occupied(width * depth * static_cast<std::size_t>(voxels.size[2]), 0);
  for (const Eigen::Vector3d& p : points_part_mm) {
    if (!p.allFinite()) continue;
    const Eigen::Vector3d u = (p - voxels.origin_mm) / voxel_mm;
    occupied[(voxel_of(u.z(), 2) * depth + voxel_of(u.y(), 1)) * width + voxel_of(u.x(), 0)] = 1;
  }
  voxels.occupied_voxels =
      static_cast<std::size_t>(std::count(occupied.begin(), occupied.end(), 1));
  voxels.occupied_runs = encode_occupied_cell_runs(
      occupied.size(), [&](std::size_t voxel) { return occupied[voxel] != 0; });
  return voxels;
}

bool part_surface_voxel_grid_bounded(const PartSurfaceVoxels& voxels) {
  return voxels.voxel_mm > 0 && std::isfinite(voxels.voxel_mm) && voxels.origin_mm.allFinite() &&
         *std::min_element(voxels.size.begin(), voxels.size.end()) >= 2 &&
         voxels.voxel_count() <= static_cast<double>(kMaxSurfaceVoxels);
}

bool part_surface_voxels_consistent(const PartSurfaceVoxels& voxels) {
  if (voxels.empty()) return voxels.occupied_runs.empty();
  if (!part_surface_voxel_grid_bounded(voxels)) return false;
  return visit_occupied_cell_runs(voxels.occupied_runs,
                                  static_cast<std::size_t>(voxels.voxel_count()),
                                  voxels.occupied_voxels, [](std::size_t, std::size_t) {});
}

}  // namespace cosmos
