// The scan loop's builders and their shared row pool: a part that finds the pool used up is
// reported (an ERROR pose with its reason) and counted, its rows go back to the pool, and
// taking and giving back blocks allocates nothing.
#include "realtime/loop/scan_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "realtime/cell/blob_recognition.hpp"
#include "tests/common/allocation_counter.hpp"

namespace cosmos {
namespace {

// The default scanner's profile on the default grid: 640 samples 0.4 mm apart.
constexpr int kSamples = 640;

// A profile with a 10 mm high dome `width_mm` wide centred at x = 0 when `part`, else the
// bare belt.
void make_profile(Profile& profile, std::uint64_t seq, bool part, double width_mm) {
  profile.seq = seq;
  profile.encoder_ticks = static_cast<std::int64_t>(seq) * 4;
  profile.t_us = static_cast<std::int64_t>(seq) * 400;
  profile.x0_mm = -127.8;
  profile.dx_mm = 0.4;
  profile.resize(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const double x = profile.x_mm(static_cast<std::size_t>(i)) / (0.5 * width_mm);
    profile.z_mm[static_cast<std::size_t>(i)] =
        part && std::abs(x) < 1 ? static_cast<float>(2 + 8 * (1 - x * x)) : 0.0f;
  }
}

ScanLoopSettings small_pool_settings() {
  ScanLoopSettings settings;
  settings.parts.builders = 2;
  // One block of two full-width rows: a 40 mm part's rows (about 100 columns) fit 12 to it.
  settings.parts.row_blocks = 1;
  settings.parts.row_block_rows = 2;
  return settings;
}

// Runs `rows` profiles of a part, then enough belt for the tracker to complete it.
void pass_part(ScanLoop& loop, Profile& profile, std::uint64_t& seq, int rows, double width_mm) {
  for (int k = 0; k < rows; ++k) {
    make_profile(profile, seq++, true, width_mm);
    loop.process(profile);
  }
  for (int k = 0; k < 100; ++k) {
    make_profile(profile, seq++, false, width_mm);
    loop.process(profile);
  }
}

TEST(ScanLoop, APartThatFindsTheRowPoolUsedUpIsReportedAndCounted) {
  ScanLoop loop(small_pool_settings());
  Profile profile;
  std::uint64_t seq = 0;
  pass_part(loop, profile, seq, 40, 40.0);  // 40 rows: more than the block holds
  EXPECT_EQ(loop.counters().parts_out_of_rows, 1);
  EXPECT_EQ(loop.counters().parts_dropped, 1);
  EXPECT_EQ(loop.counters().parts_seen, 0);
  int index = -1;
  EXPECT_FALSE(loop.completed().try_pop(index));
  LostPart lost;
  ASSERT_TRUE(loop.lost_parts().try_pop(lost));
  EXPECT_EQ(lost.reason, LostPartReason::kNoRowMemory);
  EXPECT_EQ(lost.first_profile, 0);
  EXPECT_EQ(lost.last_profile, 39);
  // Its ERROR pose names the setting that ran out.
  const PartRecognition report = report_lost_part(lost, PartRecognitionContext{}, 1);
  EXPECT_EQ(report.pose.status, PoseStatus::kError);
  EXPECT_NE(report.pose.reason.find("realtime.row_blocks"), std::string::npos)
      << report.pose.reason;
  // Its rows went back to the pool: a short part that fits it is built and completed.
  EXPECT_EQ(loop.row_pool().blocks_in_use(), 0);
  pass_part(loop, profile, seq, 8, 40.0);
  EXPECT_EQ(loop.counters().parts_seen, 1);
  ASSERT_TRUE(loop.completed().try_pop(index));
  EXPECT_EQ(loop.builder(index).cosmos.row(7).column_begin, lost.column_min);
  EXPECT_EQ(loop.counters().parts_out_of_rows, 1);
}

TEST(ScanLoop, BuildersHoldOnlyTheirPartsColumnsAndGiveThemBackWhenReturned) {
  ScanLoopSettings settings;
  settings.parts.builders = 2;
  ScanLoop loop(settings);
  Profile profile;
  std::uint64_t seq = 0;
  pass_part(loop, profile, seq, 30, 40.0);
  int index = -1;
  ASSERT_TRUE(loop.completed().try_pop(index));
  const IncrementalCosmos& cosmos = loop.builder(index).cosmos;
  // The part's 30 rows, then the belt rows until the tracker completed it: those hold no
  // columns (and no memory).
  ASSERT_GT(cosmos.rows(), 30);
  const PartRow last = cosmos.row(cosmos.rows() - 1);
  EXPECT_EQ(last.column_end - last.column_begin, 0);
  // 40 mm of dome: 99 or 100 grid columns out of 640.
  const PartRow row = cosmos.row(15);
  EXPECT_NEAR(row.column_end - row.column_begin, 100, 1);
  EXPECT_EQ(cosmos.blocks(), 1);
  EXPECT_EQ(loop.row_pool().blocks_in_use(), 1);
  loop.returned().try_push(index);
  make_profile(profile, seq++, false, 40.0);
  loop.process(profile);
  EXPECT_EQ(loop.row_pool().blocks_in_use(), 0);
  EXPECT_EQ(loop.counters().row_blocks_peak, 1);
}

TEST(ScanLoop, TakingAndGivingBackRowBlocksAllocatesNothing) {
  // A block of two full rows: the first part takes two blocks, the second finds none left.
  ScanLoopSettings settings = small_pool_settings();
  settings.parts.row_blocks = 2;
  ScanLoop loop(settings);
  Profile profile;
  profile.reserve(kSamples);
  std::uint64_t seq = 0;
  pass_part(loop, profile, seq, 20, 40.0);  // warm-up: every buffer has seen a part
  int index = -1;
  ASSERT_TRUE(loop.completed().try_pop(index));
  loop.returned().try_push(index);
  std::uint64_t allocations = 0;
  const auto counted = [&](int rows) {
    const std::uint64_t before = test::allocations_on_this_thread();
    pass_part(loop, profile, seq, rows, 40.0);
    allocations += test::allocations_on_this_thread() - before;
  };
  counted(20);  // two blocks
  counted(40);  // finds the pool used up
  EXPECT_EQ(loop.counters().parts_seen, 2);
  EXPECT_EQ(loop.counters().parts_out_of_rows, 1);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace cosmos
