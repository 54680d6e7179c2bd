#include "realtime/sources/repeating_source.hpp"

#include <algorithm>
#include <utility>

namespace cosmos {
namespace {

void add(SourceHealth& to, const SourceHealth& more) {
  to.profiles_lost += more.profiles_lost;
  to.camera_timeouts += more.camera_timeouts;
  to.encoder_errors += more.encoder_errors;
  to.encoder_reversals += more.encoder_reversals;
  to.gpio_edges_lost += more.gpio_edges_lost;
  to.photo_eye_bounces += more.photo_eye_bounces;
  to.encoder_stalls += more.encoder_stalls;
  to.laser_off_profiles += more.laser_off_profiles;
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
  return source_->start();
}

SourceHealth RepeatingSource::health() const noexcept {
  SourceHealth health = earlier_;
  add(health, source_->health());
  return health;
}

SourceStatus RepeatingSource::next(Profile& out) noexcept {
  SourceStatus status = source_->next(out);
  if (status == SourceStatus::kEndOfStream && have_last_) {
    add(earlier_, source_->health());
    source_->stop();
    if (source_->start() != SourceStatus::kOk) return SourceStatus::kError;
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
