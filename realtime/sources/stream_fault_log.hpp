#pragma once
// Where a source's stream broke, for the recognizer: the profiles at which the stream checker
// (stream_checked_source.hpp) found frames lost, an encoder step that the belt cannot have
// made, a stuck encoder or a profile without laser light. A part whose rows span one of them
// has rows missing or a wrong encoder count at its last row (its pose's position), so it is
// published as ERROR with the reason instead of as a pose nobody can trust.
//
// One writer (the acquisition thread) and any readers (the recognizer): a ring of the last
// kCapacity faults in atomics, the count published with release after each entry. A part
// completes after its last row was checked and reaches the recognizer through an acquiring
// ring, so every fault up to its last row is visible to whoever recognizes it. When the ring
// has wrapped past a part's rows (or wraps while being read), the part is reported as
// unchecked rather than as clean. No allocation, no locks, no exceptions.
#include <array>
#include <atomic>
#include <cstdint>

namespace cosmos {

enum class StreamFaultKind : std::uint8_t {
  kNone = 0,
  kSequenceGap,   // profiles lost before this one, or a sequence that went backwards
  kEncoderJump,   // the count moved other than the belt can (glitch, reversal, jump)
  kEncoderStuck,  // the count did not move while the belt did
  kLaserOff,      // no laser point at all in this profile
  kUnchecked,     // more faults than the log holds since the part began
};

// "frames lost", "encoder jump", ... for a pose's reason.
const char* to_string(StreamFaultKind kind);

class StreamFaultLog {
 public:
  static constexpr std::size_t kCapacity = 4096;

  // Writer side, with no reader running (the source's start()).
  void clear() noexcept;
  // Writer: profile `seq`, exposed at t_us, whose predecessor was exposed at t_before_us.
  void record(StreamFaultKind kind, std::uint64_t seq, std::int64_t t_before_us,
              std::int64_t t_us) noexcept;

  // Any thread: the first fault touching the rows of a part whose first row is profile
  // first_seq and whose last row was exposed at last_t_us, kNone if there is none. A fault
  // touches a part when its profile is one of the part's rows after the first (rows before
  // it are fine: the encoder count that positions the part is its last row's); laser off
  // also when it is the profile right before or right after the part (the dark profile cut
  // the part short).
  StreamFaultKind fault_in(std::uint64_t first_seq, std::int64_t last_t_us) const noexcept;
  std::uint64_t recorded() const noexcept { return count_.load(std::memory_order_acquire); }

 private:
  struct Entry {
    std::atomic<std::uint8_t> kind{0};
    std::atomic<std::uint64_t> seq{0};
    std::atomic<std::int64_t> t_before_us{0};
    std::atomic<std::int64_t> t_us{0};
  };

  std::array<Entry, kCapacity> entries_{};
  std::atomic<std::uint64_t> count_{0};
};

}  // namespace cosmos
