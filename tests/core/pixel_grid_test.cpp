// PixelGrid (core/pixel_grid.hpp): row-major storage, so that one image row is contiguous
// (the real-time loop hands whole rows to the per-pixel kernels).
#include "core/pixel_grid.hpp"

#include <gtest/gtest.h>

namespace cosmos {
namespace {

TEST(PixelGrid, IsFilledAndIndexedRowMajor) {
  PixelGrid<int> grid(4, 3, 7);
  EXPECT_EQ(grid.width(), 4);
  EXPECT_EQ(grid.height(), 3);
  ASSERT_EQ(grid.size(), 12u);
  for (std::size_t i = 0; i < grid.size(); ++i) EXPECT_EQ(grid[i], 7) << i;
  // (column, row) -> row * width + column.
  EXPECT_EQ(grid.index(0, 0), 0u);
  EXPECT_EQ(grid.index(3, 0), 3u);
  EXPECT_EQ(grid.index(1, 2), 9u);
  EXPECT_EQ(grid.index(3, 2), 11u);
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 4; ++column) grid(column, row) = 10 * row + column;
  EXPECT_EQ(grid[6], 12);  // column 2 of row 1
  EXPECT_EQ(grid.values()[11], 23);
}

TEST(PixelGrid, RowPointsAtItsFirstColumnAndRowsAreContiguous) {
  PixelGrid<float> grid(5, 4, 0.0f);
  grid.row(2)[3] = 1.5f;
  EXPECT_EQ(grid(3, 2), 1.5f);
  EXPECT_EQ(grid.row(2), grid.data() + 10);
  EXPECT_EQ(grid.row(3) - grid.row(2), 5);
  const PixelGrid<float>& view = grid;
  EXPECT_EQ(view.row(2)[3], 1.5f);
  EXPECT_EQ(view(3, 2), 1.5f);
}

TEST(PixelGrid, ContainsExactlyTheImagePixels) {
  const PixelGrid<unsigned char> grid(4, 3);
  EXPECT_TRUE(grid.contains(0, 0));
  EXPECT_TRUE(grid.contains(3, 2));
  EXPECT_FALSE(grid.contains(-1, 0));
  EXPECT_FALSE(grid.contains(0, -1));
  EXPECT_FALSE(grid.contains(4, 0));
  EXPECT_FALSE(grid.contains(0, 3));
  EXPECT_EQ(grid[5], 0);  // T{} fill by default

  const PixelGrid<int> empty;
  EXPECT_EQ(empty.width(), 0);
  EXPECT_EQ(empty.size(), 0u);
  EXPECT_FALSE(empty.contains(0, 0));
}

}  // namespace
}  // namespace cosmos
