// The simulated scanner's profile loop allocates nothing after warm-up, in both modes: it runs
// on the acquisition thread of the simulated cell, under the same rule as the real one.
//
// Allocations are counted by replacing the global operator new. The replacement is weak so it
// cannot clash with another test's counting allocator; if one replaces it, this test sees no
// counts and fails rather than passing vacuously.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <functional>
#include <new>
#include <vector>

#include "sim/procedural_meshes.hpp"
#include "tests/sim/scanner_test_scenes.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

__attribute__((weak)) void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}
__attribute__((weak)) void operator delete(void* memory) noexcept { std::free(memory); }
__attribute__((weak)) void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }

namespace cosmos {
namespace {

long allocations_while(const std::function<void()>& work) {
  const long before = g_allocations.load();
  work();
  return g_allocations.load() - before;
}

class ScannerAllocation : public ::testing::TestWithParam<ScanMode> {};

TEST_P(ScannerAllocation, ProfileLoopAllocatesNothingAfterWarmUp) {
  const long probe = allocations_while([] {
    std::vector<int> numbers(100, 1);
    volatile int sink = numbers[50];
    static_cast<void>(sink);
  });
  // The counting operator new must be the one in force, or the test below proves nothing.
  ASSERT_GT(probe, 0) << "operator new is replaced elsewhere in this binary";
  const auto scene = testing::single_part_scene(make_icosphere(20.0, 4), Eigen::Matrix3d::Identity());
  SimulatedScanner scanner(*scene, ScannerParameters{}, GetParam());
  Profile profile;
  scanner.reserve(profile);
  const ProfileRange range = profiles_covering(*scene, scanner.parameters(), 2.0);
  scanner.acquire(range.first, profile);  // warm-up
  const long allocations = allocations_while([&] {
    for (std::int64_t k = range.first; k <= range.last; ++k) scanner.acquire(k, profile);
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(range.count(), 90);
}

INSTANTIATE_TEST_SUITE_P(Modes, ScannerAllocation, ::testing::Values(ScanMode::kProfile, ScanMode::kCamera));

}  // namespace
}  // namespace cosmos
