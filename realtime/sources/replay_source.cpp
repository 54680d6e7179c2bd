#include "realtime/sources/replay_source.hpp"

#include <algorithm>
#include <exception>
#include <utility>

#include "core/input_error.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/lcm/lcm_log_reader.hpp"

namespace cosmos {

ReplaySource::ReplaySource(std::filesystem::path log_file, const ReplaySourceSettings& settings)
    : file_(std::move(log_file)), settings_(settings) {}

SourceStatus ReplaySource::start() {
  error_.clear();
  started_ = false;
  next_ = 0;
  dropped_ = 0;
  LoggedProfiles logged;
  try {
    logged = read_logged_profiles(file_, settings_.channel, settings_.max_profile_width);
  } catch (const InputError& error) {
    error_.set("%s", error.what());  // already names the file
    return SourceStatus::kError;
  } catch (const std::exception& error) {
    error_.set("%s: %s", file_.c_str(), error.what());
    return SourceStatus::kError;
  }
  profiles_ = std::move(logged.profiles);
  if (logged.damaged_bytes > 0) {
    // A cut or damaged recording loses an unknown number of profiles: a replay of what is
    // left would pass for the whole run.
    error_.set("%s: truncated or damaged at byte %lld (%lld bytes are no whole LCM event)",
               file_.c_str(), static_cast<long long>(logged.first_damage_offset),
               static_cast<long long>(logged.damaged_bytes));
    return SourceStatus::kError;
  }
  // Out-of-bounds profiles are skipped and counted, as a live overload would be.
  dropped_ = static_cast<std::uint64_t>(logged.rejected_profiles);
  if (profiles_.empty()) {
    // An empty replay is a wrong file or channel, never a useful run.
    if (logged.rejected_profiles > 0) {
      error_.set("%s: no %s events to replay (%lld rejected, first: %s)", file_.c_str(),
                 settings_.channel.c_str(), static_cast<long long>(logged.rejected_profiles),
                 logged.first_rejection.c_str());
    } else {
      error_.set("%s: no %s events to replay", file_.c_str(), settings_.channel.c_str());
    }
    return SourceStatus::kError;
  }
  started_ = true;
  return SourceStatus::kOk;
}

void ReplaySource::reserve(Profile& profile) const { profile.reserve(settings_.max_profile_width); }

SourceStatus ReplaySource::next(Profile& out) noexcept {
  if (!started_) {
    error_.set("%s: next() before start()", file_.c_str());
    return SourceStatus::kError;
  }
  while (next_ < profiles_.size()) {
    const Profile& recorded = profiles_[next_++];
    const std::size_t width = recorded.width();
    if (width > settings_.max_profile_width || width > out.z_mm.capacity()) {
      ++dropped_;
      continue;
    }
    out.seq = recorded.seq;
    out.encoder_ticks = recorded.encoder_ticks;
    out.t_us = recorded.t_us;
    out.x0_mm = recorded.x0_mm;
    out.dx_mm = recorded.dx_mm;
    // Within capacity: assign() copies without reallocating.
    out.z_mm.assign(recorded.z_mm.begin(), recorded.z_mm.end());
    return SourceStatus::kOk;
  }
  return SourceStatus::kEndOfStream;
}

}  // namespace cosmos
