#pragma once
// Writes profiles as range_profile_t events into an LCM log file, as `lcm-logger` records
// them from a cell that publishes COSMOS_PROFILE: the counterpart of LcmLogReader, so a known
// stream can be replayed (ReplaySource, `cosmos cell --replay`) by tests and benches.
#include <filesystem>
#include <span>
#include <string>

#include "core/profile.hpp"
#include "realtime/lcm/lcm_channels.hpp"

namespace cosmos {

// Event numbers count from 0; each event's timestamp is its profile's t_us. Throws
// InputError naming the file when it cannot be created or written.
void write_profile_log(const std::filesystem::path& log_file, std::span<const Profile> profiles,
                       const std::string& channel = kProfileChannel);

}  // namespace cosmos
