#pragma once
// Where the HIL player injects its faults: in the empty belt between parts (or before the
// first), so that each fault must be counted and survived without costing a part.
//   cell   the run of `cosmos cell`: a skip, a jiggle, a glitch, a stall, a corrupted frame
//          and a bouncing photo eye, each in its own gap between parts (as many as fit);
//   probe  the bridge probe's short run: the same faults, closer together;
//   none   no faults.
#include <string>
#include <vector>

#include "tests/hil/frame_player.hpp"
#include "tests/hil/frame_tape.hpp"

namespace cosmos::hil {

struct FaultPlan {
  std::vector<FaultAt> faults;  // in profile order
  std::vector<std::size_t> bouncing_arrivals;
};

// Throws std::invalid_argument for an unknown mode.
FaultPlan plan_faults(const std::string& mode, const TapeHeader& conveyor);

// The stall's length: longer than the HIL camera's watchdog (config/hardware-hil.yaml).
inline constexpr int kStallMs = 600;
// The cell run's stall: long enough that the cell, even with frames still queued when it
// began, waits through several of its status periods (config/cell-hil.yaml), so that
// COSMOS_STATUS shows FAULT while it lasts; short enough for the gap between two parts.
inline constexpr int kCellStallMs = 1200;
// Frames the skip drops.
inline constexpr int kSkipFrames = 5;

}  // namespace cosmos::hil
