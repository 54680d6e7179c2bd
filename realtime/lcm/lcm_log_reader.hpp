#pragma once
// Reads an lcm-logger log file back into the project's structs: COSMOS_PROFILE events as
// Profiles (so a recorded scan replays through the same code as a live scanner) and
// COSMOS_POSE / COSMOS_STATUS events as PartPose / CellStatus (tests, offline checks).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/profile.hpp"
#include "realtime/cell/cell_status.hpp"
#include "realtime/cell/part_pose.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"

namespace lcm {
class LogFile;
struct LogEvent;
}  // namespace lcm

namespace cosmos {

class LcmLogReader {
 public:
  // Throws InputError naming the file when it cannot be opened. Profiles wider than
  // max_profile_width are rejected (the recording cell's points_per_profile).
  explicit LcmLogReader(const std::filesystem::path& log_file, const LcmChannelNames& channels = {},
                        std::size_t max_profile_width = kMaxProfileWidth);
  ~LcmLogReader();
  LcmLogReader(const LcmLogReader&) = delete;
  LcmLogReader& operator=(const LcmLogReader&) = delete;

  // Each reads forward to the next event on its channel, skipping the others, and returns
  // false at the end of the log. One reader reads one stream: to read two channels, open
  // two readers. An event on the channel that does not decode as its type, or a non-empty
  // file without a single LCM event, throws InputError naming the file and event number;
  // next_profile instead skips and counts a profile that does not decode or is out of
  // bounds (one bad datagram in a recording is not a bad recording).
  bool next_profile(Profile& profile);  // reuses profile's storage (replay keeps one)
  bool next_pose(PartPose& pose);
  bool next_status(CellStatus& status);

  // When lcm-logger received the event last returned, microseconds since the Unix epoch.
  std::int64_t event_timestamp_us() const { return event_timestamp_us_; }

  // Profile events skipped by next_profile, and why the first one was.
  std::int64_t rejected_profiles() const { return rejected_profiles_; }
  const std::string& first_rejection() const { return first_rejection_; }

  // Bytes that are not part of a whole event (a truncated last event, a damaged header, junk
  // between events), and the offset of the first: the reader skips them, resynchronizing on
  // the next event's sync word, and never hands LCM a header that claims more than the file.
  std::int64_t damaged_bytes() const { return damaged_bytes_; }
  std::int64_t first_damage_offset() const { return first_damage_offset_; }

 private:
  struct Messages;  // generated message types, reused

  const lcm::LogEvent* next_on(const std::string& channel);
  bool seek_whole_event();
  void record_damage(std::int64_t offset, std::int64_t bytes);
  [[noreturn]] void throw_undecodable(const lcm::LogEvent& event, const char* type_name) const;

  std::filesystem::path file_;
  LcmChannelNames channels_;
  std::unique_ptr<lcm::LogFile> log_;
  std::unique_ptr<Messages> messages_;
  std::int64_t events_read_ = 0;
  std::int64_t event_timestamp_us_ = 0;
  std::size_t max_profile_width_;
  std::int64_t file_size_ = 0;
  std::int64_t rejected_profiles_ = 0;
  std::string first_rejection_;
  std::int64_t damaged_bytes_ = 0;
  std::int64_t first_damage_offset_ = -1;
};

// Whole-log conveniences.
std::vector<Profile> read_logged_profiles(const std::filesystem::path& log_file,
                                          const std::string& channel = kProfileChannel);
// As above, and the reader's counts once the log is read.
struct LoggedProfiles {
  std::vector<Profile> profiles;
  std::int64_t rejected_profiles = 0;
  std::string first_rejection;
  std::int64_t damaged_bytes = 0;
  std::int64_t first_damage_offset = -1;
};
LoggedProfiles read_logged_profiles(const std::filesystem::path& log_file,
                                    const std::string& channel, std::size_t max_profile_width);
std::vector<PartPose> read_logged_poses(const std::filesystem::path& log_file);
std::vector<CellStatus> read_logged_statuses(const std::filesystem::path& log_file);

}  // namespace cosmos
