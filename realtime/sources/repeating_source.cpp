#include "realtime/sources/repeating_source.hpp"

#include <algorithm>
#include <utility>

namespace cosmos {
namespace {

// to += now − since, field by field: what a pass added, whether the source's counts restart
// with it (the simulated source's) or run on over restarts (a camera's statistics).
void add_since(SourceHealth& to, const SourceHealth& now, const SourceHealth& since) {
  const auto added = [](std::uint64_t a, std::uint64_t b) { return a > b ? a - b : 0; };
  to.profiles_lost += added(now.profiles_lost, since.profiles_lost);
  to.camera_timeouts += added(now.camera_timeouts, since.camera_timeouts);
  to.encoder_errors += added(now.encoder_errors, since.encoder_errors);
  to.encoder_reversals += added(now.encoder_reversals, since.encoder_reversals);
  to.gpio_edges_lost += added(now.gpio_edges_lost, since.gpio_edges_lost);
  to.photo_eye_bounces += added(now.photo_eye_bounces, since.photo_eye_bounces);
  to.encoder_stalls += added(now.encoder_stalls, since.encoder_stalls);
  to.laser_off_profiles += added(now.laser_off_profiles, since.laser_off_profiles);
  to.encoder_counts_unsettled +=
      added(now.encoder_counts_unsettled, since.encoder_counts_unsettled);
}

}  // namespace

RepeatingSource::RepeatingSource(std::unique_ptr<ScannerSource> source,
                                 int encoder_ticks_per_profile, std::int64_t profile_period_us)
    : source_(std::move(source)),
      ticks_per_profile_(std::max(encoder_ticks_per_profile, 1)),
      period_us_(std::max<std::int64_t>(profile_period_us, 1)) {}

SourceStatus RepeatingSource::start() {
  passes_ = 0;
  have_last_ = false;
  seq_offset_ = 0;
  ticks_offset_ = 0;
  t_offset_us_ = 0;
  earlier_ = {};
  const SourceStatus status = source_->start();
  at_pass_start_ = source_->health();
  return status;
}

SourceHealth RepeatingSource::health() const noexcept {
  SourceHealth health = earlier_;
  add_since(health, source_->health(), at_pass_start_);
  return health;
}

SourceStatus RepeatingSource::next(Profile& out) noexcept {
  SourceStatus status = source_->next(out);
  if (status == SourceStatus::kEndOfStream && have_last_) {
    add_since(earlier_, source_->health(), at_pass_start_);
    source_->stop();
    if (source_->start() != SourceStatus::kOk) return SourceStatus::kError;
    at_pass_start_ = source_->health();
    ++passes_;
    seq_offset_ = last_seq_ + 1;
    ticks_offset_ = last_ticks_ + ticks_per_profile_;
    t_offset_us_ = last_t_us_ + period_us_;
    status = source_->next(out);
  }
  if (status != SourceStatus::kOk) return status;
  out.seq += seq_offset_;
  out.encoder_ticks += ticks_offset_;
  out.t_us += t_offset_us_;
  have_last_ = true;
  last_seq_ = out.seq;
  last_ticks_ = out.encoder_ticks;
  last_t_us_ = out.t_us;
  return status;
}

}  // namespace cosmos
