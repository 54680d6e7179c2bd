// The fault plan: off by default, the first run clean, one occurrence of the set length in
// every later run, at seeded places.
#include "sim/source/fault_plan.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

int active_in(const FaultPlan& plan, InjectedFault fault, std::int64_t from, std::int64_t to) {
  int count = 0;
  for (std::int64_t k = from; k < to; ++k) count += plan.active(fault, k) ? 1 : 0;
  return count;
}

TEST(FaultPlan, IsOffByDefault) {
  const FaultPlan plan;
  EXPECT_EQ(active_in(plan, InjectedFault::kFrameGap, 0, 100'000), 0);
  EXPECT_EQ(active_in(plan, InjectedFault::kLaserOff, 0, 100'000), 0);
}

TEST(FaultPlan, PutsOneOccurrenceInEveryRunButTheFirst) {
  FaultInjectionSettings settings;
  settings.laser_off = {.every_profiles = 1000, .profiles = 30};
  const FaultPlan plan(settings);
  EXPECT_EQ(active_in(plan, InjectedFault::kLaserOff, 0, 1000), 0);
  for (std::int64_t run = 1; run < 20; ++run) {
    SCOPED_TRACE(run);
    EXPECT_EQ(active_in(plan, InjectedFault::kLaserOff, run * 1000, run * 1000 + 1000), 30);
    const std::int64_t start = plan.occurrence_start(InjectedFault::kLaserOff, run * 1000);
    EXPECT_TRUE(plan.active(InjectedFault::kLaserOff, start));
    EXPECT_FALSE(plan.active(InjectedFault::kLaserOff, start - 1));
    EXPECT_TRUE(plan.active(InjectedFault::kLaserOff, start + 29));
    EXPECT_FALSE(plan.active(InjectedFault::kLaserOff, start + 30));
  }
  EXPECT_EQ(active_in(plan, InjectedFault::kFrameGap, 0, 20'000), 0);  // only the one set
}

TEST(FaultPlan, PlacesFollowTheSeed) {
  FaultInjectionSettings a;
  a.frame_gaps = {.every_profiles = 5000, .profiles = 3};
  FaultInjectionSettings b = a;
  b.seed = a.seed + 1;
  int same_seed = 0, other_seed = 0;
  for (std::int64_t run = 1; run <= 20; ++run) {
    same_seed += FaultPlan(a).occurrence_start(InjectedFault::kFrameGap, run * 5000) ==
                 FaultPlan(a).occurrence_start(InjectedFault::kFrameGap, run * 5000);
    other_seed += FaultPlan(a).occurrence_start(InjectedFault::kFrameGap, run * 5000) ==
                  FaultPlan(b).occurrence_start(InjectedFault::kFrameGap, run * 5000);
  }
  EXPECT_EQ(same_seed, 20);
  EXPECT_LE(other_seed, 2);
}

}  // namespace
}  // namespace cosmos
