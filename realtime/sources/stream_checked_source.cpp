#include "realtime/sources/stream_checked_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace cosmos {
namespace {

bool has_laser_point(const Profile& profile) noexcept {
  for (const float z : profile.z_mm)
    if (std::isfinite(z)) return true;
  return false;
}

std::uint64_t increase(std::uint64_t now, std::uint64_t before) {
  return now > before ? now - before : 0;
}

}  // namespace

StreamCheckedSource::StreamCheckedSource(std::unique_ptr<ScannerSource> source,
                                         int encoder_ticks_per_profile,
                                         const StreamCheckSettings& settings)
    : source_(std::move(source)),
      faults_(std::make_unique<StreamFaultLog>()),
      ticks_per_profile_(std::max(encoder_ticks_per_profile, 1)),
      tolerance_ticks_(
          std::max<std::int64_t>(1, std::llround(settings.encoder_tolerance_profiles *
                                                 static_cast<double>(ticks_per_profile_)))),
      stuck_profiles_(std::max(settings.stuck_profiles, 2)) {}

SourceStatus StreamCheckedSource::start() {
  const SourceStatus status = source_->start();
  faults_->clear();
  have_previous_ = false;
  previous_direction_ = 0;
  zero_steps_ = 0;
  // What the source found while starting (a replay's undecodable events) is its own count.
  reported_ = source_->health();
  tally_ = reported_;
  return status;
}

SourceHealth StreamCheckedSource::health() const noexcept {
  SourceHealth health = source_->health();
  health.profiles_lost = tally_.profiles_lost;
  health.encoder_errors = tally_.encoder_errors;
  health.encoder_reversals = tally_.encoder_reversals;
  health.encoder_stalls = tally_.encoder_stalls;
  health.laser_off_profiles = tally_.laser_off_profiles;
  return health;
}

SourceStatus StreamCheckedSource::next(Profile& out) noexcept {
  const SourceStatus status = source_->next(out);
  if (status == SourceStatus::kOk) check(out, source_->health());
  return status;
}

void StreamCheckedSource::check(const Profile& profile, const SourceHealth& reported) noexcept {
  const std::uint64_t reported_lost = increase(reported.profiles_lost, reported_.profiles_lost);
  const std::uint64_t reported_errors = increase(reported.encoder_errors, reported_.encoder_errors);
  const std::uint64_t reported_reversals =
      increase(reported.encoder_reversals, reported_.encoder_reversals);
  reported_ = reported;
  tally_.encoder_errors += reported_errors;
  tally_.encoder_reversals += reported_reversals;

  const std::uint64_t seq = profile.seq;
  const std::uint64_t previous_seq = have_previous_ ? previous_seq_ : seq;
  std::uint64_t gap = 0;
  bool broken_sequence = false;
  bool encoder_jump = reported_errors > 0 || reported_reversals > 0;
  bool encoder_stuck = false;
  if (have_previous_) {
    broken_sequence = seq <= previous_seq_;
    gap = broken_sequence ? 0 : seq - previous_seq_ - 1;
    const std::int64_t steps = broken_sequence ? 1 : static_cast<std::int64_t>(seq - previous_seq_);
    const std::int64_t step = profile.encoder_ticks - previous_ticks_;
    const std::int64_t expected = ticks_per_profile_ * steps;
    if (step == 0 && !encoder_jump) {
      if (++zero_steps_ == 1) {
        first_zero_seq_ = seq;
        first_zero_previous_seq_ = previous_seq;
      } else if (zero_steps_ >= stuck_profiles_) {
        encoder_stuck = true;
        if (zero_steps_ == stuck_profiles_) {  // the zero steps before were the fault, not jitter
          tally_.encoder_stalls += static_cast<std::uint64_t>(stuck_profiles_ - 1);
          faults_->record(StreamFaultKind::kEncoderStuck, first_zero_previous_seq_,
                          first_zero_seq_);
        }
        ++tally_.encoder_stalls;
      }
    } else if (std::llabs(step - expected) > tolerance_ticks_) {
      if (!encoder_jump) ++tally_.encoder_errors;
      encoder_jump = true;
    }
    if (step != 0 || encoder_jump) zero_steps_ = 0;
    // Only a step the belt could make either way turns the direction: a spike is no reversal.
    const int direction = std::llabs(step) > expected + tolerance_ticks_ ? 0
                          : step > 0                                     ? 1
                          : step < 0                                     ? -1
                                                                         : 0;
    if (direction != 0) {
      if (previous_direction_ != 0 && direction != previous_direction_ && reported_reversals == 0)
        ++tally_.encoder_reversals;
      previous_direction_ = direction;
    }
  }
  tally_.profiles_lost += std::max(gap, reported_lost);
  if (gap > 0 || reported_lost > 0 || broken_sequence)
    faults_->record(StreamFaultKind::kSequenceGap, previous_seq, seq);
  if (encoder_jump) faults_->record(StreamFaultKind::kEncoderJump, previous_seq, seq);
  if (encoder_stuck) faults_->record(StreamFaultKind::kEncoderStuck, previous_seq, seq);
  if (!has_laser_point(profile)) {
    ++tally_.laser_off_profiles;
    faults_->record(StreamFaultKind::kLaserOff, previous_seq, seq);
  }
  have_previous_ = true;
  previous_seq_ = seq;
  previous_ticks_ = profile.encoder_ticks;
}

}  // namespace cosmos
