#include "realtime/sources/stream_fault_log.hpp"

namespace cosmos {

const char* to_string(StreamFaultKind kind) {
  switch (kind) {
    case StreamFaultKind::kNone:
      return "none";
    case StreamFaultKind::kSequenceGap:
      return "frames lost";
    case StreamFaultKind::kEncoderJump:
      return "encoder jump";
    case StreamFaultKind::kEncoderStuck:
      return "encoder stuck";
    case StreamFaultKind::kLaserOff:
      return "laser off";
    case StreamFaultKind::kUnchecked:
      return "too many stream faults to check";
  }
  return "unknown stream fault";
}

void StreamFaultLog::clear() noexcept { count_.store(0, std::memory_order_release); }

void StreamFaultLog::record(StreamFaultKind kind, std::uint64_t previous_seq,
                            std::uint64_t seq) noexcept {
  const std::uint64_t index = count_.load(std::memory_order_relaxed);
  Entry& entry = entries_[index % kCapacity];
  entry.kind.store(static_cast<std::uint8_t>(kind), std::memory_order_relaxed);
  entry.previous_seq.store(previous_seq, std::memory_order_relaxed);
  entry.seq.store(seq, std::memory_order_relaxed);
  count_.store(index + 1, std::memory_order_release);
}

namespace {

bool touches(StreamFaultKind kind, std::uint64_t previous_seq, std::uint64_t seq,
             const PartProfileSpan& rows) {
  const bool after_first = seq > rows.first_seq;
  switch (kind) {
    case StreamFaultKind::kSequenceGap:
      // Lost: the frames after previous_seq and before seq, beside or among the data rows.
      if (seq > previous_seq) return previous_seq <= rows.last_data_seq && seq >= rows.first_seq;
      return after_first && seq <= rows.last_data_seq;  // the sequence went backwards here
    case StreamFaultKind::kLaserOff:
      return seq + 1 >= rows.first_seq && seq <= rows.last_data_seq + 1;
    default:
      return after_first && seq <= rows.last_data_seq;
  }
}

}  // namespace

StreamFaultKind StreamFaultLog::fault_in(const PartProfileSpan& rows) const noexcept {
  const std::uint64_t count = count_.load(std::memory_order_acquire);
  const std::uint64_t oldest = count > kCapacity ? count - kCapacity : 0;
  StreamFaultKind found = StreamFaultKind::kNone;
  std::uint64_t lowest_read = count;
  bool reached_older = false;
  for (std::uint64_t i = count; i-- > oldest;) {
    const Entry& entry = entries_[i % kCapacity];
    const auto kind = static_cast<StreamFaultKind>(entry.kind.load(std::memory_order_relaxed));
    const std::uint64_t previous_seq = entry.previous_seq.load(std::memory_order_relaxed);
    const std::uint64_t seq = entry.seq.load(std::memory_order_relaxed);
    lowest_read = i;
    if (seq + 1 < rows.first_seq) {
      reached_older = true;  // entries are in stream order: the rest are older still
      break;
    }
    if (touches(kind, previous_seq, seq, rows)) found = kind;
  }
  // Entries overwritten while they were read, or gone before the part's first row.
  const std::uint64_t now = count_.load(std::memory_order_acquire);
  const bool torn = now > kCapacity && now - kCapacity > lowest_read;
  if (torn || (!reached_older && oldest > 0)) return StreamFaultKind::kUnchecked;
  return found;
}

}  // namespace cosmos
