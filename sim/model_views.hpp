#pragma once
// Model views of a catalog part (thesis §4.5): for each of the view-sphere directions the
// part is turned so that the direction points at the scanner (+z, rotation_looking_along),
// laid with its lowest point on the belt, centred, and scanned by the same simulated scanner
// as live parts (profile mode), so a model view carries the same laser shadows, camera
// occlusions and dropouts as a live scan of that pose. The ideal orthographic view of the same
// pose on the same grid is the reference beside it.
//
// One Embree structure per part serves every view: only the part's instance transform moves.
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "core/range_image.hpp"
#include "scanner/conditioning_parameters.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/mesh.hpp"
#include "sim/simulated_scanner.hpp"

namespace cosmos {

struct ModelView {
  int index = 0;
  Eigen::Vector3d direction_part = Eigen::Vector3d::UnitZ();         // unit, in the part frame
  Eigen::Isometry3d T_scanner_part = Eigen::Isometry3d::Identity();  // in the image's frame
  RangeImage image;  // ground_truth set; empty (width 0) if nothing was measured
};

class ModelViewRenderer {
 public:
  // `mesh` in the part frame (mm). Directions: view_directions(subdivisions).
  ModelViewRenderer(const TriangleMesh& mesh, std::string part_name,
                    const ScannerParameters& parameters, const ConditioningParameters& conditioning,
                    int subdivisions = 2);
  ~ModelViewRenderer();

  int view_count() const { return static_cast<int>(directions_.size()); }
  const Eigen::Vector3d& direction(int index) const {
    return directions_.at(static_cast<std::size_t>(index));
  }
  // The pose of view `index`: R = rotation_looking_along(direction), placed on the belt.
  Eigen::Isometry3d view_pose(int index) const;

  // The simulated scan of view `index`; its z noise is seeded by (parameters.seed, index).
  ModelView scan_view(int index);
  // The ideal orthographic image of view `index` on the grid of `grid` (size, pixel size,
  // origin), e.g. a scan_view image.
  RangeImage ideal_view(int index, const RangeImage& grid);

 private:
  void pose_part(int index);

  TriangleMesh mesh_;
  std::string part_name_;
  ScannerParameters parameters_;
  ConditioningParameters conditioning_;  // the belt threshold of the views
  std::vector<Eigen::Vector3d> directions_;
  ConveyorScene scene_;  // one part turned through every view
  std::unique_ptr<SimulatedScanner> scanner_;
};

}  // namespace cosmos
