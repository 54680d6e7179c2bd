#pragma once
// The encoder count as it stood at any recent instant, so that a frame gets the count of its
// own time stamp rather than the count when it happened to be dequeued. A free-running camera
// hands its frames over in bursts (the driver's queue, a loop held up by recognition): counts
// read at dequeue jitter with the delivery, while the belt under the laser moved evenly.
//
// The decoder records every count it makes with the time stamp of the edge that made it; a
// fixed ring keeps the latest kCapacity of them. ticks_at(t) is the count after every step
// stamped at or before t. An instant older than the ring reaches back to is answered with the
// oldest count kept, and said to be so.
//
// Real-time: fixed storage, no allocation, no exceptions.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace cosmos {

class EncoderHistory {
 public:
  // At 10,000 counts a second (2,500 profiles/s, 4 counts each) 0.4 s of belt: far more than
  // the frames a camera's queue holds.
  static constexpr std::size_t kCapacity = 4096;
  static constexpr std::int64_t kSinceEver = std::numeric_limits<std::int64_t>::min();

  // The count is `ticks` from t_ns on (kSinceEver: from any time).
  void reset(std::int64_t ticks, std::int64_t t_ns = kSinceEver) noexcept;
  // A count made by an edge stamped t_ns. Steps come in time order; one stamped before the
  // latest (a debounced edge settled late) is kept at the latest's time.
  void record(std::int64_t t_ns, std::int64_t ticks) noexcept;

  struct Count {
    std::int64_t ticks = 0;
    bool covered = false;  // false: t_ns lies before the kept history (the oldest count given)
  };
  Count ticks_at(std::int64_t t_ns) const noexcept;

  std::size_t size() const noexcept { return count_; }

 private:
  struct Step {
    std::int64_t t_ns = 0;
    std::int64_t ticks = 0;
  };
  const Step& step(std::size_t k) const noexcept { return steps_[(first_ + k) % kCapacity]; }

  std::array<Step, kCapacity> steps_{};
  std::size_t first_ = 0;
  std::size_t count_ = 0;
  Step origin_{kSinceEver, 0};  // the count from origin_.t_ns until the oldest kept step
};

}  // namespace cosmos
