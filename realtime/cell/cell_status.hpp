#pragma once
// The cell's health once a second, as the publisher sends it on COSMOS_STATUS. Every drop and
// overrun the real-time loop counts appears here, so overload is visible, never silent.
#include <cstdint>
#include <string>

namespace cosmos {

// Numbered like cell_status_t's constants (checked where they are converted).
enum class CellState : std::int8_t { kIdle = 0, kScanning = 1, kFault = 2 };

// "IDLE", "SCANNING", "FAULT", or "UNKNOWN" for a value off the wire that is none of them.
const char* to_string(CellState state);

struct CellStatus {
  std::int64_t utime_us = 0;  // utime_us of the last published pose (source clock)
  CellState state = CellState::kIdle;
  std::string state_text;  // one line for people: the fault's reason, or what the cell does

  // Totals since start.
  std::int64_t profiles_acquired = 0;
  std::int64_t profiles_dropped = 0;
  std::int64_t deadline_overruns = 0;

  // Per-profile processing time of the acquisition thread over the last period.
  double profile_time_p50_us = 0.0;
  double profile_time_p99_us = 0.0;
  double profile_time_max_us = 0.0;

  std::int64_t parts_seen = 0;
  std::int64_t parts_recognized = 0;
  std::int64_t parts_rejected = 0;

  std::int32_t recognition_queue_depth = 0;
  std::int32_t publish_queue_depth = 0;
};

}  // namespace cosmos
