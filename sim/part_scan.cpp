#include "sim/part_scan.hpp"

#include "sim/conveyor_scene.hpp"
#include "sim/part_pose.hpp"

namespace cosmos {

RangeImage scan_single_part(const TriangleMesh& mesh, const std::string& part_name,
                            const Eigen::Matrix3d& R_belt_part, const ScannerParameters& parameters,
                            const ConditioningParameters& conditioning, ScanMode mode,
                            const ProfileObserver& observer) {
  ConveyorScene scene;
  const int mesh_index = scene.add_mesh(mesh);
  scene.add_part(part_name, mesh_index, place_on_belt(mesh, R_belt_part));
  scene.commit();
  SimulatedScanner scanner(scene, parameters, mode);
  RangeImage image = scan_range_image(scene, scanner, conditioning, {}, observer);
  if (image.width() > 0) {
    const Eigen::Isometry3d& T_scanner_part = scene.parts().front().T_belt_part;
    image.ground_truth =
        GroundTruthPose{part_name, T_scanner_part.linear(), T_scanner_part.translation()};
  }
  return image;
}

}  // namespace cosmos
