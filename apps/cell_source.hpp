#pragma once
// The scanner source of `cosmos cell`, from its options and the cell configuration:
//   --replay FILE                          a recorded COSMOS_PROFILE log (ReplaySource)
//   --source hardware --hardware FILE      the live camera and GPIO lines (HardwareSource), or,
//                                          when FILE names the simulated devices
//                                          (config/hardware-sim.yaml), the same HardwareSource
//                                          on the hardware twins (HardwareTwinSource)
//   --source sim (default)                 the simulated conveyor and scanner (SimulatedSource)
// The simulated conveyor, twins or not, is the config's `sim_source:` section, --parts
// overriding its count. Construction errors throw InputError (one line).
#include <memory>
#include <string>

#include "realtime/config/cell_config.hpp"
#include "realtime/sources/scanner_source.hpp"
#include "sim/part_catalog.hpp"
#include "sim/source/simulated_conveyor.hpp"

namespace cosmos::cli {

struct CellSourceChoice {
  std::string source = "sim";  // sim | hardware
  std::string hardware;        // the hardware YAML
  std::string replay;          // an LCM log; wins over `source`
  int parts = -1;              // simulated parts; <= 0: sim_source.parts
};

std::unique_ptr<ScannerSource> make_cell_source(const CellSourceChoice& choice,
                                                const CellConfig& config,
                                                const PartCatalog& catalog);

// The simulated world behind the source (the simulated source's or the twins' conveyor),
// for the ground truth of the live table; nullptr for real hardware and replays.
const SimulatedConveyor* simulated_ground_truth(const ScannerSource& source);

// A pose went out: a hardware source (real or on the twins) pulses result_ready for it;
// other sources ignore it. Safe from the publisher thread (HardwareSource::announce_result).
void announce_pose_published(ScannerSource& source);

}  // namespace cosmos::cli
