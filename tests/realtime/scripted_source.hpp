#pragma once
// A ScannerSource that hands out a fixed list of profiles (and a fixed health), for the tests
// of what wraps a source: the stream checker, the repeating source.
#include <cstdint>
#include <utility>
#include <vector>

#include "realtime/sources/scanner_source.hpp"

namespace cosmos::testing {

class ScriptedSource final : public ScannerSource {
 public:
  explicit ScriptedSource(std::vector<Profile> profiles) : profiles_(std::move(profiles)) {}

  SourceStatus start() override {
    next_ = 0;
    ++starts;
    return SourceStatus::kOk;
  }
  void reserve(Profile& profile) const override { profile.reserve(kWidth); }
  SourceStatus next(Profile& out) noexcept override {
    if (next_ >= profiles_.size()) return SourceStatus::kEndOfStream;
    const Profile& from = profiles_[next_++];
    out.seq = from.seq;
    out.encoder_ticks = from.encoder_ticks;
    out.t_us = from.t_us;
    out.x0_mm = from.x0_mm;
    out.dx_mm = from.dx_mm;
    out.z_mm.assign(from.z_mm.begin(), from.z_mm.end());
    if (next_ == lose_at) health_now.profiles_lost += lost_reported;
    return SourceStatus::kOk;
  }
  void stop() noexcept override {}
  double mm_per_profile() const override { return 0.4; }
  std::string_view last_error() const noexcept override { return {}; }
  SourceHealth health() const noexcept override { return health_now; }

  static constexpr std::size_t kWidth = 8;
  SourceHealth health_now;
  std::size_t lose_at = 0;  // after this many profiles, report lost_reported more lost
  std::uint64_t lost_reported = 0;
  int starts = 0;

 private:
  std::vector<Profile> profiles_;
  std::size_t next_ = 0;
};

// Profile k of a belt at 4 ticks per profile, 400 us apart, with the belt lit.
inline Profile belt_profile(std::uint64_t seq) {
  Profile profile;
  profile.seq = seq;
  profile.encoder_ticks = static_cast<std::int64_t>(seq) * 4;
  profile.t_us = static_cast<std::int64_t>(seq) * 400;
  profile.x0_mm = -1;
  profile.dx_mm = 0.25;
  profile.z_mm.assign(ScriptedSource::kWidth, 0.0f);
  return profile;
}

inline std::vector<Profile> belt_profiles(int count) {
  std::vector<Profile> profiles;
  for (int k = 0; k < count; ++k) profiles.push_back(belt_profile(static_cast<std::uint64_t>(k)));
  return profiles;
}

}  // namespace cosmos::testing
