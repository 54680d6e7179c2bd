#include "core/modelbase/view_extent.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/modelbase/model_base.hpp"
#include "core/modelbase/point_set_widths.hpp"

namespace cosmos {
namespace {

// The cell is sampled on rings this far apart, each ring's directions about as far apart, and
// the widths across every direction on this many turns over half a circle: a part 150 mm
// across is then off by a millimetre or so at most, which the gate's tolerances hold.
constexpr double kCellStepRad = 3.0 * M_PI / 180.0;
constexpr int kAcrossTurns = 36;
// Directions spread over the sphere to measure how far the farthest lies from the views.
constexpr int kCoverageSamples = 20000;

void widen_by_direction(const std::vector<Eigen::Vector3d>& hull, const Eigen::Vector3d& direction,
                        ViewExtent& extent) {
  const WidthsAcross across = widths_across(hull, direction, kAcrossTurns);
  extent.highest_mm = std::max(extent.highest_mm, width_along(hull, direction));
  extent.widest_mm = std::max(extent.widest_mm, across.widest_mm);
  extent.narrowest_mm = std::max(extent.narrowest_mm, across.narrowest_mm);
}

}  // namespace

ViewExtent view_extent(const std::vector<Eigen::Vector3d>& hull_vertices_mm,
                       const Eigen::Vector3d& direction, double cell_radius_rad) {
  if (hull_vertices_mm.empty()) return {};
  ViewExtent extent{0, 0, 0};
  const Eigen::Vector3d centre = direction.normalized();
  const Eigen::Vector3d across = centre.unitOrthogonal();
  const Eigen::Vector3d across_too = centre.cross(across);
  widen_by_direction(hull_vertices_mm, centre, extent);
  const int rings = static_cast<int>(std::ceil(cell_radius_rad / kCellStepRad));
  for (int ring = 1; ring <= rings; ++ring) {
    const double tilt = cell_radius_rad * ring / rings;
    const int count =
        std::max(3, static_cast<int>(std::ceil(2 * M_PI * std::sin(tilt) / kCellStepRad)));
    for (int k = 0; k < count; ++k) {
      const double turn = 2 * M_PI * k / count;
      const Eigen::Vector3d tilted =
          std::cos(tilt) * centre +
          std::sin(tilt) * (std::cos(turn) * across + std::sin(turn) * across_too);
      widen_by_direction(hull_vertices_mm, tilted.normalized(), extent);
    }
  }
  return extent;
}

double covering_radius_rad(const std::vector<Eigen::Vector3d>& directions) {
  if (directions.empty()) return M_PI;
  double farthest = 0;
  for (int k = 0; k < kCoverageSamples; ++k) {
    const Eigen::Vector3d sample = spread_direction(k, kCoverageSamples, SphereCover::kWhole);
    double nearest_cosine = -1;
    for (const Eigen::Vector3d& direction : directions)
      nearest_cosine = std::max(nearest_cosine, sample.dot(direction));
    farthest = std::max(farthest, std::acos(std::clamp(nearest_cosine, -1.0, 1.0)));
  }
  // The samples themselves lie this far apart: a direction between them may lie farther.
  const double sample_spacing_rad = std::sqrt(4 * M_PI / kCoverageSamples);
  return std::min(M_PI, farthest + sample_spacing_rad);
}

void summarize_view_extents(ModelBase& base, int part) {
  bool has_coarse_views = false;
  for (const ModelBaseView& view : base.views)
    has_coarse_views |= view.part_index == part && is_once_subdivided_view(view.view_index);
  const auto starts_search = [&](const ModelBaseView& view) {
    return view.part_index == part && view.control_point_count() > 0 &&
           (!has_coarse_views || is_once_subdivided_view(view.view_index));
  };
  std::vector<Eigen::Vector3d> start_directions;
  for (const ModelBaseView& view : base.views)
    if (starts_search(view)) start_directions.push_back(view.direction_part.normalized());
  const double cell_radius_rad = covering_radius_rad(start_directions);
  const std::vector<Eigen::Vector3d>& hull =
      base.parts[static_cast<std::size_t>(part)].hull_vertices_mm;
  for (ModelBaseView& view : base.views)
    if (view.part_index == part)
      view.extent = starts_search(view) ? view_extent(hull, view.direction_part, cell_radius_rad)
                                        : ViewExtent{};
}

}  // namespace cosmos
