#include "realtime/lcm/lcm_log_reader.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <lcm/lcm-cpp.hpp>
#include <system_error>

#include "core/input_error.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"

namespace cosmos {

struct LcmLogReader::Messages {
  cosmos_lcm::part_pose_t pose{};
  cosmos_lcm::cell_status_t status{};
  cosmos_lcm::range_profile_t profile{};
};

namespace {

// lcm_eventlog's framing: sync word, event number (8 bytes), timestamp (8), channel length
// (4), data length (4), channel, data; big-endian.
constexpr std::uint32_t kEventSync = 0xEDA1DA01;
constexpr std::int64_t kEventHeaderBytes = 4 + 8 + 8 + 4 + 4;
constexpr std::int32_t kMaxChannelBytes = 1000;  // lcm_eventlog refuses longer

std::int32_t big_endian_int32(const unsigned char* bytes) {
  return static_cast<std::int32_t>((std::uint32_t{bytes[0]} << 24) |
                                   (std::uint32_t{bytes[1]} << 16) |
                                   (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]});
}

}  // namespace

LcmLogReader::LcmLogReader(const std::filesystem::path& log_file, const LcmChannelNames& channels,
                           std::size_t max_profile_width)
    : file_(log_file),
      channels_(channels),
      messages_(std::make_unique<Messages>()),
      max_profile_width_(max_profile_width) {
  std::error_code size_error;
  const std::uintmax_t size = std::filesystem::file_size(log_file, size_error);
  file_size_ = size_error ? 0 : static_cast<std::int64_t>(size);
  errno = 0;
  log_ = std::make_unique<lcm::LogFile>(log_file.string(), "r");
  if (!log_->good()) {
    const int error = errno;
    throw InputError(file_.string() + ": cannot open as an LCM log (" +
                     (error != 0 ? std::strerror(error) : "unknown reason") + ")");
  }
}

LcmLogReader::~LcmLogReader() = default;

void LcmLogReader::record_damage(std::int64_t offset, std::int64_t bytes) {
  if (bytes <= 0) return;
  if (first_damage_offset_ < 0) first_damage_offset_ = offset;
  damaged_bytes_ += bytes;
}

// Leaves the file at the sync word of the next event that lies wholly inside the file, or
// returns false at its end. lcm_eventlog trusts the header's lengths (a data length near
// 2^31 makes it allocate length + 1 bytes in int, which wraps, and read into the null
// pointer it gets back), so every header is checked here before LCM reads it.
bool LcmLogReader::seek_whole_event() {
  std::FILE* file = log_->getFilePtr();
  std::int64_t damage_from = ftello(file);
  std::int64_t position = damage_from;
  for (;;) {
    std::uint32_t word = 0;
    int byte = 0;
    int bytes_seen = 0;
    while ((byte = std::fgetc(file)) != EOF) {
      word = (word << 8) | static_cast<std::uint32_t>(byte);
      ++position;
      if (++bytes_seen >= 4 && word == kEventSync) break;
    }
    if (byte == EOF) {
      record_damage(damage_from, position - damage_from);
      return false;
    }
    const std::int64_t sync_at = position - 4;
    unsigned char header[kEventHeaderBytes - 4];
    const std::size_t got = std::fread(header, 1, sizeof header, file);
    const std::int32_t channel_bytes = big_endian_int32(header + 16);
    const std::int32_t data_bytes = big_endian_int32(header + 20);
    if (got == sizeof header && channel_bytes > 0 && channel_bytes < kMaxChannelBytes &&
        data_bytes >= 0 &&
        sync_at + kEventHeaderBytes + channel_bytes + std::int64_t{data_bytes} <= file_size_) {
      record_damage(damage_from, sync_at - damage_from);
      fseeko(file, sync_at, SEEK_SET);
      return true;
    }
    // Not a whole event: everything from the last good one on is damaged up to the next
    // sync word after this one.
    position = sync_at + 1;
    fseeko(file, position, SEEK_SET);
  }
}

