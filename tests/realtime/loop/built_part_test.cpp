// What recognition reads of a builder: the ids it owns, and when a copy taken before the
// tracker completed the part still holds at completion.
#include "realtime/loop/built_part.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

BuiltPart sample_part() {
  BuiltPart part;
  part.rows = 30;
  part.part_id = 7;
  part.merged_ids[0] = 9;
  part.merged_count = 1;
  part.first_profile = 100;
  part.last_data_profile = 129;
  part.first_encoder_ticks = 400;
  part.last_data_encoder_ticks = 516;
  part.last_data_t_us = 51'600;
  part.column_min = 270;
  part.column_max = 370;
  part.max_z_mm = 10.0F;
  part.tracked_rows = 30;
  return part;
}

TEST(BuiltPart, OwnsItsIdAndTheIdsMergedIntoIt) {
  const BuiltPart part = sample_part();
  EXPECT_TRUE(part.owns(7));
  EXPECT_TRUE(part.owns(9));
  EXPECT_FALSE(part.owns(8));
  EXPECT_FALSE(part.owns(-1));
}

TEST(BuiltPart, ACopyHoldsOnlyWhileNothingOfThePartChanged) {
  const BuiltPart part = sample_part();
  EXPECT_TRUE(part.same_as(sample_part()));
  const auto changed = [&part](auto change) {
    BuiltPart other = part;
    change(other);
    return !part.same_as(other);
  };
  EXPECT_TRUE(changed([](BuiltPart& p) { p.rows = 31; }));
  EXPECT_TRUE(changed([](BuiltPart& p) { p.part_id = 8; }));
  EXPECT_TRUE(changed([](BuiltPart& p) { p.merged_ids[1] = 12, p.merged_count = 2; }));
  EXPECT_TRUE(changed([](BuiltPart& p) { p.last_data_profile = 130; }));
  EXPECT_TRUE(changed([](BuiltPart& p) { p.last_data_encoder_ticks = 520; }));
  EXPECT_TRUE(changed([](BuiltPart& p) { p.column_min = 260; }));
  EXPECT_TRUE(changed([](BuiltPart& p) { p.column_max = 380; }));
  EXPECT_TRUE(changed([](BuiltPart& p) { p.max_z_mm = 11.0F; }));
  EXPECT_TRUE(changed([](BuiltPart& p) { p.truncated = true; }));
}

}  // namespace
}  // namespace cosmos
