#include "firmware_bridge/encoder_history.hpp"

#include <algorithm>

namespace cosmos {

void EncoderHistory::reset(std::int64_t ticks, std::int64_t t_ns) noexcept {
  first_ = 0;
  count_ = 0;
  origin_ = {t_ns, ticks};
}

void EncoderHistory::record(std::int64_t t_ns, std::int64_t ticks) noexcept {
  const std::int64_t latest_ns = count_ > 0 ? step(count_ - 1).t_ns : origin_.t_ns;
  if (count_ == kCapacity) {
    // The oldest step becomes the origin: its count held from its time until the next step.
    origin_ = steps_[first_];
    first_ = (first_ + 1) % kCapacity;
    --count_;
  }
  steps_[(first_ + count_) % kCapacity] = {std::max(t_ns, latest_ns), ticks};
  ++count_;
}

EncoderHistory::Count EncoderHistory::ticks_at(std::int64_t t_ns) const noexcept {
  if (t_ns < origin_.t_ns) return {origin_.ticks, false};
  // The first kept step stamped after t_ns: the count before it is the answer.
  std::size_t low = 0;
  std::size_t high = count_;
  while (low < high) {
    const std::size_t middle = low + (high - low) / 2;
    if (step(middle).t_ns <= t_ns) {
      low = middle + 1;
    } else {
      high = middle;
    }
  }
  return {low == 0 ? origin_.ticks : step(low - 1).ticks, true};
}

}  // namespace cosmos