const lcm::LogEvent* LcmLogReader::next_on(const std::string& channel) {
  while (seek_whole_event()) {
    const lcm::LogEvent* event = log_->readNextEvent();
    if (event == nullptr) break;
    ++events_read_;
    if (event->channel == channel) {
      event_timestamp_us_ = event->timestamp;
      return event;
    }
  }
  // The reader skips to the next sync word, so a foreign file reads as an empty log.
  std::error_code error;
  if (events_read_ == 0 && std::filesystem::file_size(file_, error) > 0 && !error) {
    throw InputError(file_.string() + ": not an LCM log (no event found)");
  }
  return nullptr;
}

void LcmLogReader::throw_undecodable(const lcm::LogEvent& event, const char* type_name) const {
  throw InputError(file_.string() + ": event " + std::to_string(event.eventnum) + " on " +
                   event.channel + " does not decode as " + type_name);
}

bool LcmLogReader::next_profile(Profile& profile) {
  while (const lcm::LogEvent* event = next_on(channels_.profile)) {
    cosmos_lcm::range_profile_t& message = messages_->profile;
    const auto size = static_cast<std::size_t>(event->datalen);
    const char* reason = nullptr;
    const std::int64_t width = encoded_profile_width(event->data, size);
    if (width > static_cast<std::int64_t>(max_profile_width_)) {
      reason = "is wider than the profile width";
    } else if (!decode_message(event->data, size, max_profile_width_, message)) {
      reason = "does not decode as range_profile_t";
    } else if (!from_message(message, profile)) {
      reason = "has x0_mm or dx_mm out of range";
    }
    if (reason == nullptr) return true;
    if (rejected_profiles_++ == 0) {
      first_rejection_ =
          "event " + std::to_string(event->eventnum) + " on " + event->channel + " " + reason;
      if (width > static_cast<std::int64_t>(max_profile_width_))
        first_rejection_ +=
            " (" + std::to_string(width) + " > " + std::to_string(max_profile_width_) + ")";
    }
  }
  return false;
}

bool LcmLogReader::next_pose(PartPose& pose) {
  const lcm::LogEvent* event = next_on(channels_.pose);
  if (event == nullptr) return false;
  if (!decode_message(event->data, static_cast<std::size_t>(event->datalen), messages_->pose)) {
    throw_undecodable(*event, "part_pose_t");
  }
  from_message(messages_->pose, pose);
  return true;
}

bool LcmLogReader::next_status(CellStatus& status) {
  const lcm::LogEvent* event = next_on(channels_.status);
  if (event == nullptr) return false;
  if (!decode_message(event->data, static_cast<std::size_t>(event->datalen), messages_->status)) {
    throw_undecodable(*event, "cell_status_t");
  }
  from_message(messages_->status, status);
  return true;
}

namespace {

// Every message of one kind in a log, through the reader's next_* for that kind.
template <class Message>
std::vector<Message> read_all(const std::filesystem::path& log_file,
                              bool (LcmLogReader::*next)(Message&),
                              const LcmChannelNames& channels = {}) {
  LcmLogReader reader(log_file, channels);
  std::vector<Message> messages;
  Message message;
  while ((reader.*next)(message)) messages.push_back(message);
  return messages;
}

}  // namespace

std::vector<Profile> read_logged_profiles(const std::filesystem::path& log_file,
                                          const std::string& channel) {
  LcmChannelNames channels;
  channels.profile = channel;
  return read_all(log_file, &LcmLogReader::next_profile, channels);
}

LoggedProfiles read_logged_profiles(const std::filesystem::path& log_file,
                                    const std::string& channel, std::size_t max_profile_width) {
  LcmChannelNames channels;
  channels.profile = channel;
  LcmLogReader reader(log_file, channels, max_profile_width);
  LoggedProfiles logged;
  Profile profile;
  while (reader.next_profile(profile)) logged.profiles.push_back(profile);
  logged.rejected_profiles = reader.rejected_profiles();
  logged.first_rejection = reader.first_rejection();
  logged.damaged_bytes = reader.damaged_bytes();
  logged.first_damage_offset = reader.first_damage_offset();
  return logged;
}

std::vector<PartPose> read_logged_poses(const std::filesystem::path& log_file) {
  return read_all(log_file, &LcmLogReader::next_pose);
}

std::vector<CellStatus> read_logged_statuses(const std::filesystem::path& log_file) {
  return read_all(log_file, &LcmLogReader::next_status);
}

}  // namespace cosmos
