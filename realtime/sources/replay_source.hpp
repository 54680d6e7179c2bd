#pragma once
// A recorded scan as a ScannerSource (`--replay FILE`): the range_profile_t events on
// COSMOS_PROFILE (or the configured profile channel) of an lcm-logger log, played in log order with
// their recorded seq, encoder_ticks and t_us, so a recorded run goes through the same downstream
// code as a live one and gives the same result.
//
// start() reads the whole log (set-up, not real-time: it may allocate and take a while), so
// next() only copies a stored profile into the caller's slot. A profile wider than the slot
// (or than max_profile_width) would make the slot allocate: it is skipped and counted in
// health().profiles_lost instead, as a live overload would be; so is a profile event that does not
// decode or is out of bounds. A truncated or damaged log is refused (it would replay as a
// shorter run).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "firmware_bridge/error_line.hpp"
#include "realtime/lcm/lcm_channels.hpp"
#include "realtime/sources/scanner_source.hpp"
#include "scanner/scanner_model.hpp"

namespace cosmos {

struct ReplaySourceSettings {
  // The ring slots' width: the recording cell's points_per_profile.
  std::size_t max_profile_width = static_cast<std::size_t>(ScannerParameters{}.points_per_profile);
  // The recording cell's belt travel per profile (its scanner's profile_step_mm()); a log
  // holds encoder counts but not the millimetres per tick.
  double mm_per_profile = ScannerParameters{}.profile_step_mm();
  std::string channel = kProfileChannel;  // the recording cell's lcm.profile_channel
};

class ReplaySource final : public ScannerSource {
 public:
  explicit ReplaySource(std::filesystem::path log_file, const ReplaySourceSettings& settings = {});

  // Reads the log. kError with one line naming the file when it is missing, not an LCM log,
  // truncated or damaged, or holds no profile at all. Rewinds a
  // replay that was already started.
  SourceStatus start() override;
  void reserve(Profile& profile) const override;
  SourceStatus next(Profile& out) noexcept override;
  void stop() noexcept override { started_ = false; }

  double mm_per_profile() const override { return settings_.mm_per_profile; }
  std::string_view last_error() const noexcept override { return error_.view(); }
  SourceHealth health() const noexcept override { return {.profiles_lost = dropped_}; }

  std::size_t profile_count() const { return profiles_.size(); }

 private:
  std::filesystem::path file_;
  ReplaySourceSettings settings_;
  std::vector<Profile> profiles_;
  std::size_t next_ = 0;
  std::uint64_t dropped_ = 0;
  bool started_ = false;
  ErrorLine error_;
};

}  // namespace cosmos
