#pragma once
// Any ScannerSource with its stream checked profile by profile, as the cell runs every source
// (simulated, hardware twins, hardware, replay): faults the device cannot report are found
// in the data, and those it does report are tied to the profiles they hit.
//   sequence   a seq more than one past the previous one lost the profiles between
//              (profiles_lost: the larger of the gap and what the source reported for the
//              same call, which for a camera are the same frames); a seq that does not
//              increase is a broken stream (recorded, not counted as a loss)
//   encoder    with the belt moving at the config's speed the count advances
//              encoder_ticks_per_profile per profile (per seq step). A step further off than
//              half of that (at least one tick: the readout lag of a free-running camera
//              jitters far less) is an encoder error, unless the decoder counted the missed
//              edges itself (the larger of the two counts, as for frames); a change of the
//              step's sign is a reversal; no step at all is a stuck encoder (encoder_stalls),
//              a fault no decoder can see: its lines are simply quiet
//   laser      a profile without a single point, not even the belt, was taken with the laser
//              off or blocked (laser_off_profiles)
// Every such profile is recorded in faults() for the recognizer (stream_fault_log.hpp).
// next() adds a pass over the profile's points and a few comparisons: no allocation, no
// locks, no exceptions.
#include <cstdint>
#include <memory>

#include "realtime/sources/scanner_source.hpp"
#include "realtime/sources/stream_fault_log.hpp"

namespace cosmos {

class StreamCheckedSource final : public ScannerSource {
 public:
  // encoder_ticks_per_profile: the cell's scanner.encoder_ticks_per_profile (>= 1).
  StreamCheckedSource(std::unique_ptr<ScannerSource> source, int encoder_ticks_per_profile);

  SourceStatus start() override;
  void reserve(Profile& profile) const override { source_->reserve(profile); }
  SourceStatus next(Profile& out) noexcept override;
  void stop() noexcept override { source_->stop(); }

  double mm_per_profile() const override { return source_->mm_per_profile(); }
  std::string_view last_error() const noexcept override { return source_->last_error(); }
  SourceHealth health() const noexcept override;

  const StreamFaultLog& faults() const noexcept { return *faults_; }
  ScannerSource& checked() noexcept { return *source_; }

 private:
  void check(const Profile& profile, const SourceHealth& reported) noexcept;

  std::unique_ptr<ScannerSource> source_;
  std::unique_ptr<StreamFaultLog> faults_;
  std::int64_t ticks_per_profile_ = 1;
  std::int64_t tolerance_ticks_ = 1;
  SourceHealth reported_;  // the source's own health at the last check
  SourceHealth tally_;     // this checker's totals (reported losses merged in)
  bool have_previous_ = false;
  std::uint64_t previous_seq_ = 0;
  std::int64_t previous_ticks_ = 0;
  std::int64_t previous_t_us_ = 0;
  int previous_direction_ = 0;
};

}  // namespace cosmos
