// A part's compact rows: each row's columns between its first and last sample, laid end to
// end in blocks of the shared pool.
#include "realtime/loop/part_rows.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace cosmos {
namespace {

TEST(PartRows, RecordsAreSeventyNineBytesPerColumnRoundedToEight) {
  EXPECT_EQ(PartRows::record_bytes(0), 0u);
  EXPECT_EQ(PartRows::record_bytes(1), 80u);  // 79 rounded up
  EXPECT_EQ(PartRows::record_bytes(640), 50560u);
}

TEST(PartRows, RowsShareABlockUntilItIsFullThenTakeTheNext) {
  RowBlockPool pool(2, 3 * PartRows::record_bytes(10));
  PartRows rows(pool, 100);
  for (int r = 0; r < 3; ++r) ASSERT_TRUE(rows.append(5, 15));
  EXPECT_EQ(rows.blocks(), 1);
  ASSERT_TRUE(rows.append(0, 10));
  EXPECT_EQ(rows.blocks(), 2);
  // A row without samples takes no room.
  ASSERT_TRUE(rows.append(7, 7));
  EXPECT_EQ(rows.blocks(), 2);
  EXPECT_EQ(rows.rows(), 5);
  const PartRow row = rows.row(1);
  EXPECT_EQ(row.column_begin, 5);
  EXPECT_EQ(row.column_end, 15);
  EXPECT_TRUE(row.holds(14));
  EXPECT_FALSE(row.holds(15));
  EXPECT_FALSE(row.holds(4));
  EXPECT_EQ(row.at(14), 9u);
  // The planes of consecutive rows do not overlap: row 1 starts where row 0 ends.
  EXPECT_EQ(reinterpret_cast<const std::byte*>(rows.row(1).tracker_label) -
                reinterpret_cast<const std::byte*>(rows.row(0).tracker_label),
            static_cast<std::ptrdiff_t>(PartRows::record_bytes(10)));
  EXPECT_EQ(reinterpret_cast<const std::byte*>(row.label + 10) -
                reinterpret_cast<const std::byte*>(row.tracker_label),
            79 * 10);
}

TEST(PartRows, AFullPoolRefusesARowAndChangesNothing) {
  RowBlockPool pool(1, PartRows::record_bytes(20));
  PartRows rows(pool, 100);
  ASSERT_TRUE(rows.append(0, 20));
  EXPECT_FALSE(rows.append(0, 1));
  EXPECT_EQ(rows.rows(), 1);
  EXPECT_EQ(pool.blocks_in_use(), 1);
  rows.clear();
  EXPECT_EQ(rows.rows(), 0);
  EXPECT_EQ(pool.blocks_in_use(), 0);
  // Rows beyond max_rows are refused as well.
  PartRows short_rows(pool, 1);
  ASSERT_TRUE(short_rows.append(0, 2));
  EXPECT_FALSE(short_rows.append(0, 2));
}

TEST(PartRows, GivesItsBlocksBackWhenDestroyed) {
  RowBlockPool pool(2, PartRows::record_bytes(8));
  {
    PartRows rows(pool, 10);
    ASSERT_TRUE(rows.append(0, 8));
    ASSERT_TRUE(rows.append(0, 8));
    EXPECT_EQ(pool.blocks_in_use(), 2);
  }
  EXPECT_EQ(pool.blocks_in_use(), 0);
}

}  // namespace
}  // namespace cosmos
