#pragma once
// The cell's state on COSMOS_STATUS, decided in one place. An operator reads FAULT with its
// reason while a fault lasts and SCANNING again once the cell is back to normal:
//   - the source failed for good: FAULT with the source's one line;
//   - the source has ended: IDLE;
//   - the camera stalls (its last read timed out), or a fault total grew since the previous
//     status (frames lost, encoder errors, ...): FAULT naming each, for as long as it lasts;
//   - otherwise SCANNING.
// Tools that check a run (the hardware-in-the-loop suite) explain each FAULT from the same
// list of fault totals.
#include <cstdint>
#include <span>
#include <string_view>

#include "realtime/cell/cell_status.hpp"

namespace cosmos {

// What the acquisition thread knows of its source when a status is sent.
struct SourceCondition {
  bool failed = false;
  std::string_view failure;  // the source's one line, when failed
  bool stalled = false;      // its last read timed out and no frame has come since
  bool ended = false;
};

// A total whose growth while scanning is a fault, with what it counts, for the reason text.
struct FaultTotal {
  std::int64_t CellStatus::*total;
  const char* what;
};
std::span<const FaultTotal> fault_totals();

// The stall's reason text, as FAULT shows it while the camera stalls.
inline constexpr std::string_view kCameraStallReason =
    "no frame from the camera within its watchdog (camera timeout)";

// Sets status.state and status.state_text from the source's condition and the totals of this
// status against those of the previous one.
void decide_cell_state(const SourceCondition& source, const CellStatus& previous,
                       CellStatus& status);

}  // namespace cosmos
