#pragma once
// Scenes of procedural parts for the simulated-scanner tests: a part placed on the belt at a
// known pose, and helpers to scan it, so the tests do not depend on the mesh cache.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/profile.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/part_pose.hpp"
#include "sim/range_image_scan.hpp"
#include "sim/simulated_scanner.hpp"

namespace cosmos::testing {

// One part at rotation R, centred at (x_mm, y_mm), lowest point on the belt.
inline std::unique_ptr<ConveyorScene> single_part_scene(const TriangleMesh& mesh,
                                                        const Eigen::Matrix3d& R, double x_mm = 0.0,
                                                        double y_mm = 0.0,
                                                        const std::string& name = "part") {
  auto scene = std::make_unique<ConveyorScene>();
  const int mesh_index = scene->add_mesh(mesh);
  scene->add_part(name, mesh_index, place_on_belt(mesh, R, x_mm, y_mm));
  scene->commit();
  return scene;
}

inline RangeImage scan(const ConveyorScene& scene, const ScannerParameters& parameters,
                       ScanMode mode = ScanMode::kProfile) {
  SimulatedScanner scanner(scene, parameters, mode);
  return scan_range_image(scene, scanner, ConditioningParameters{});
}

// Raw profiles (belt included, no background removal) in exposure order, with the belt-frame
// y of each.
struct ProfileScan {
  std::vector<Profile> profiles;
  std::vector<double> y_mm;
};

inline ProfileScan scan_profiles(const ConveyorScene& scene, const ScannerParameters& parameters,
                                 double margin_mm, ScanMode mode = ScanMode::kProfile) {
  SimulatedScanner scanner(scene, parameters, mode);
  const ProfileRange range = profiles_covering(scene, parameters, margin_mm);
  ProfileScan result;
  for (std::int64_t k = range.first; k <= range.last; ++k) {
    Profile profile;
    scanner.reserve(profile);
    scanner.acquire(k, profile);
    result.profiles.push_back(profile);
    result.y_mm.push_back(laser_y_belt_mm(parameters, k));
  }
  return result;
}

// The profile sample nearest x_mm.
inline std::size_t sample_at(const Profile& profile, double x_mm) {
  return static_cast<std::size_t>(std::lround((x_mm - profile.x0_mm) / profile.dx_mm));
}

}  // namespace cosmos::testing
