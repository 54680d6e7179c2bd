#include "apps/cell_source.hpp"

#include "core/input_error.hpp"
#include "realtime/config/hardware_config.hpp"
#include "realtime/sources/hardware_source.hpp"
#include "realtime/sources/replay_source.hpp"
#include "sim/source/simulated_source.hpp"
#include "sim/twins/hardware_twin_source.hpp"

namespace cosmos::cli {
namespace {

SimulatedConveyorSettings conveyor_settings(const CellSourceChoice& choice,
                                            const CellConfig& config) {
  SimulatedConveyorSettings settings;
  settings.parts = choice.parts > 0 ? choice.parts : config.sim_source.parts;
  settings.seed = config.sim_source.seed;
  settings.part_gap_mm = config.sim_source.part_gap_mm;
  settings.pose =
      config.sim_source.pose == SimPoseMode::kResting ? PoseMode::kResting : PoseMode::kRandom;
  settings.part_names = config.sim_source.part_names;
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
                                                      conveyor_settings(choice, config)));
  }
  SimulatedSourceSettings settings;
  static_cast<SimulatedConveyorSettings&>(settings) = conveyor_settings(choice, config);
  return std::make_unique<SimulatedSource>(catalog, config.scanner, settings);
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
