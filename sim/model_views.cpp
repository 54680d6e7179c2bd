#include "sim/model_views.hpp"

#include "sim/orthographic_renderer.hpp"
#include "sim/part_pose.hpp"
#include "sim/range_image_scan.hpp"
#include "sim/seeded_random.hpp"
#include "sim/view_sphere.hpp"

namespace cosmos {

ModelViewRenderer::ModelViewRenderer(const TriangleMesh& mesh, std::string part_name,
                                     const ScannerParameters& parameters,
                                     const ConditioningParameters& conditioning, int subdivisions)
    : mesh_(mesh),
      part_name_(std::move(part_name)),
      parameters_(parameters),
      conditioning_(conditioning),
      directions_(view_directions(subdivisions)) {
  const int mesh_index = scene_.add_mesh(mesh_);
  scene_.add_part(part_name_, mesh_index, view_pose(0));
  scene_.commit();
  scanner_ = std::make_unique<SimulatedScanner>(scene_, parameters_, ScanMode::kProfile);
}

ModelViewRenderer::~ModelViewRenderer() = default;

Eigen::Isometry3d ModelViewRenderer::view_pose(int index) const {
  return place_on_belt(mesh_, rotation_looking_along(direction(index)));
}

void ModelViewRenderer::pose_part(int index) {
  scene_.move_part(0, view_pose(index));
  scene_.commit();
}

ModelView ModelViewRenderer::scan_view(int index) {
  pose_part(index);
  scanner_->set_seed(mix_seed(parameters_.seed, static_cast<std::uint64_t>(index)));
  ModelView view;
  view.index = index;
  view.direction_part = direction(index).normalized();
  view.T_scanner_part = scene_.parts().front().T_belt_part;
  view.image = scan_range_image(scene_, *scanner_, conditioning_);
  if (view.image.width() > 0) {
    view.image.ground_truth = GroundTruthPose{part_name_, view.T_scanner_part.linear(),
                                              view.T_scanner_part.translation()};
  }
  return view;
}

RangeImage ModelViewRenderer::ideal_view(int index, const RangeImage& grid) {
  pose_part(index);
  RangeImage image(grid.width(), grid.height(), grid.pixel_size_x_mm, grid.pixel_size_y_mm);
  image.origin_x_mm = grid.origin_x_mm;
  image.origin_y_mm = grid.origin_y_mm;
  render_orthographic(scene_, image);
  const Eigen::Isometry3d& T = scene_.parts().front().T_belt_part;
  image.ground_truth = GroundTruthPose{part_name_, T.linear(), T.translation()};
  return image;
}

}  // namespace cosmos
