#pragma once
// Where a source's stream broke, for the recognizer: the profiles at which the stream checker
// (stream_checked_source.hpp) found frames lost, an encoder step that the belt cannot have
// made, a stuck encoder or a profile without laser light. A part whose rows span one of them
// has rows missing or a wrong encoder count at its last row (its pose's position), so it is
// published as ERROR with the reason instead of as a pose nobody can trust.
//
// Each fault is placed where it happened, by sequence number: lost frames at the frames
// between the profile before the gap and the one after it, the others at their profile. A
// part has three extents (PartProfileSpan): its first row, its last row with data, and the
// last row the loop added to it, which lies up to tracking.link_gap_rows of empty belt later
// (the tracker completes a part only then). The pose holds at the last row with data (its
// count and time are that row's), so nothing in those empty rows is the part's fault: frames
// lost there took nothing of it, and an encoder fault there moves neither its rows nor its
// count.
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

// A part's rows by the sequence numbers of their profiles.
struct PartProfileSpan {
  std::uint64_t first_seq = 0;      // its first row
  std::uint64_t last_data_seq = 0;  // its last row with data of it: its pose's encoder count
  std::uint64_t last_seq = 0;       // the last row added to it
};

class StreamFaultLog {
 public:
  static constexpr std::size_t kCapacity = 4096;

  // Writer side, with no reader running (the source's start()).
  void clear() noexcept;
  // Writer: a fault at profile `seq`, whose predecessor in the stream was profile
  // previous_seq (for kSequenceGap: the frames between the two were lost).
  void record(StreamFaultKind kind, std::uint64_t previous_seq, std::uint64_t seq) noexcept;

  // Any thread: a fault touching the part's rows (the latest), kNone if there is none.
  //   frames lost   the lost frames lie among the part's rows with data or right next to
  //                 them (a lost frame beside its first or last row may have held more of it)
  //   encoder       its profile is a row after the first, up to last_data_seq (rows before
  //                 it are fine: the count that positions the part is last_data_seq's)
  //   laser off     its profile is a row with data or right next to them (the dark profile
  //                 cut the part short)
  StreamFaultKind fault_in(const PartProfileSpan& rows) const noexcept;
  std::uint64_t recorded() const noexcept { return count_.load(std::memory_order_acquire); }

 private:
  struct Entry {
    std::atomic<std::uint8_t> kind{0};
    std::atomic<std::uint64_t> previous_seq{0};
    std::atomic<std::uint64_t> seq{0};
  };

  std::array<Entry, kCapacity> entries_{};
  std::atomic<std::uint64_t> count_{0};
};

}  // namespace cosmos
