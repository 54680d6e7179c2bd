#include "tests/hil/fault_plan.hpp"

#include <algorithm>
#include <stdexcept>

namespace cosmos::hil {

FaultPlan plan_faults(const std::string& mode, const TapeHeader& conveyor) {
  FaultPlan plan;
  if (mode == "none") return plan;
  const std::vector<TapePart>& parts = conveyor.parts;
  if (parts.empty()) return plan;
  // The middle of the empty belt after part i (i = -1: before the first).
  const auto gap_middle = [&](int i) -> std::int64_t {
    if (i < 0) return parts.front().first_profile / 2;
    const std::int64_t end = i + 1 < static_cast<int>(parts.size())
                                 ? parts[static_cast<std::size_t>(i) + 1].first_profile
                                 : conveyor.last_profile;
    return (parts[static_cast<std::size_t>(i)].last_profile + end) / 2;
  };
  if (mode == "probe") {
    // All in the conveyor's own lead-in but the stall, which takes a whole gap.
    const std::int64_t lead_in = parts.front().first_profile;
    plan.faults = {{"skip", lead_in * 1 / 6, kSkipFrames},
                   {"jiggle", lead_in * 2 / 6, 3},
                   {"glitch", lead_in * 3 / 6, 0},
                   {"corrupt", lead_in * 4 / 6, 0},
                   {"stall", gap_middle(0), kStallMs}};
    plan.bouncing_arrivals = {parts.size() > 1 ? 1u : 0u};
    return plan;
  }
  if (mode != "cell") throw std::invalid_argument("unknown fault plan \"" + mode + "\"");
  const std::vector<FaultAt> in_order = {{"skip", 0, kSkipFrames},
                                         {"jiggle", 0, 3},
                                         {"glitch", 0, 0},
                                         {"stall", 0, kCellStallMs},
                                         {"corrupt", 0, 0}};
  // Gaps after part 0, 1, …: one fault each, the last gap before the end left quiet.
  const int gaps = static_cast<int>(parts.size()) - 1;
  for (int i = 0; i < gaps && i < static_cast<int>(in_order.size()); ++i) {
    FaultAt fault = in_order[static_cast<std::size_t>(i)];
    fault.profile = gap_middle(i);
    plan.faults.push_back(fault);
  }
  if (parts.size() > 2) plan.bouncing_arrivals = {parts.size() / 2};
  return plan;
}

}  // namespace cosmos::hil
