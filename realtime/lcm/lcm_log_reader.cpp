#include "realtime/lcm/lcm_log_reader.hpp"

#include <cerrno>
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

LcmLogReader::LcmLogReader(const std::filesystem::path& log_file, const LcmChannelNames& channels)
    : file_(log_file), channels_(channels), messages_(std::make_unique<Messages>()) {
  errno = 0;
  log_ = std::make_unique<lcm::LogFile>(log_file.string(), "r");
  if (!log_->good()) {
    const int error = errno;
    throw InputError(file_.string() + ": cannot open as an LCM log (" +
                     (error != 0 ? std::strerror(error) : "unknown reason") + ")");
  }
}

LcmLogReader::~LcmLogReader() = default;

const lcm::LogEvent* LcmLogReader::next_on(const std::string& channel) {
  while (const lcm::LogEvent* event = log_->readNextEvent()) {
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
  const lcm::LogEvent* event = next_on(channels_.profile);
  if (event == nullptr) return false;
  cosmos_lcm::range_profile_t& message = messages_->profile;
  // Generated decode() keeps the old array when width is 0; an empty one keeps its capacity.
  message.z_mm.clear();
  if (!decode_message(event->data, static_cast<std::size_t>(event->datalen), message) ||
      !from_message(message, profile)) {
    throw_undecodable(*event, "range_profile_t");
  }
  return true;
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

std::vector<PartPose> read_logged_poses(const std::filesystem::path& log_file) {
  return read_all(log_file, &LcmLogReader::next_pose);
}

std::vector<CellStatus> read_logged_statuses(const std::filesystem::path& log_file) {
  return read_all(log_file, &LcmLogReader::next_status);
}

}  // namespace cosmos
