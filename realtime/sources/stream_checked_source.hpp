#pragma once
// Any ScannerSource with its stream checked profile by profile, as the cell runs every source
// (simulated, hardware twins, hardware, replay): faults the device cannot report are found
// in the data, and those it does report are tied to the profiles they hit.
//   sequence   a seq more than one past the previous one lost the profiles between
//              (profiles_lost: the larger of the gap and what the source reported for the
//              same call, which for a camera are the same frames); a seq that does not
//              increase is a broken stream (recorded, not counted as a loss)
//   encoder    with the belt moving at the config's speed the count advances
//              encoder_ticks_per_profile per profile (per seq step). The hardware source takes
//              each frame's count at the frame's time stamp, so the step stays even however the
//              frames are delivered, give or take a tick of edge timing: a step further off
//              than encoder_tolerance_profiles profiles' ticks is an encoder error, unless the
//              decoder counted the missed edges itself (then its count is taken, as for
//              frames); a change of the step's sign at belt speed is a reversal. A count that
//              stands still for stuck_profiles profiles in a row (one zero step is jitter) is a
//              stuck encoder, every profile of it in encoder_stalls: a fault no decoder can
//              see, its lines are simply quiet. A source whose counts jitter more needs both
//              wider (the `stream_check:` keys)
//   laser      a profile without a single point, not even the belt, was taken with the laser
//              off or blocked (laser_off_profiles)
// Every such profile is recorded in faults() for the recognizer (stream_fault_log.hpp).
// next() adds a pass over the profile's points and a few comparisons: no allocation, no
// locks, no exceptions.
#include <cstdint>
#include <memory>

#include "core/parameter_visitor.hpp"
#include "realtime/sources/scanner_source.hpp"
#include "realtime/sources/stream_fault_log.hpp"

namespace cosmos {

// The cell's `stream_check:` section.
struct StreamCheckSettings {
  double encoder_tolerance_profiles = 1.0;
  int stuck_profiles = 2;

  template <class Visitor>
  void visit(Visitor& v) {
    v("encoder_tolerance_profiles", encoder_tolerance_profiles,
      "an encoder step further off than this many profiles' ticks is an encoder error",
      Range::above(0, 1e6));
    v("stuck_profiles", stuck_profiles,
      "profiles in a row without an encoder step that make a stuck encoder", Range{2, 1000000});
  }
};

class StreamCheckedSource final : public ScannerSource {
 public:
  // encoder_ticks_per_profile: the cell's scanner.encoder_ticks_per_profile (>= 1).
  StreamCheckedSource(std::unique_ptr<ScannerSource> source, int encoder_ticks_per_profile,
                      const StreamCheckSettings& settings = {});

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
  int stuck_profiles_ = 2;
  SourceHealth reported_;  // the source's own health at the last check
  SourceHealth tally_;     // this checker's totals (reported losses merged in)
  bool have_previous_ = false;
  std::uint64_t previous_seq_ = 0;
  std::int64_t previous_ticks_ = 0;
  int previous_direction_ = 0;
  int zero_steps_ = 0;  // consecutive profiles without an encoder step
  std::uint64_t first_zero_seq_ = 0;
  std::uint64_t first_zero_previous_seq_ = 0;
};

}  // namespace cosmos
