#include "sim/conveyor_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/embree_scene.hpp"

namespace cosmos {
namespace {

// Cells of the parts' height bounds: fine enough to follow a part's outline, coarse enough
// that a line of sight crosses few of them.
constexpr double kHeightBoundCellMm = 2.0;

bool overlap_xy(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  return a.min().x() < b.max().x() && b.min().x() < a.max().x() && a.min().y() < b.max().y() &&
         b.min().y() < a.max().y();
}

}  // namespace

ConveyorScene::ConveyorScene() : embree_(std::make_unique<EmbreeScene>()) {}
ConveyorScene::~ConveyorScene() = default;

int ConveyorScene::add_mesh(const TriangleMesh& mesh) {
  const int index = embree_->add_mesh(mesh);
  meshes_.push_back(mesh);
  return index;
}

int ConveyorScene::add_part(std::string name, int mesh, const Eigen::Isometry3d& T_belt_part) {
  if (mesh < 0 || mesh >= static_cast<int>(meshes_.size()))
    throw std::invalid_argument("ConveyorScene: no such mesh");
  // Checked before the part reaches the ray tracer, so a refused part leaves no trace.
  Eigen::AlignedBox3d bounds;
  for (const Eigen::Vector3f& v : meshes_[static_cast<std::size_t>(mesh)].vertices) {
    bounds.extend(T_belt_part * v.cast<double>());
  }
  for (const PlacedPart& other : parts_) {
    if (overlap_xy(bounds, other.bounds_mm)) {
      throw std::invalid_argument("ConveyorScene: part '" + name + "' touches part '" + other.name +
                                  "' (bounding boxes overlap on the belt)");
    }
  }
  const int instance = embree_->add_instance(mesh, T_belt_part);
  parts_.push_back(
      {std::move(name), mesh, T_belt_part, embree_->instance_bounds(instance),
       HeightBoundGrid(meshes_[static_cast<std::size_t>(mesh)], T_belt_part, kHeightBoundCellMm)});
  return instance;
}

void ConveyorScene::move_part(int part, const Eigen::Isometry3d& T_belt_part) {
  PlacedPart& placed = parts_.at(static_cast<std::size_t>(part));
  embree_->set_instance_transform(part, T_belt_part);
  placed.T_belt_part = T_belt_part;
  placed.bounds_mm = embree_->instance_bounds(part);
  placed.height_bounds = HeightBoundGrid(meshes_[static_cast<std::size_t>(placed.mesh)],
                                         T_belt_part, kHeightBoundCellMm);
}

void ConveyorScene::commit() {
  embree_->commit();
  std::vector<Eigen::AlignedBox3d> boxes;
  boxes.reserve(parts_.size());
  highest_z_mm_ = 0.0;
  for (const PlacedPart& part : parts_) {
    boxes.push_back(part.bounds_mm);
    highest_z_mm_ = std::max(highest_z_mm_, part.bounds_mm.max().z());
  }
  parts_along_belt_.rebuild(boxes);
}

Eigen::AlignedBox3d ConveyorScene::bounds_mm() const {
  Eigen::AlignedBox3d box;
  for (const PlacedPart& part : parts_) box.extend(part.bounds_mm);
  return box;
}

Eigen::Isometry3d T_scanner_belt(const ScannerParameters& parameters, std::int64_t encoder_ticks) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().y() = parameters.belt_offset_mm(encoder_ticks);
  return T;
}

double laser_y_belt_mm(const ScannerParameters& parameters, std::int64_t profile_index) {
  // The sheet is the plane y_scanner = 0 (make_triangulation_geometry's laser plane).
  return -parameters.belt_offset_mm(parameters.encoder_ticks_of_profile(profile_index));
}

ProfileRange profiles_covering(const ConveyorScene& scene, const ScannerParameters& parameters,
                               double margin_mm) {
  const Eigen::AlignedBox3d box = scene.bounds_mm();
  if (box.isEmpty()) return {};
  const double step_mm = parameters.profile_step_mm();
  // The sheet reaches the downstream (+y) end of the parts first.
  ProfileRange range;
  range.first = static_cast<std::int64_t>(std::floor(-(box.max().y() + margin_mm) / step_mm));
  range.last = static_cast<std::int64_t>(std::ceil(-(box.min().y() - margin_mm) / step_mm));
  return range;
}

}  // namespace cosmos
