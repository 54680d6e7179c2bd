#include "realtime/lcm/profile_log_writer.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <lcm/lcm-cpp.hpp>
#include <vector>

#include "core/input_error.hpp"
#include "realtime/lcm/lcm_codec.hpp"
#include "realtime/lcm/lcm_message_conversion.hpp"

namespace cosmos {

void write_profile_log(const std::filesystem::path& log_file, std::span<const Profile> profiles,
                       const std::string& channel) {
  errno = 0;
  lcm::LogFile log(log_file.string(), "w");
  if (!log.good()) {
    const int error = errno;
    throw InputError(log_file.string() + ": cannot create an LCM log (" +
                     (error != 0 ? std::strerror(error) : "unknown reason") + ")");
  }
  std::vector<std::uint8_t> bytes;
  std::int64_t event_number = 0;
  for (const Profile& profile : profiles) {
    cosmos_lcm::range_profile_t message{};
    to_message(profile, message);
    if (!encode_message(message, bytes))
      throw InputError(log_file.string() + ": profile " + std::to_string(profile.seq) +
                       " does not encode as range_profile_t");
    lcm::LogEvent event;
    event.eventnum = event_number++;
    event.timestamp = profile.t_us;
    event.channel = channel;
    event.datalen = static_cast<std::int32_t>(bytes.size());
    event.data = bytes.data();
    if (log.writeEvent(&event) != 0)
      throw InputError(log_file.string() + ": cannot write event " +
                       std::to_string(event.eventnum));
  }
}

}  // namespace cosmos
