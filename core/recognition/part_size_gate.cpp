#include "core/recognition/part_size_gate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/modelbase/point_set_widths.hpp"

namespace cosmos {
namespace {

// Directions on the sphere for the coarse pass (about 3 degrees apart), then grids of
// (2 kGridHalf + 1)^2 directions about the best, each kZoom times narrower, from the coarse
// spacing down to where a part a metre across is off by well under a tenth of a millimetre.
constexpr int kCoarseDirections = 2000;
constexpr std::size_t kCoarseCorners = 128;
constexpr int kGridHalf = 5;
constexpr double kFirstRadiusRad = 0.06;
constexpr double kLastRadiusRad = 1e-5;
constexpr double kZoom = 4;

}  // namespace

PartExtent part_extent(const ModelPart& part) {
  PartExtent extent;
  extent.diameter_mm = part.diameter_mm;
  const std::vector<Eigen::Vector3d>& hull = part.hull_vertices_mm;
  if (hull.size() < 4) return extent;
  Eigen::Vector3d best = Eigen::Vector3d::UnitZ();
  double narrowest = std::numeric_limits<double>::infinity();
  // The coarse pass only finds where to zoom in: on a hull of thousands of corners, every
  // k-th of them narrows the same directions, at a fraction of the cost.
  std::vector<Eigen::Vector3d> corners;
  const std::size_t stride = (hull.size() + kCoarseCorners - 1) / kCoarseCorners;
  for (std::size_t i = 0; i < hull.size(); i += stride) corners.push_back(hull[i]);
  double coarse_narrowest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kCoarseDirections; ++k) {
    const Eigen::Vector3d direction =
        spread_direction(k, kCoarseDirections, SphereCover::kUpperHalf);
    const double width = width_along(corners, direction);
    if (width < coarse_narrowest) {
      coarse_narrowest = width;
      best = direction;
    }
  }
  narrowest = width_along(hull, best);
  // A grid of directions about the best one, zoomed in: the width is not smooth where the
  // narrowest direction lies (a face's normal, or across two edges), and a grid, unlike a
  // descent, does not stall at such a crease.
  for (double radius = kFirstRadiusRad; radius >= kLastRadiusRad; radius /= kZoom) {
    const Eigen::Vector3d centre = best;
    const Eigen::Vector3d across = centre.unitOrthogonal();
    const Eigen::Vector3d across_too = centre.cross(across);
    for (int i = -kGridHalf; i <= kGridHalf; ++i)
      for (int j = -kGridHalf; j <= kGridHalf; ++j) {
        const Eigen::Vector3d direction =
            (centre + radius / kGridHalf * (i * across + j * across_too)).normalized();
        const double width = width_along(hull, direction);
        if (width < narrowest) {
          narrowest = width;
          best = direction;
        }
      }
  }
  extent.thinnest_width_mm = narrowest;
  return extent;
}

SceneExtent scene_extent(const RegistrationPoints& points, const RangeImage& image) {
  SceneExtent extent;
  constexpr int kDirections = 64;
  const Eigen::Matrix3Xd& positions = points.position_mm;
  for (int k = 0; k < kDirections && positions.cols() > 0; ++k)
    extent.width_mm = std::max(
        extent.width_mm, width_along(positions.colwise(),
                                     spread_direction(k, kDirections, SphereCover::kUpperHalf)));
  // Across the viewing direction: along directions in the belt's plane, half a circle.
  constexpr int kAcrossDirections = 36;
  if (positions.cols() > 0) {
    const WidthsAcross across =
        widths_across(positions.colwise(), Eigen::Vector3d::UnitZ(), kAcrossDirections);
    extent.widest_across_mm = across.widest_mm;
    extent.narrowest_across_mm = across.narrowest_mm;
  }
  for (int row = 0; row < image.height(); ++row)
    for (int column = 0; column < image.width(); ++column)
      if (image.has_data(column, row))
        extent.top_mm = std::max(extent.top_mm, static_cast<double>(image.z_mm(column, row)));
  return extent;
}

SizeVerdict judge_part_size(const PartExtent& part, const SceneExtent& scene, SceneParts parts,
                            bool parts_touch_belt, const PartSizeGateParameters& parameters) {
  if (!parameters.enabled) return SizeVerdict::kFits;
  if (parts == SceneParts::kOne &&
      part.diameter_mm + parameters.extent_tolerance_mm < scene.width_mm)
    return SizeVerdict::kSmallerThanScene;
  if (parts_touch_belt && part.thinnest_width_mm > scene.top_mm + parameters.height_tolerance_mm)
    return SizeVerdict::kThickerThanScene;
  return SizeVerdict::kFits;
}

bool ViewSizeGate::fits(const ViewExtent& view) const {
  if (!enabled) return true;
  if (bounds_height && view.highest_mm + height_tolerance_mm < scene.top_mm) return false;
  return view.widest_mm + width_tolerance_mm >= scene.widest_across_mm &&
         view.narrowest_mm + width_tolerance_mm >= scene.narrowest_across_mm;
}

ViewSizeGate view_size_gate(const SceneExtent& scene, SceneParts parts, bool parts_touch_belt,
                            const PartSizeGateParameters& parameters) {
  ViewSizeGate gate;
  gate.enabled = parameters.enabled && parameters.views && parts == SceneParts::kOne;
  gate.scene = scene;
  gate.bounds_height = parts_touch_belt;
  gate.height_tolerance_mm = parameters.view_height_tolerance_mm;
  gate.width_tolerance_mm = parameters.extent_tolerance_mm;
  return gate;
}

}  // namespace cosmos
