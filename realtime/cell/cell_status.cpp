#include "realtime/cell/cell_status.hpp"

namespace cosmos {

const char* to_string(CellState state) {
  switch (state) {
    case CellState::kIdle:
      return "IDLE";
    case CellState::kScanning:
      return "SCANNING";
    case CellState::kFault:
      return "FAULT";
  }
  return "UNKNOWN";
}

}  // namespace cosmos
