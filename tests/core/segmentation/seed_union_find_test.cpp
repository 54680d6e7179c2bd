// Pass 1 of the seed search, row by row over nodes kept one vector per row (as the real-time
// builder keeps them, not one raster array): pixels join their earlier neighbours' sets while
// the joined S_I range stays within one quantum, the least joined range first, and the sets
// they touch without joining are listed as crossings.
#include "core/segmentation/seed_union_find.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace cosmos {
namespace {

constexpr int kWidth = 4;

// Nodes one vector per row; ids row * 100 + column (raster ordered).
struct RowVectorNodes {
  std::vector<std::vector<SeedNode>>* rows;
  int row;
  std::int32_t id(int column) const { return row * 100 + column; }
  std::int32_t above_id(int column) const { return (row - 1) * 100 + column; }
  SeedNode& at(std::int32_t id) { return (*rows)[id / 100][id % 100]; }
  SeedNode& here(int column) { return (*rows)[row][column]; }
  SeedNode& above(int column) { return (*rows)[row - 1][column]; }
};

struct Grown {
  std::vector<std::vector<SeedNode>> nodes;
  std::vector<std::pair<std::int32_t, std::int32_t>> crossings;

  std::int32_t root_of(int row, int column) {
    RowVectorNodes view{&nodes, row};
    return find_seed_root(view, view.id(column));
  }
};

// Rows of shape indices, every pixel curved and linked to all its neighbours.
Grown grow(const std::vector<std::vector<float>>& shape_index, float quantum) {
  Grown grown;
  grown.nodes.assign(shape_index.size(), std::vector<SeedNode>(kWidth));
  const std::vector<SurfaceLabel> labels(kWidth, SurfaceLabel::kCurved);
  const std::vector<std::uint8_t> linked(kWidth, 0xFF);
  std::vector<std::uint8_t> edges(kWidth);
  for (int row = 0; row < static_cast<int>(shape_index.size()); ++row) {
    SeedRowInput input;
    input.width = input.column_end = kWidth;
    input.label = labels.data();
    input.label_above = row > 0 ? labels.data() : nullptr;
    input.shape_index = shape_index[static_cast<std::size_t>(row)].data();
    input.same_side = linked.data();
    backward_seed_edges(input, 1.0, edges.data());
    RowVectorNodes nodes{&grown.nodes, row};
    grow_seeds_in_row(input, edges.data(), quantum, nodes,
                      [&](std::int32_t a, std::int32_t b) { grown.crossings.emplace_back(a, b); });
  }
  return grown;
}

TEST(SeedUnionFind, ARowSplitsWhereItsRangeWouldExceedAQuantum) {
  Grown grown = grow({{0.10f, 0.12f, 0.30f, 0.33f}}, 0.05f);
  EXPECT_EQ(grown.root_of(0, 1), 0);
  EXPECT_EQ(grown.root_of(0, 3), 2);
  ASSERT_EQ(grown.crossings.size(), 1u);
  EXPECT_EQ(grown.crossings[0], std::make_pair(2, 0));
  // The root keeps its set's range.
  EXPECT_FLOAT_EQ(grown.nodes[0][2].low, 0.30f);
  EXPECT_FLOAT_EQ(grown.nodes[0][2].high, 0.33f);
}

TEST(SeedUnionFind, APixelJoinsTheSetGivingTheLeastRangeFirst) {
  // Row 0: the sets {0.10, 0.10} and {0.20, 0.20} (a quantum of 0.08 keeps them apart). Pixel
  // (1, 1) at 0.16 touches both and could join either, but not both: it joins the nearer,
  // the younger set of (2, 0), and crosses the other.
  Grown grown = grow({{0.10f, 0.10f, 0.20f, 0.20f}, {0.10f, 0.16f, 0.40f, 0.40f}}, 0.08f);
  EXPECT_EQ(grown.root_of(0, 1), 0);
  EXPECT_EQ(grown.root_of(0, 3), 2);
  EXPECT_EQ(grown.root_of(1, 0), 0);
  EXPECT_EQ(grown.root_of(1, 1), 2);
  EXPECT_FLOAT_EQ(grown.nodes[0][2].low, 0.16f);
  EXPECT_FLOAT_EQ(grown.nodes[0][2].high, 0.20f);
  // (2, 1) at 0.40 joins neither and opens a set beside both.
  EXPECT_EQ(grown.root_of(1, 2), 102);
  int crossings_of_row_1 = 0;
  for (const auto& [a, b] : grown.crossings) crossings_of_row_1 += a == 102 ? 1 : 0;
  EXPECT_GE(crossings_of_row_1, 2);
}

}  // namespace
}  // namespace cosmos
