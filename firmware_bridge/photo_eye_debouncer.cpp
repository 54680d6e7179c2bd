#include "firmware_bridge/photo_eye_debouncer.hpp"

namespace cosmos {

PhotoEyeDebouncer::PhotoEyeDebouncer(const PhotoEyeParameters& parameters)
    : parameters_(parameters) {}

void PhotoEyeDebouncer::reset(bool present, std::int64_t t_ns) noexcept {
  present_ = present;
  raw_ = present;
  seen_edge_ = false;
  last_edge_t_ns_ = t_ns;
  burst_start_t_ns_ = t_ns;
  burst_tag_ = 0;
  counts_ = {};
}

PhotoEyeChange PhotoEyeDebouncer::advance_to(std::int64_t t_ns) noexcept {
  PhotoEyeChange change;
  if (raw_ == present_ || t_ns - last_edge_t_ns_ < parameters_.debounce_ns) return change;
  // Leaving the present state needs a gap of min_off_ns, entering it an interruption of min_on_ns.
  const std::int64_t needed_ns = present_ ? parameters_.min_off_ns : parameters_.min_on_ns;
  if (t_ns - burst_start_t_ns_ < needed_ns) return change;
  present_ = raw_;
  if (present_) ++counts_.parts;
  change = {true, present_, burst_start_t_ns_, burst_tag_};
  return change;
}

PhotoEyeChange PhotoEyeDebouncer::on_edge(bool level, std::int64_t t_ns,
                                          std::int64_t tag) noexcept {
  PhotoEyeChange change = advance_to(t_ns);
  ++counts_.edges;
  if (seen_edge_ && t_ns - last_edge_t_ns_ < parameters_.debounce_ns) {
    ++counts_.bounces;
  } else {
    // A new burst while the previous one is still pending: the previous one did not last.
    if (raw_ != present_) ++(present_ ? counts_.bridged_gaps : counts_.rejected_pulses);
    burst_start_t_ns_ = t_ns;
    burst_tag_ = tag;
  }
  raw_ = level;
  seen_edge_ = true;
  last_edge_t_ns_ = t_ns;
  if (!change.changed) change = advance_to(t_ns);
  return change;
}

}  // namespace cosmos
