// The simulated scanner's profile loop allocates nothing after warm-up, in both modes: it runs
// on the acquisition thread of the simulated cell, under the same rule as the real one.
//
// Allocations are counted by the binary's one replacement operator new
// (tests/common/allocation_counter.hpp), per thread.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "sim/procedural_meshes.hpp"
#include "tests/common/allocation_counter.hpp"
#include "tests/sim/scanner_test_scenes.hpp"

namespace cosmos {
namespace {

long allocations_while(const std::function<void()>& work) {
  const std::uint64_t before = test::allocations_on_this_thread();
  work();
  return static_cast<long>(test::allocations_on_this_thread() - before);
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
  const auto scene =
      testing::single_part_scene(make_icosphere(20.0, 4), Eigen::Matrix3d::Identity());
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

INSTANTIATE_TEST_SUITE_P(Modes, ScannerAllocation,
                         ::testing::Values(ScanMode::kProfile, ScanMode::kCamera));

}  // namespace
}  // namespace cosmos
