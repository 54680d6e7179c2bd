#include "core/modelbase/part_surface_summary.hpp"

#include <algorithm>

#include "core/modelbase/model_surface.hpp"

namespace cosmos {

void summarize_part_surface(ModelBase& base, int part,
                            const PartDistanceFieldParameters& parameters) {
  std::vector<Eigen::Vector3d> points_part_mm;
  for (ModelBaseView& view : base.views) {
    if (view.part_index != part) continue;
    const ModelSurface surface(view);
    const Eigen::Matrix3Xd& position = surface.points().position_mm;
    view.control_point_centroid_mm = Eigen::Vector3d::Zero();
    if (position.cols() == 0) continue;
    view.control_point_centroid_mm = position.rowwise().mean();
    const RigidTransform T_part_view = view.T_scanner_part.inverse();
    for (Eigen::Index i = 0; i < position.cols(); ++i)
      points_part_mm.push_back(T_part_view.apply(position.col(i)));
  }
  ModelPart& model_part = base.parts[static_cast<std::size_t>(part)];
  model_part.surface_voxels = part_surface_voxels(points_part_mm, parameters);
  const std::size_t step = std::max<std::size_t>(1, points_part_mm.size() / kSurfaceSamplePoints);
  model_part.surface_sample_mm.clear();
  for (std::size_t i = 0; i < points_part_mm.size() / step; ++i)
    model_part.surface_sample_mm.push_back(points_part_mm[i * step]);
}

void summarize_part_surfaces(ModelBase& base, const PartDistanceFieldParameters& parameters) {
  for (int part = 0; part < static_cast<int>(base.parts.size()); ++part)
    summarize_part_surface(base, part, parameters);
}

}  // namespace cosmos
