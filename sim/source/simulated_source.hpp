#pragma once
// The simulated cell as a ScannerSource: a conveyor carrying a seeded sequence of catalog
// parts, one after another, through the simulated laser-line scanner (sim/).
//
// The conveyor (its parts, their placement and ground truth) is simulated_conveyor.hpp, shared
// with the hardware twins; this source scans it with the simulated scanner. The stream is
// profiles k = 0 … last_profile(), then kEndOfStream.
//
// Determinism: the conveyor from settings.seed, the measurement noise from
// ScannerParameters::seed per profile. t_us is the profile's nominal exposure time
// (k · 1e6 / line_rate_hz), never the wall clock, so the same settings give a bit-identical
// stream however the loop is paced.
#include <cstdint>
#include <memory>
#include <vector>

#include "firmware_bridge/error_line.hpp"
#include "realtime/config/sim_source_settings.hpp"  // SimulatedSourceSettings, PoseMode
#include "realtime/sources/scanner_source.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/part_catalog.hpp"
#include "sim/simulated_scanner.hpp"
#include "sim/source/simulated_conveyor.hpp"
#include "sim/source/source_fault_injector.hpp"

namespace cosmos {

class SimulatedSource final : public ScannerSource {
 public:
  // Draws from the catalog's parts (settings.part_names selects among them) and loads only
  // the meshes drawn. InputError for an unknown part name or an unreadable mesh,
  // std::invalid_argument for settings out of range; builds the whole scene.
  // `faults`: injected as source_fault_injector.hpp describes (none by default).
  SimulatedSource(const PartCatalog& catalog, const ScannerParameters& parameters,
                  const SimulatedSourceSettings& settings,
                  const FaultInjectionSettings& faults = {});
  // The same from meshes in memory (procedural test parts); part_names selects among them.
  SimulatedSource(const std::vector<SimPartModel>& models, const ScannerParameters& parameters,
                  const SimulatedSourceSettings& settings,
                  const FaultInjectionSettings& faults = {});
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
  SourceHealth health() const noexcept override {
    return {.camera_timeouts = faults_.camera_timeouts()};
  }

  const SimulatedConveyor& conveyor() const { return conveyor_; }
  const std::vector<PlacedSimPart>& placed_parts() const { return conveyor_.placed_parts(); }
  // The conveyor's ground-truth query (SimulatedConveyor::placed_part_scanned_in).
  const PlacedSimPart* placed_part_scanned_in(std::int64_t first_profile,
                                              std::int64_t last_profile) const {
    return conveyor_.placed_part_scanned_in(first_profile, last_profile);
  }
  // The last profile index of the stream (next() gives 0 … last_profile(), then the end).
  std::int64_t last_profile() const { return conveyor_.last_profile(); }
  const ScannerParameters& parameters() const { return parameters_; }

 private:
  ScannerParameters parameters_;
  SimulatedConveyor conveyor_;  // declared before the scanner that traces it
  std::unique_ptr<SimulatedScanner> scanner_;
  SourceFaultInjector faults_;
  std::int64_t next_profile_ = 0;
  bool started_ = false;
  ErrorLine error_;
};

}  // namespace cosmos
