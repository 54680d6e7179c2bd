#pragma once
// The simulated cell's world: a conveyor carrying a seeded sequence of catalog parts, one
// after another, each placed once in the belt frame with its exact pose (the ground truth).
// Two readers scan it: the simulated scanner of SimulatedSource (simulated_source.hpp) and
// the hardware twins (sim/twins/), whose camera and encoder follow the same belt, so a
// simulated and a twin-driven hardware cell with the same settings see the same parts.
//
// Frames (sim/conveyor_scene.hpp): the belt frame is the scanner frame at encoder tick 0. At
// profile k the belt has moved by s = k · Δy along +y (Δy = profile_step_mm()), so a part's
// pose in the scanner frame is then T_scanner_part = Translation(0, s, 0) · T_belt_part. The
// laser sheet of profile k lies at y_belt = −k · Δy, so the parts are placed at decreasing
// y_belt in sequence order: part 0 meets the sheet first. The stream is profiles
// k = 0 … last_profile(): an empty lead-in, the parts as part_layout.hpp lays them out
// (by default each part_gap_mm apart, bounding box to bounding box, along y), and as much
// trailing empty belt.
//
// Determinism: the part sequence, each part's rotation and across-belt offset come from
// settings.seed alone.
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "realtime/config/sim_source_settings.hpp"  // SimulatedConveyorSettings, PoseMode
#include "scanner/scanner_model.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"

namespace cosmos {

// A part the conveyor may carry: its mesh in its own frame (mm) and its index in the catalog.
struct SimPartModel {
  std::string name;
  TriangleMesh mesh;
  int catalog_index = -1;
};

// Ground truth of one part on the belt.
struct PlacedSimPart {
  int catalog_index = -1;
  std::string name;
  int scene_mesh = -1;  // its mesh in scene() (ConveyorScene::mesh), shared by its copies
  Eigen::Isometry3d T_belt_part = Eigen::Isometry3d::Identity();
  Eigen::AlignedBox3d bounds_mm;  // belt frame
  // The profiles whose laser sheet crosses the part's bounding box: every sample of the part
  // lies in them, and no other part's does.
  std::int64_t first_profile = 0;
  std::int64_t last_profile = -1;
};

class SimulatedConveyor {
 public:
  // Draws from the catalog's parts (settings.part_names selects among them) and loads only
  // the meshes drawn. InputError for an unknown part name or an unreadable mesh,
  // std::invalid_argument for settings out of range; builds the whole scene.
  SimulatedConveyor(const PartCatalog& catalog, const ScannerParameters& parameters,
                    const SimulatedConveyorSettings& settings);
  // The same from meshes in memory (procedural test parts); part_names selects among them.
  SimulatedConveyor(const std::vector<SimPartModel>& models, const ScannerParameters& parameters,
                    const SimulatedConveyorSettings& settings);
  ~SimulatedConveyor();
  SimulatedConveyor(const SimulatedConveyor&) = delete;
  SimulatedConveyor& operator=(const SimulatedConveyor&) = delete;

  // The committed scene, for the scanners that trace it.
  const ConveyorScene& scene() const { return *scene_; }
  const std::vector<PlacedSimPart>& placed_parts() const { return placed_; }
  // The placed part that profiles first_profile … last_profile (a scanned part's rows) cover
  // most, nullptr when they cover none. Parts the cell dropped take no part_seq, so this,
  // not part_seq, pairs a pose with its truth.
  const PlacedSimPart* placed_part_scanned_in(std::int64_t first_profile,
                                              std::int64_t last_profile) const;
  // Of the placed parts that profiles first_profile … last_profile cross, the one nearest to
  // point_belt_mm (a pose's or a rejection's position on the belt; distance to its box plus
  // to its origin): pairs each of a blob's parts with its truth, side by side ones too.
  const PlacedSimPart* placed_part_at(const Eigen::Vector3d& point_belt_mm,
                                      std::int64_t first_profile, std::int64_t last_profile) const;
  // The last profile index of the stream.
  std::int64_t last_profile() const { return last_profile_; }
  const ScannerParameters& parameters() const { return parameters_; }

 private:
  // picks: per belt position, an index into `models`.
  void build(const std::vector<const SimPartModel*>& models, const std::vector<std::size_t>& picks,
             const SimulatedConveyorSettings& settings);

  ScannerParameters parameters_;
  std::unique_ptr<ConveyorScene> scene_;
  std::vector<PlacedSimPart> placed_;
  std::int64_t last_profile_ = -1;
};

}  // namespace cosmos
