#include "core/representation/cosmos_view.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace cosmos {
namespace {

struct PatchSums {
  double area = 0;
  Eigen::Vector3d normal_area = Eigen::Vector3d::Zero();
  Eigen::Vector3d position_area = Eigen::Vector3d::Zero();
  double shape_index_area = 0;
  double curvedness_area = 0;
  double shape_index_min = 2.0;
  double shape_index_max = -1.0;
  int pixels = 0;
  int planar_pixels = 0;
};

// V(P) of Eq. 3.10 with the number of 8-adjacent same-side pixel pairs across each boundary.
std::vector<std::map<int, int>> patch_adjacency(const ShapeIndexField& field,
                                                const CsmpSegmentation& segmentation) {
  std::vector<std::map<int, int>> shared(segmentation.patch_count);
  const auto& patch = segmentation.patch_of_pixel;
  for (int row = 0; row < field.height(); ++row) {
    for (int column = 0; column < field.width(); ++column) {
      const std::size_t i = patch.index(column, row);
      if (patch[i] == kNoPatch) continue;
      for (int k = 4; k < 8; ++k) {  // forward half: each pair once
        if (!((field.same_side[i] >> k) & 1u)) continue;
        const std::size_t j =
            patch.index(column + kNeighborOffsets[k].column, row + kNeighborOffsets[k].row);
        if (patch[j] == kNoPatch || patch[j] == patch[i]) continue;
        ++shared[patch[i]][patch[j]];
        ++shared[patch[j]][patch[i]];
      }
    }
  }
  return shared;
}

std::vector<GaussMapPoint> gauss_patch_map(const std::vector<Csmp>& patches) {
  const double merge_cos = std::cos(kGaussMapMergeDeg * std::numbers::pi / 180.0);
  std::vector<GaussMapPoint> points;
  for (const Csmp& patch : patches) {
    auto point = std::find_if(points.begin(), points.end(), [&](const GaussMapPoint& p) {
      return p.direction.dot(patch.mean_normal) >= merge_cos;
    });
    if (point == points.end()) {
      points.push_back({patch.mean_normal, {}});
      point = points.end() - 1;
    }
    // Eqs. 3.14-3.15: patches of equal shape index at one point aggregate their area and
    // curvedness in one term of the spectral function e^{j t S_I}.
    auto term = std::find_if(point->terms.begin(), point->terms.end(), [&](const SupportTerm& t) {
      return std::abs(t.shape_index - patch.shape_index) < kSupportShapeIndexTolerance;
    });
    if (term == point->terms.end()) {
      point->terms.push_back({patch.shape_index, 0, 0, {}});
      term = point->terms.end() - 1;
    }
    term->area_mm2 += patch.area_mm2;
    term->curvedness_area += patch.mean_curvedness_per_mm * patch.area_mm2;
    term->patches.push_back(patch.id);
  }
  return points;
}

}  // namespace

CosmosView build_cosmos_view(const DarbouxFrameField& frames, const ShapeIndexField& field,
                             const CsmpSegmentation& segmentation) {
  std::vector<PatchSums> sums(segmentation.patch_count);
  for (std::size_t i = 0; i < field.label.size(); ++i) {
    const int id = segmentation.patch_of_pixel[i];
    // A patch's features are its surface's (§3.5): a pixel without a usable surface fit that
    // the segmentation folded into a patch (a hole inside it) brings no shape to it.
    if (id == kNoPatch || field.label[i] == SurfaceLabel::kInvalid) continue;
    PatchSums& s = sums[id];
    const double area = field.area_mm2[i];
    const double shape = field.shape_index[i];
    s.area += area;
    s.normal_area +=
        area * Eigen::Vector3d(frames.frame[kNx][i], frames.frame[kNy][i], frames.frame[kNz][i]);
    s.position_area += area * Eigen::Vector3d(frames.position_mm[0][i], frames.position_mm[1][i],
                                              frames.position_mm[2][i]);
    s.shape_index_area += area * shape;
    s.curvedness_area += area * field.curvedness_per_mm[i];
    s.shape_index_min = std::min(s.shape_index_min, shape);
    s.shape_index_max = std::max(s.shape_index_max, shape);
    ++s.pixels;
    s.planar_pixels += field.label[i] == SurfaceLabel::kPlanar ? 1 : 0;
  }
  const auto adjacency = patch_adjacency(field, segmentation);

  CosmosView view;
  for (int id = 0; id < segmentation.patch_count; ++id) {
    const PatchSums& s = sums[id];
    Csmp patch;
    patch.id = id;
    patch.area_mm2 = s.area;
    patch.mean_normal = s.normal_area.normalized();  // Eq. 3.7
    patch.shape_index = s.shape_index_area / s.area;
    patch.shape_index_min = s.shape_index_min;
    patch.shape_index_max = s.shape_index_max;
    patch.mean_curvedness_per_mm = s.curvedness_area / s.area;  // Eq. 3.16
    patch.centroid_mm = s.position_area / s.area;
    patch.pixels = s.pixels;
    patch.planar = 2 * s.planar_pixels > s.pixels;
    for (const auto& [neighbor, count] : adjacency[id])
      patch.neighbors.push_back({neighbor, count});
    view.visible_area_mm2 += s.area;
    view.patches.push_back(std::move(patch));
  }
  view.gauss_map = gauss_patch_map(view.patches);
  return view;
}

}  // namespace cosmos
