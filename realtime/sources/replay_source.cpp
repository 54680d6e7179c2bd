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
  try {
    profiles_ = read_logged_profiles(file_, settings_.channel);
  } catch (const InputError& error) {
    error_.set("%s", error.what());  // already names the file
    return SourceStatus::kError;
  } catch (const std::exception& error) {
    error_.set("%s: %s", file_.c_str(), error.what());
    return SourceStatus::kError;
  }
  if (profiles_.empty()) {
    // An empty replay is a wrong file or channel, never a useful run.
    error_.set("%s: no %s events to replay", file_.c_str(), settings_.channel.c_str());
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
