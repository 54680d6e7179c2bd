#pragma once
// The replay source of `cosmos cell --replay LOG`: the log's COSMOS_PROFILE messages on the
// cell config's profile channel, bounded by its scanner's profile width and spaced by its
// belt step (the same in the build with and without the simulator).
#include <memory>
#include <string>

#include "realtime/config/cell_config.hpp"
#include "realtime/sources/replay_source.hpp"

namespace cosmos::cli {

inline std::unique_ptr<ReplaySource> make_cell_replay_source(const std::string& log,
                                                             const CellConfig& config) {
  ReplaySourceSettings settings;
  settings.max_profile_width = static_cast<std::size_t>(config.scanner.points_per_profile);
  settings.mm_per_profile = config.scanner.profile_step_mm();
  settings.channel = config.lcm.profile_channel;
  return std::make_unique<ReplaySource>(log, settings);
}

}  // namespace cosmos::cli
