#pragma once
// Heap allocations made by the calling thread, counted by the replacement global operator
// new of allocation_counter.cpp: proves that a hot path allocates nothing. This test binary
// (each that links it) holds the one replacement; no other file of it may define operator new.
#include <cstdint>

namespace cosmos::test {

std::uint64_t allocations_on_this_thread() noexcept;

}  // namespace cosmos::test
