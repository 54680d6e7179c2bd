#pragma once
// Reads an lcm-logger log file back into the project's structs: COSMOS_PROFILE events as
// Profiles (so a recorded scan replays through the same code as a live scanner) and
// COSMOS_POSE / COSMOS_STATUS events as PartPose / CellStatus (tests, offline checks).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/profile.hpp"
#include "realtime/cell/cell_status.hpp"
#include "realtime/cell/part_pose.hpp"
#include "realtime/lcm/lcm_channels.hpp"

namespace lcm {
class LogFile;
struct LogEvent;
}  // namespace lcm

namespace cosmos {

class LcmLogReader {
 public:
  // Throws InputError naming the file when it cannot be opened.
  explicit LcmLogReader(const std::filesystem::path& log_file,
                        const LcmChannelNames& channels = {});
  ~LcmLogReader();
  LcmLogReader(const LcmLogReader&) = delete;
  LcmLogReader& operator=(const LcmLogReader&) = delete;

  // Each reads forward to the next event on its channel, skipping the others, and returns
  // false at the end of the log. One reader reads one stream: to read two channels, open
  // two readers. An event on the channel that does not decode as its type, or a non-empty
  // file without a single LCM event, throws InputError naming the file and event number.
  bool next_profile(Profile& profile);  // reuses profile's storage (replay keeps one)
  bool next_pose(PartPose& pose);
  bool next_status(CellStatus& status);

  // When lcm-logger received the event last returned, microseconds since the Unix epoch.
  std::int64_t event_timestamp_us() const { return event_timestamp_us_; }

 private:
  struct Messages;  // generated message types, reused

  const lcm::LogEvent* next_on(const std::string& channel);
  [[noreturn]] void throw_undecodable(const lcm::LogEvent& event, const char* type_name) const;

  std::filesystem::path file_;
  LcmChannelNames channels_;
  std::unique_ptr<lcm::LogFile> log_;
  std::unique_ptr<Messages> messages_;
  std::int64_t events_read_ = 0;
  std::int64_t event_timestamp_us_ = 0;
};

// Whole-log conveniences.
std::vector<Profile> read_logged_profiles(const std::filesystem::path& log_file,
                                          const std::string& channel = kProfileChannel);
std::vector<PartPose> read_logged_poses(const std::filesystem::path& log_file);
std::vector<CellStatus> read_logged_statuses(const std::filesystem::path& log_file);

}  // namespace cosmos
