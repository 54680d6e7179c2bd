#pragma once
// The faults the HIL player injects (fault_plan.hpp, "probe"), counted where the bridge counts
// them: the cell's own HardwareSource runs on a V4l2Camera and LibgpiodLines this probe holds,
// so their counters can be read, while the player plays a short conveyor into vivid and
// gpio-sim. Compared with the player's log:
//   dropped    the camera's dropped frames equal the sequence gaps vivid left (the skip's
//              among them, exactly), and every other frame reached the source as a profile
//              of its sequence number, stamped within two frame periods of its fill;
//   stall      the watchdog expired (timeouts counted) and frames came again after it;
//   corrupt    the frame flagged V4L2_BUF_FLAG_ERROR counted as corrupted, not as dropped;
//   encoder    the jiggle's and the glitch's reversals or invalid transitions counted, the
//              count at each frame the belt's (no drift across the faults);
//   photo eye  one arrival and one departure per part, the bounce filtered and counted.
#include <filesystem>
#include <vector>

#include "realtime/config/hardware_config.hpp"
#include "scanner/scanner_model.hpp"
#include "tests/hil/check_line.hpp"

namespace cosmos::hil {

struct BridgeProbeSettings {
  HardwareConfig hardware;
  ScannerParameters scanner;
  std::filesystem::path plan_file;   // the player's plan, waited for
  std::filesystem::path player_log;  // the player's log, waited for after the run
  double wait_s = 120;
};

std::vector<ProbeCheck> probe_bridge(const BridgeProbeSettings& settings);

}  // namespace cosmos::hil
