#pragma once
// The simulated cell as a ScannerSource: a conveyor carrying a seeded sequence of catalog
// parts, one after another, through the simulated laser-line scanner (sim/).
//
// Frames and ground truth (sim/conveyor_scene.hpp): every part is placed once, in the belt
// frame (the scanner frame at encoder tick 0), and T_belt_part is its exact pose there. At
// profile k the belt has moved by s = k · mm_per_profile() along +y, so the part's pose in
// the scanner frame is then T_scanner_part = Translation(0, s, 0) · T_belt_part. The laser
// sheet of profile k lies at y_belt = −k · Δy, so the parts are placed at decreasing y_belt
// in sequence order: part 0 meets the sheet first. The stream is profiles k = 0, 1, …: an
// empty lead-in of part_gap_mm, the parts each part_gap_mm apart (bounding box to bounding
// box, along y), a trailing part_gap_mm of empty belt, then kEndOfStream.
//
// Determinism: the part sequence, each part's rotation and across-belt offset come from
// settings.seed; the measurement noise from ScannerParameters::seed per profile. t_us is the
// profile's nominal exposure time (k · 1e6 / line_rate_hz), never the wall clock, so the
// same settings give a bit-identical stream however the loop is paced.
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "firmware_bridge/error_line.hpp"
#include "realtime/config/sim_source_settings.hpp"  // SimulatedSourceSettings, PoseMode
#include "realtime/sources/scanner_source.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/conveyor_scene.hpp"
#include "sim/mesh.hpp"
#include "sim/part_catalog.hpp"
#include "sim/simulated_scanner.hpp"

namespace cosmos {

// A part the source may place: its mesh in its own frame (mm) and its index in the catalog.
struct SimPartModel {
  std::string name;
  TriangleMesh mesh;
  int catalog_index = -1;
};

// Ground truth of one part in the stream.
struct PlacedSimPart {
  int catalog_index = -1;
  std::string name;
  Eigen::Isometry3d T_belt_part = Eigen::Isometry3d::Identity();
  Eigen::AlignedBox3d bounds_mm;  // belt frame
  // The profiles whose laser sheet crosses the part's bounding box: every sample of the part
  // lies in them, and no other part's does.
  std::int64_t first_profile = 0;
  std::int64_t last_profile = -1;
};

class SimulatedSource final : public ScannerSource {
 public:
  // Draws from the catalog's parts (settings.part_names selects among them) and loads only
  // the meshes drawn. InputError for an unknown part name or an unreadable mesh,
  // std::invalid_argument for settings out of range; builds the whole scene.
  SimulatedSource(const PartCatalog& catalog, const ScannerParameters& parameters,
                  const SimulatedSourceSettings& settings);
  // The same from meshes in memory (procedural test parts); part_names selects among them.
  SimulatedSource(const std::vector<SimPartModel>& models, const ScannerParameters& parameters,
                  const SimulatedSourceSettings& settings);
  ~SimulatedSource() override;
  SimulatedSource(const SimulatedSource&) = delete;
  SimulatedSource& operator=(const SimulatedSource&) = delete;

  // Rewinds to profile 0: a restarted source replays the identical stream.
  SourceStatus start() override;
  void reserve(Profile& profile) const override;
  SourceStatus next(Profile& out) noexcept override;
  void stop() noexcept override { started_ = false; }

  double mm_per_profile() const override { return parameters_.profile_step_mm(); }
  std::string_view last_error() const noexcept override { return error_.view(); }
  std::uint64_t dropped_profiles() const noexcept override { return 0; }

  const std::vector<PlacedSimPart>& placed_parts() const { return placed_; }
  // The placed part that profiles first_profile … last_profile (a scanned part's rows) cover
  // most, nullptr when they cover none. Parts the cell dropped take no part_seq, so this,
  // not part_seq, pairs a pose with its truth.
  const PlacedSimPart* placed_part_scanned_in(std::int64_t first_profile,
                                              std::int64_t last_profile) const;
  // The last profile index of the stream (next() gives 0 … last_profile(), then the end).
  std::int64_t last_profile() const { return last_profile_; }
  const ScannerParameters& parameters() const { return parameters_; }

 private:
  // picks: per stream position, an index into `models`.
  void build(const std::vector<const SimPartModel*>& models, const std::vector<std::size_t>& picks);

  ScannerParameters parameters_;
  SimulatedSourceSettings settings_;
  std::unique_ptr<ConveyorScene> scene_;  // declared before the scanner that traces it
  std::unique_ptr<SimulatedScanner> scanner_;
  std::vector<PlacedSimPart> placed_;
  std::int64_t last_profile_ = -1;
  std::int64_t next_profile_ = 0;
  bool started_ = false;
  ErrorLine error_;
};

}  // namespace cosmos
