// The occupied cells of a registration grid as run lengths: they read back as written, and
// runs that do not cover the grid, or hold another number of points, are told apart.
#include "core/registration/occupied_cell_runs.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cosmos {
namespace {

std::vector<std::int32_t> occupied_cells_of(std::span<const std::uint8_t> runs, std::size_t cells,
                                            std::size_t points, bool& consistent) {
  std::vector<std::int32_t> cell_point(cells, -1);
  std::int32_t next = 0;
  consistent =
      visit_occupied_cell_runs(runs, cells, points, [&](std::size_t first, std::size_t end) {
        for (std::size_t cell = first; cell < end; ++cell) cell_point[cell] = next++;
      });
  return cell_point;
}

TEST(OccupiedCellRuns, RunsReadBackAsWritten) {
  // Starting occupied (an empty first run of length 0), gaps of 1 and 5, ending empty.
  const std::vector<std::int32_t> cell_point = {0, 1, -1, 2, -1, -1, -1, -1, -1, 3, 4, -1};
  const std::vector<std::uint8_t> runs = encode_occupied_cell_runs(cell_point);
  // Runs 0, 2, 1, 1, 5, 2, 1 as gamma codes of 1, 3, 2, 2, 6, 3, 2: 1+3+3+3+5+3+3 = 21 bits.
  EXPECT_EQ(runs.size(), 3u);
  bool consistent = false;
  EXPECT_EQ(occupied_cells_of(runs, cell_point.size(), 5, consistent), cell_point);
  EXPECT_TRUE(consistent);
}

TEST(OccupiedCellRuns, RunsThatDoNotFitTheGridOrThePointCountAreInconsistent) {
  const std::vector<std::int32_t> cell_point = {-1, 0, 1, -1, 2, -1};
  const std::vector<std::uint8_t> runs = encode_occupied_cell_runs(cell_point);
  bool consistent = true;
  occupied_cells_of(runs, 6, 2, consistent);  // one point more than announced
  EXPECT_FALSE(consistent);
  occupied_cells_of(runs, 6, 4, consistent);  // one fewer
  EXPECT_FALSE(consistent);
  occupied_cells_of(runs, 5, 3, consistent);  // a smaller grid
  EXPECT_FALSE(consistent);
  occupied_cells_of(runs, 9, 3, consistent);  // a larger one: the runs end before it does
  EXPECT_FALSE(consistent);
  occupied_cells_of(std::span<const std::uint8_t>(runs).first(1), 6, 3, consistent);
  EXPECT_FALSE(consistent);
  occupied_cells_of(runs, 6, 3, consistent);
  EXPECT_TRUE(consistent);
  EXPECT_TRUE(encode_occupied_cell_runs({}).empty());
}

}  // namespace
}  // namespace cosmos
