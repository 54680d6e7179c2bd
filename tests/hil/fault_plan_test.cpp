// The HIL faults fall in empty belt: never inside a part's profiles.
#include "tests/hil/fault_plan.hpp"

#include <gtest/gtest.h>

namespace cosmos::hil {
namespace {

TapeHeader ten_parts() {
  TapeHeader header;
  std::int64_t profile = 100;
  for (int i = 0; i < 10; ++i) {
    header.parts.push_back({"part", {}, profile, profile + 250});
    profile += 350;
  }
  header.last_profile = profile;
  return header;
}

bool inside_a_part(const TapeHeader& header, std::int64_t profile) {
  for (const TapePart& part : header.parts)
    if (profile >= part.first_profile && profile <= part.last_profile) return true;
  return false;
}

TEST(FaultPlan, PutsEveryFaultOfTheCellRunBetweenParts) {
  const TapeHeader header = ten_parts();
  const FaultPlan plan = plan_faults("cell", header);
  ASSERT_EQ(plan.faults.size(), 5u);
  for (const FaultAt& fault : plan.faults) EXPECT_FALSE(inside_a_part(header, fault.profile));
  for (std::size_t i = 1; i < plan.faults.size(); ++i)
    EXPECT_GT(plan.faults[i].profile, plan.faults[i - 1].profile);
  EXPECT_EQ(plan.faults[0].kind, "skip");
  EXPECT_EQ(plan.faults[0].amount, kSkipFrames);
  EXPECT_EQ(plan.faults[3].kind, "stall");
  EXPECT_EQ(plan.faults[3].amount, kCellStallMs);
  ASSERT_EQ(plan.bouncing_arrivals.size(), 1u);
  EXPECT_LT(plan.bouncing_arrivals[0], header.parts.size());
}

TEST(FaultPlan, ProbePlanFitsBeforeTheSecondPart) {
  TapeHeader header = ten_parts();
  header.parts.resize(2);
  header.last_profile = 900;
  const FaultPlan plan = plan_faults("probe", header);
  ASSERT_EQ(plan.faults.size(), 5u);
  for (const FaultAt& fault : plan.faults) {
    EXPECT_FALSE(inside_a_part(header, fault.profile));
    EXPECT_LT(fault.profile, header.parts[1].first_profile);
  }
  EXPECT_TRUE(plan_faults("none", header).faults.empty());
  EXPECT_THROW(plan_faults("chaos", header), std::invalid_argument);
}

}  // namespace
}  // namespace cosmos::hil
