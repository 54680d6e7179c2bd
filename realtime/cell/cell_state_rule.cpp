#include "realtime/cell/cell_state_rule.hpp"

#include <string>

namespace cosmos {

std::span<const FaultTotal> fault_totals() {
  static constexpr FaultTotal kFaults[] = {
      {&CellStatus::camera_timeouts, "camera timeouts"},
      {&CellStatus::profiles_lost, "frames lost"},
      {&CellStatus::encoder_errors, "encoder errors"},
      {&CellStatus::encoder_reversals, "encoder reversals"},
      {&CellStatus::encoder_stalls, "profiles with the encoder stuck while the belt moves"},
      {&CellStatus::laser_off_profiles, "profiles without laser light (laser off)"},
      {&CellStatus::gpio_edges_lost, "GPIO edges lost"},
      {&CellStatus::photo_eye_bounces, "photo-eye bounces"},
      {&CellStatus::parts_dropped, "parts dropped (recognizer overloaded)"},
  };
  return kFaults;
}

void decide_cell_state(const SourceCondition& source, const CellStatus& previous,
                       CellStatus& status) {
  if (source.failed) {
    status.state = CellState::kFault;
    status.state_text = "the scanner source failed: " + std::string(source.failure);
    return;
  }
  if (source.ended) {
    status.state = CellState::kIdle;
    status.state_text = "the source has ended";
    return;
  }
  std::string text = source.stalled ? std::string(kCameraStallReason) : std::string();
  std::string grown;
  for (const FaultTotal& fault : fault_totals()) {
    const std::int64_t added = status.*fault.total - previous.*fault.total;
    if (added <= 0) continue;
    grown += (grown.empty() ? "" : "; ") + std::to_string(added) + ' ' + fault.what;
  }
  if (!grown.empty()) text += (text.empty() ? "" : "; ") + grown + " since the last status";
  status.state = text.empty() ? CellState::kScanning : CellState::kFault;
  status.state_text = text.empty() ? "scanning" : text;
}

}  // namespace cosmos
