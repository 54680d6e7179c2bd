#pragma once
// A finite source played again and again as one endless stream (`cosmos cell --repeat`, the
// soak run of scripts/soak.sh): when the source ends it is restarted, and its seq,
// encoder_ticks and t_us go on from where the last pass ended, one profile step later, so
// the cell sees a belt that never stops rather than a stream that jumps back. Its health
// adds up what each pass added, whether the source's counts restart with it or not.
//
// The restart runs on the acquisition thread and is the source's start(): set-up that may
// allocate, once per pass (seconds apart), never per profile.
#include <cstdint>
#include <memory>

#include "realtime/sources/scanner_source.hpp"

namespace cosmos {

class RepeatingSource final : public ScannerSource {
 public:
  // encoder_ticks_per_profile and profile_period_us: one profile's step, added between passes.
  RepeatingSource(std::unique_ptr<ScannerSource> source, int encoder_ticks_per_profile,
                  std::int64_t profile_period_us);

  SourceStatus start() override;
  void reserve(Profile& profile) const override { source_->reserve(profile); }
  SourceStatus next(Profile& out) noexcept override;
  void stop() noexcept override { source_->stop(); }

  double mm_per_profile() const override { return source_->mm_per_profile(); }
  std::string_view last_error() const noexcept override { return source_->last_error(); }
  SourceHealth health() const noexcept override;

  std::uint64_t passes() const noexcept { return passes_; }
  ScannerSource& repeated() noexcept { return *source_; }

 private:
  std::unique_ptr<ScannerSource> source_;
  std::int64_t ticks_per_profile_ = 4;
  std::int64_t period_us_ = 400;
  std::uint64_t passes_ = 0;
  bool have_last_ = false;
  std::uint64_t last_seq_ = 0;  // the stream as the cell saw it
  std::int64_t last_ticks_ = 0;
  std::int64_t last_t_us_ = 0;
  std::uint64_t seq_offset_ = 0;
  std::int64_t ticks_offset_ = 0;
  std::int64_t t_offset_us_ = 0;
  SourceHealth earlier_;        // what the passes before this one added
  SourceHealth at_pass_start_;  // the source's health when this pass began
};

}  // namespace cosmos
