#include "core/segmentation/neighbor_equality.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace cosmos {
namespace {

// Bit k set when neighbour k is inside the grid and equal, from the definition.
std::uint8_t brute_force(const std::vector<int>& values, int width, int height, int column, int row,
                         int directions) {
  std::uint8_t mask = 0;
  for (int k = 0; k < directions; ++k) {
    const int c = column + kNeighborOffsets[k].column, r = row + kNeighborOffsets[k].row;
    if (c < 0 || r < 0 || c >= width || r >= height) continue;
    if (values[static_cast<std::size_t>(r * width + c)] ==
        values[static_cast<std::size_t>(row * width + column)])
      mask |= static_cast<std::uint8_t>(1u << k);
  }
  return mask;
}

TEST(NeighborEquality, EveryRowMatchesTheDefinitionWithBackwardAndAllDirections) {
  // 7 x 5 values in three classes, so that every direction is equal somewhere and not
  // elsewhere, on the border rows and columns as inside.
  constexpr int kWidth = 7, kHeight = 5;
  std::vector<int> values(kWidth * kHeight);
  for (int i = 0; i < kWidth * kHeight; ++i) values[static_cast<std::size_t>(i)] = (i * 7 / 3) % 3;
  std::vector<std::uint8_t> backward(kWidth), all(kWidth);
  int equal_bits = 0;
  for (int row = 0; row < kHeight; ++row) {
    equal_neighbors_of_row<4>(values.data(), kWidth, kHeight, row, backward.data());
    equal_neighbors_of_row<8>(values.data(), kWidth, kHeight, row, all.data());
    for (int column = 0; column < kWidth; ++column) {
      EXPECT_EQ(backward[column], brute_force(values, kWidth, kHeight, column, row, 4))
          << column << ", " << row;
      EXPECT_EQ(all[column], brute_force(values, kWidth, kHeight, column, row, 8))
          << column << ", " << row;
      equal_bits += __builtin_popcount(all[column]);
    }
  }
  EXPECT_GT(equal_bits, 20);
  EXPECT_LT(equal_bits, 8 * kWidth * kHeight - 60);
}

TEST(NeighborEquality, ARangeOfARowGetsTheMasksOfTheWholeRowsComparison) {
  constexpr int kWidth = 9, kHeight = 2;
  std::vector<int> values(kWidth * kHeight);
  for (int i = 0; i < kWidth * kHeight; ++i) values[static_cast<std::size_t>(i)] = (i * 5 / 2) % 2;
  std::vector<std::uint8_t> whole(kWidth), ranged(kWidth);
  int compared = 0;
  for (int begin = 0; begin < kWidth; ++begin)
    for (int end = begin + 1; end <= kWidth; ++end)
      for (int row = 0; row < kHeight; ++row) {
        const int* own = values.data() + row * kWidth;
        const int* above = row > 0 ? own - kWidth : nullptr;
        equal_backward_neighbors(above, own, kWidth, whole.data());
        std::fill(ranged.begin(), ranged.end(), 0xAA);
        equal_backward_neighbors(above, own, kWidth, begin, end, ranged.data());
        for (int column = 0; column < kWidth; ++column) {
          const bool inside = column >= begin && column < end;
          EXPECT_EQ(ranged[column], inside ? whole[column] : 0xAA)
              << begin << ".." << end << " row " << row << " column " << column;
          compared += inside ? 1 : 0;
        }
      }
  EXPECT_EQ(compared, 2 * 165);  // every column of every range, on both rows
}

TEST(NeighborEquality, AUniformGridIsEqualEverywhereInsideAndNowhereOutside) {
  const std::vector<std::uint8_t> values(4 * 3, 5);
  std::vector<std::uint8_t> all(4);
  equal_neighbors_of_row<8>(values.data(), 4, 3, 1, all.data());
  EXPECT_EQ(all[1], 0xFFu);
  EXPECT_EQ(all[2], 0xFFu);
  // Column 0 lacks its three left neighbours (directions 0, 3 and 5).
  EXPECT_EQ(all[0], static_cast<std::uint8_t>(0xFFu & ~0x29u));
  equal_neighbors_of_row<4>(values.data(), 4, 3, 0, all.data());
  EXPECT_EQ(all[0], 0u);     // the first pixel has no earlier neighbour
  EXPECT_EQ(all[3], 0x08u);  // the rest of the first row only its left one
}

TEST(NeighborEquality, ListsTheColumnsWhoseMaskDiffersInOrder) {
  const std::vector<std::uint8_t> masks = {0xFF, 0x01, 0xFF, 0xFF, 0x00, 0x80, 0xFF};
  std::vector<std::int32_t> columns(masks.size());
  const int width = static_cast<int>(masks.size());
  ASSERT_EQ(columns_with_mask_other_than(masks.data(), width, 0xFF, columns.data()), 3);
  EXPECT_EQ(columns[0], 1);
  EXPECT_EQ(columns[1], 4);
  EXPECT_EQ(columns[2], 5);
  ASSERT_EQ(columns_with_mask_other_than(masks.data(), width, 0x00, columns.data()), 6);
  EXPECT_EQ(columns[3], 3);  // all but column 4
  EXPECT_EQ(columns[4], 5);
  EXPECT_EQ(columns[5], 6);
}

}  // namespace
}  // namespace cosmos
