#include "apps/cell_source.hpp"

#include "core/input_error.hpp"
#include "realtime/config/hardware_config.hpp"
#include "realtime/sources/hardware_source.hpp"
#include "realtime/sources/replay_source.hpp"
#include "sim/source/simulated_source.hpp"
#include "sim/twins/hardware_twin_source.hpp"

namespace cosmos::cli {
namespace {

SimulatedSourceSettings source_settings(const CellSourceChoice& choice, const CellConfig& config) {
  SimulatedSourceSettings settings = config.sim_source;
  if (choice.parts > 0) settings.parts = choice.parts;
  return settings;
}

}  // namespace

std::unique_ptr<ScannerSource> make_cell_source(const CellSourceChoice& choice,
                                                const CellConfig& config,
                                                const PartCatalog& catalog) {
  if (!choice.replay.empty()) {
    ReplaySourceSettings settings;
    settings.max_profile_width = static_cast<std::size_t>(config.scanner.points_per_profile);
    settings.mm_per_profile = config.scanner.profile_step_mm();
    settings.channel = config.lcm.profile_channel;
    return std::make_unique<ReplaySource>(choice.replay, settings);
  }
  if (choice.source == "hardware") {
    if (choice.hardware.empty()) {
      throw InputError(
          "cell: --source hardware needs --hardware FILE (see config/hardware-example.yaml, or "
          "config/hardware-sim.yaml for the simulated twins)");
    }
    const HardwareConfig hardware = read_hardware_config(choice.hardware);
    if (!hardware.camera_simulated())
      return std::make_unique<HardwareSource>(hardware, config.scanner);
    return std::make_unique<HardwareTwinSource>(
        hardware, std::make_unique<SimulatedConveyor>(catalog, config.scanner,
                                                      source_settings(choice, config)));
  }
  return std::make_unique<SimulatedSource>(catalog, config.scanner,
                                           source_settings(choice, config));
}

const SimulatedConveyor* simulated_ground_truth(const ScannerSource& source) {
  if (const auto* simulated = dynamic_cast<const SimulatedSource*>(&source))
    return &simulated->conveyor();
  if (const auto* twins = dynamic_cast<const HardwareTwinSource*>(&source))
    return &twins->conveyor();
  return nullptr;
}

void announce_pose_published(ScannerSource& source) {
  if (auto* hardware = dynamic_cast<HardwareSource*>(&source)) hardware->announce_result();
  if (auto* twins = dynamic_cast<HardwareTwinSource*>(&source)) twins->hardware().announce_result();
}

}  // namespace cosmos::cli
