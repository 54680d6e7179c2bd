#pragma once
// Runs a started ScannerSource the way the acquisition loop does (one reserved slot, next()
// until it stops giving profiles) and keeps what came out, with the heap allocations made
// inside next(): the real-time contract every source must keep.
#include <cstdint>
#include <vector>

#include "realtime/sources/scanner_source.hpp"
#include "tests/common/allocation_counter.hpp"

namespace cosmos::testing {

struct SourceStream {
  std::vector<Profile> profiles;
  SourceStatus end = SourceStatus::kOk;  // the status that ended the stream
  std::uint64_t allocations_in_next = 0;
};

inline SourceStream read_stream(ScannerSource& source) {
  SourceStream stream;
  Profile slot;
  source.reserve(slot);
  for (;;) {
    const std::uint64_t before = test::allocations_on_this_thread();
    stream.end = source.next(slot);
    stream.allocations_in_next += test::allocations_on_this_thread() - before;
    if (stream.end != SourceStatus::kOk) return stream;
    stream.profiles.push_back(slot);  // outside the count: the copy is the test's, not next()'s
  }
}

}  // namespace cosmos::testing
