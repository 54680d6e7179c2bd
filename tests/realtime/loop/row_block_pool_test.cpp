// The builders' row pool: a fixed number of blocks, handed out until none is left.
#include "realtime/loop/row_block_pool.hpp"

#include <gtest/gtest.h>

#include <set>

namespace cosmos {
namespace {

TEST(RowBlockPool, HandsOutEveryBlockOnceThenNone) {
  RowBlockPool pool(3, 100);
  EXPECT_EQ(pool.block_bytes(), 128u);  // whole 64-byte lines
  EXPECT_EQ(pool.bytes(), 384u);
  std::set<int> blocks;
  for (int k = 0; k < 3; ++k) blocks.insert(pool.acquire());
  EXPECT_EQ(blocks, (std::set<int>{0, 1, 2}));
  EXPECT_EQ(pool.acquire(), -1);
  EXPECT_EQ(pool.blocks_in_use(), 3);
  // Blocks do not overlap.
  EXPECT_EQ(pool.data(1) - pool.data(0), 128);
  EXPECT_EQ(pool.data(2) - pool.data(1), 128);
}

TEST(RowBlockPool, ReusesTheLastReleasedBlockAndKeepsItsPeak) {
  RowBlockPool pool(4, 64);
  const int first = pool.acquire();
  const int second = pool.acquire();
  EXPECT_EQ(first, 0);  // a lightly used pool stays in its first blocks
  pool.release(first);
  EXPECT_EQ(pool.acquire(), first);
  pool.release(first);
  pool.release(second);
  EXPECT_EQ(pool.blocks_in_use(), 0);
  EXPECT_EQ(pool.peak_blocks_in_use(), 2);
}

}  // namespace
}  // namespace cosmos
