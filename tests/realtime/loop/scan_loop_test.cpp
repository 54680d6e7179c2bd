// The scan loop's builders and their shared row pool: a part that finds the pool used up is
// reported (an ERROR pose with its reason) and counted, its rows go back to the pool, and
// taking and giving back blocks allocates nothing. A pitched laser sheet's part, de-sheared,
// comes out with its own profiles' stamps and length, also when the stream ends right behind
// it.
#include "realtime/loop/scan_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "realtime/cell/blob_recognition.hpp"
#include "tests/common/allocation_counter.hpp"
#include "tests/realtime/loop/identical_rows.hpp"
#include "tests/realtime/loop/pitched_sheet.hpp"

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

// The dome of make_profile drawn along the belt as a prism over the rows [first, first + rows)
// (its ends 0.4 rows before the first and 0.4 after the last row's centre), measured by a
// sheet pitched by `pitch_deg`: the upright sheet's profiles are make_profile's.
void make_pitched_profile(Profile& profile, std::uint64_t seq, double pitch_deg, int first,
                          int rows, double width_mm) {
  make_profile(profile, seq, false, width_mm);
  const double y_begin = (first - 0.4) * 0.4, y_end = (first + rows - 0.6) * 0.4;
  for (int i = 0; i < kSamples; ++i) {
    const double x = profile.x_mm(static_cast<std::size_t>(i)) / (0.5 * width_mm);
    if (std::abs(x) >= 1) continue;
    const double dome = 2 + 8 * (1 - x * x);
    const auto height = [&](double y) { return y >= y_begin && y <= y_end ? dome : 0.0; };
    profile.z_mm[static_cast<std::size_t>(i)] = static_cast<float>(
        testing::pitched_sheet_hit(height, static_cast<double>(seq) * 0.4, pitch_deg, 10.0));
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

// The recognizer's answer to parts sent ahead of their completion when it recognizes none:
// no worker reads their builders.
void decline_speculation(ScanLoop& loop) {
  SpeculativePart part;
  while (loop.speculative().try_pop(part)) loop.speculated().try_push(part.builder);
}

// Runs `rows` profiles of a part, then enough belt for the tracker to complete it.
void pass_part(ScanLoop& loop, Profile& profile, std::uint64_t& seq, int rows, double width_mm) {
  for (int k = 0; k < rows; ++k) {
    make_profile(profile, seq++, true, width_mm);
    loop.process(profile);
    decline_speculation(loop);
  }
  for (int k = 0; k < 100; ++k) {
    make_profile(profile, seq++, false, width_mm);
    loop.process(profile);
    decline_speculation(loop);
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

// Row k of a 30-row part whose dome narrows towards both ends, so that its last rows curve
// along the belt too.
void make_tapered_profile(Profile& profile, std::uint64_t seq, int k) {
  make_profile(profile, seq, k >= 0 && k < 30, 40.0 - 0.8 * std::abs(k - 15));
}

// A 30-row part sent ahead and finished by the worker, against a twin loop that built it
// through to its completion: the same part, and the same planes bit for bit. With
// `follower_gap` > 0 a second part starts that many blank rows after it (beyond the fit's
// reach), in the rows the twin's builder still takes while the part waits out its links.
void expect_sent_ahead_as_completed(int follower_gap) {
  ScanLoop loop(ScanLoopSettings{});
  ScanLoopSettings without;
  without.parts.speculative_recognition = false;
  ScanLoop twin(without);
  Profile profile;
  std::uint64_t seq = 0;
  const auto feed = [&](int k) {
    const bool follower = follower_gap > 0 && k >= 30 + follower_gap && k < 50 + follower_gap;
    if (follower)
      make_profile(profile, seq++, true, 60.0);
    else
      make_tapered_profile(profile, seq++, k);
    loop.process(profile);
    twin.process(profile);
  };
  int k = 0;
  for (; k < 30; ++k) feed(k);
  SpeculativePart ahead;
  while (!loop.speculative().try_pop(ahead)) {
    feed(k++);
    // No run can join it outright, and the fit's reach below its end is blank.
    ASSERT_LE(k, 35) << "not sent ahead right after the fit's reach below its end";
  }
  EXPECT_TRUE(loop.completed().empty());
  EXPECT_EQ(ahead.built.rows, 30);
  EXPECT_EQ(ahead.built.last_data_profile, 29);
  // Frozen: the loop adds no more rows to its pipeline; the worker finishes it.
  IncrementalCosmos& frozen = loop.builder(ahead.builder).cosmos;
  const int frozen_rows = frozen.rows();
  frozen.finish();
  EXPECT_GE(frozen.final_rows(), 30);
  int index = -1, twin_index = -1;
  while (k < 200 && !loop.completed().try_pop(index)) feed(k++);
  ASSERT_TRUE(twin.completed().try_pop(twin_index));
  ASSERT_EQ(index, ahead.builder);
  EXPECT_EQ(frozen.rows(), frozen_rows);
  const PartBuilder& built = loop.builder(index);
  PartBuilder& twin_built = twin.builder(twin_index);
  EXPECT_TRUE(built.built().same_as(ahead.built));
  EXPECT_EQ(built.rows_added, twin_built.cosmos.rows());
  EXPECT_EQ(built.last_profile, twin_built.last_profile);
  twin_built.cosmos.finish();
  if (follower_gap > 0) {
    // The twin's builder did take the follower's rows.
    const PartRow follower_row = twin_built.cosmos.row(30 + follower_gap);
    ASSERT_GT(follower_row.column_end - follower_row.column_begin, 100);
  }
  testing::expect_identical_rows(frozen, twin_built.cosmos, 30);
  SpeculativePart later;  // once per part
  while (loop.speculative().try_pop(later)) EXPECT_NE(later.built.part_id, ahead.built.part_id);
}

TEST(ScanLoop, APartIsSentAheadOnceNothingCanChangeItWithWhatItsCompletionHolds) {
  expect_sent_ahead_as_completed(0);
}

TEST(ScanLoop, APartFollowedBeyondTheFitsReachIsSentAheadWithWhatItsCompletionHolds) {
  expect_sent_ahead_as_completed(5);
}

TEST(ScanLoop, APartWithAnotherStartingWithinTheFitsReachBelowItIsNotSentAhead) {
  ScanLoop loop(ScanLoopSettings{});
  Profile profile;
  std::uint64_t seq = 0;
  // Three blank rows (more than hard_link_gap_rows: two parts), then a second part whose
  // first row the fits of the first part's last rows read.
  for (int k = 0; k < 30; ++k) {
    make_profile(profile, seq++, true, 40.0);
    loop.process(profile);
  }
  for (int k = 0; k < 3; ++k) {
    make_profile(profile, seq++, false, 40.0);
    loop.process(profile);
  }
  for (int k = 0; k < 20; ++k) {
    make_profile(profile, seq++, true, 20.0);
    loop.process(profile);
  }
  for (int k = 0; k < 100; ++k) {
    make_profile(profile, seq++, false, 40.0);
    loop.process(profile);
  }
  SpeculativePart ahead;
  while (loop.speculative().try_pop(ahead)) EXPECT_NE(ahead.built.last_data_profile, 29);
  EXPECT_GE(loop.counters().parts_seen, 1);
}

TEST(ScanLoop, ABuilderAWorkerMayStillReadIsFreedOnlyOnceItsSpeculationEnds) {
  ScanLoopSettings settings;
  settings.parts.builders = 1;
  ScanLoop loop(settings);
  Profile profile;
  std::uint64_t seq = 0;
  const auto belt = [&](int rows) {
    for (int k = 0; k < rows; ++k) {
      make_profile(profile, seq++, false, 40.0);
      loop.process(profile);
    }
  };
  for (int k = 0; k < 30; ++k) {
    make_profile(profile, seq++, true, 40.0);
    loop.process(profile);
  }
  belt(100);
  SpeculativePart ahead;
  ASSERT_TRUE(loop.speculative().try_pop(ahead));
  int index = -1;
  ASSERT_TRUE(loop.completed().try_pop(index));
  loop.returned().try_push(index);
  belt(1);
  EXPECT_EQ(loop.row_pool().blocks_in_use(), 1);  // a worker may still read its rows
  loop.speculated().try_push(ahead.builder);
  belt(1);
  EXPECT_EQ(loop.row_pool().blocks_in_use(), 0);
}

TEST(ScanLoop, BlobsMayStillComeFromTheOldestOpenPartsFirstProfile) {
  ScanLoop loop{ScanLoopSettings{}};
  Profile profile;
  std::uint64_t seq = 0;
  const auto feed = [&](int rows, bool part) {
    for (int k = 0; k < rows; ++k) {
      make_profile(profile, seq++, part, 40.0);
      loop.process(profile);
      decline_speculation(loop);
    }
  };
  feed(10, false);
  EXPECT_EQ(loop.unfinished_from_profile(), 10);  // nothing open: the next profile
  feed(30, true);                                 // a part from profile 10
  EXPECT_EQ(loop.unfinished_from_profile(), 10);
  feed(50, false);  // still open: the tracker waits out link_gap_rows
  EXPECT_EQ(loop.unfinished_from_profile(), 10);
  int index = -1;
  EXPECT_FALSE(loop.completed().try_pop(index));
  feed(50, false);
  // Completed, and in completed() before the value moved past it.
  ASSERT_TRUE(loop.completed().try_pop(index));
  EXPECT_EQ(loop.builder(index).first_profile, 10);
  EXPECT_EQ(loop.unfinished_from_profile(), static_cast<std::int64_t>(seq));
  loop.flush();
  EXPECT_EQ(loop.unfinished_from_profile(), std::numeric_limits<std::int64_t>::max());
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
  // Every row whose COSMOS became final went through the CSMP seed search's first pass too
  // (the rest are the worker's to finish, once the part was sent ahead).
  ASSERT_TRUE(loop.completed().try_pop(index));
  const IncrementalCosmos& built = loop.builder(index).cosmos;
  EXPECT_GT(built.final_rows(), 0);
  EXPECT_EQ(built.seeds().seeded_rows(), built.final_rows());
  counted(40);  // finds the pool used up
  EXPECT_EQ(loop.counters().parts_seen, 2);
  EXPECT_EQ(loop.counters().parts_out_of_rows, 1);
  EXPECT_EQ(allocations, 0u);
}

// A pitched sheet's scan of a 60-row part starting at profile 20 through a loop de-shearing it,
// with `belt_after` profiles of belt behind it, then the end of the stream; the part's builder.
struct PitchedScan {
  std::int64_t first_profile = 0, last_data_profile = 0, first_encoder_ticks = 0,
               last_data_encoder_ticks = 0, tracked_rows = 0;
  int delay = 0;
};

PitchedScan pitched_scan(double pitch_deg, int belt_after) {
  constexpr int kFirst = 20, kRows = 60;
  ScanLoopSettings settings;
  settings.parts.builders = 2;
  settings.conditioning.sheet_pitch_deg = pitch_deg;
  ScanLoop loop(settings);
  Profile profile;
  for (int k = 0; k < kFirst + kRows + belt_after; ++k) {
    make_pitched_profile(profile, static_cast<std::uint64_t>(k), pitch_deg, kFirst, kRows, 40.0);
    loop.process(profile);
  }
  loop.flush();
  EXPECT_EQ(loop.counters().profiles, kFirst + kRows + belt_after);
  EXPECT_EQ(loop.counters().parts_seen, 1);
  EXPECT_EQ(loop.counters().samples_too_high, 0);
  int index = -1;
  EXPECT_TRUE(loop.completed().try_pop(index));
  if (index < 0) return {};
  const PartBuilder& builder = loop.builder(index);
  return {builder.first_profile,           builder.last_data_profile, builder.first_encoder_ticks,
          builder.last_data_encoder_ticks, builder.tracked_rows,      loop.sheet_delay_rows()};
}

TEST(ScanLoop, APitchedSheetsPartComesOutWithItsOwnProfilesStampsAndLength) {
  const PitchedScan upright = pitched_scan(0, 100);
  EXPECT_EQ(upright.delay, 0);
  EXPECT_EQ(upright.first_profile, 20);
  EXPECT_EQ(upright.last_data_profile, 79);
  EXPECT_EQ(upright.tracked_rows, 60);
  for (const double pitch : {-5.0, -1.0, 1.0, 5.0}) {
    const PitchedScan scan = pitched_scan(pitch, 100);
    // 200 mm (max_height_mm) at 5°: 45 rows; at 1°: 10.
    EXPECT_EQ(scan.delay, std::abs(pitch) == 5 ? 45 : 10) << pitch;
    // Stamped by the profiles that measured its first and last rows, not by the newest ones,
    // the window's rows later.
    EXPECT_EQ(scan.first_profile, 20) << pitch;
    EXPECT_EQ(scan.first_encoder_ticks, 80) << pitch;
    EXPECT_EQ(scan.last_data_profile, 79) << pitch;
    EXPECT_EQ(scan.last_data_encoder_ticks, 316) << pitch;
    EXPECT_NEAR(scan.tracked_rows, upright.tracked_rows, 1) << pitch;
  }
}

TEST(ScanLoop, FlushFeedsTheRowsTheDeshearStillHolds) {
  // The stream ends with the part's last profile: its last 45 rows are still in the window.
  const PitchedScan upright = pitched_scan(0, 0);
  EXPECT_EQ(upright.last_data_profile, 79);
  for (const double pitch : {-5.0, 5.0}) {
    const PitchedScan scan = pitched_scan(pitch, 0);
    EXPECT_EQ(scan.first_profile, 20) << pitch;
    EXPECT_EQ(scan.last_data_profile, 79) << pitch;
    EXPECT_NEAR(scan.tracked_rows, upright.tracked_rows, 1) << pitch;
  }
}

TEST(ScanLoop, DeshearingAPitchedSheetAllocatesNothing) {
  ScanLoopSettings settings;
  settings.parts.builders = 2;
  settings.conditioning.sheet_pitch_deg = 5;
  ScanLoop loop(settings);
  Profile profile;
  profile.reserve(kSamples);
  std::uint64_t seq = 0;
  const auto pass = [&] {
    const int first = static_cast<int>(seq) + 20;
    for (int k = 0; k < 180; ++k, ++seq)
      make_pitched_profile(profile, seq, 5.0, first, 30, 40.0), loop.process(profile);
    int index = -1;
    ASSERT_TRUE(loop.completed().try_pop(index));
    loop.returned().try_push(index);
  };
  pass();  // warm-up: every buffer has seen a part
  const std::uint64_t before = test::allocations_on_this_thread();
  pass();
  EXPECT_EQ(test::allocations_on_this_thread() - before, 0u);
  EXPECT_EQ(loop.counters().parts_seen, 2);
}

}  // namespace
}  // namespace cosmos
