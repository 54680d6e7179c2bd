// Parts on the belt as connected components across rows.
#include "realtime/loop/part_tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace cosmos {
namespace {

// Rows drawn as strings: '#' data, '.' background.
std::vector<std::vector<TrackedPart>> track(
    PartTracker& tracker, const std::vector<std::string>& rows,
    std::vector<std::vector<std::int64_t>>* labels = nullptr) {
  std::vector<std::vector<TrackedPart>> completed;
  std::int64_t index = 0;
  for (const std::string& text : rows) {
    std::vector<float> z(text.size());
    for (std::size_t i = 0; i < text.size(); ++i)
      z[i] = text[i] == '#' ? 5.0f : std::numeric_limits<float>::quiet_NaN();
    completed.push_back(tracker.add_row(z.data(), index++));
    if (labels) labels->push_back(tracker.row_labels());
  }
  return completed;
}

PartTrackerParameters small_parts() {
  PartTrackerParameters parameters;
  parameters.min_pixels = 3;
  return parameters;
}

TEST(PartTracker, TwoPartsSideBySideCompleteSeparately) {
  PartTracker tracker(small_parts(), 12);
  std::vector<std::vector<std::int64_t>> labels;
  const auto completed =
      track(tracker, {"##......###.", "###.....###.", ".##.........", "............"}, &labels);
  EXPECT_EQ(labels[1][0], 0);
  EXPECT_EQ(labels[1][9], 1);
  ASSERT_EQ(completed[2].size(), 1u);  // the right part ends first
  EXPECT_EQ(completed[2][0].id, 1);
  EXPECT_EQ(completed[2][0].pixels, 6);
  EXPECT_EQ(completed[2][0].last_row, 1);
  ASSERT_EQ(completed[3].size(), 1u);
  EXPECT_EQ(completed[3][0].id, 0);
  EXPECT_EQ(completed[3][0].first_row, 0);
  EXPECT_EQ(completed[3][0].last_row, 2);
  EXPECT_EQ(completed[3][0].column_min, 0);
  EXPECT_EQ(completed[3][0].column_max, 2);
  EXPECT_EQ(completed[3][0].pixels, 7);
  EXPECT_FALSE(completed[3][0].noise);
}

TEST(PartTracker, DiagonalAndSmallGapsStayConnected) {
  PartTracker tracker(small_parts(), 10);
  const auto completed = track(tracker, {"##........", "...##.....", "......##..", ".........."});
  ASSERT_EQ(completed[3].size(), 1u);  // one part: diagonal step, then a one-column gap
  EXPECT_EQ(completed[3][0].pixels, 6);
}

TEST(PartTracker, AUShapeMergesIntoTheEarlierPart) {
  PartTracker tracker(small_parts(), 10);
  const auto completed = track(tracker, {"##.....##.", "##.....##.", "#########.", ".........."});
  ASSERT_EQ(completed[2].size(), 1u);
  EXPECT_EQ(completed[2][0].id, 1);
  EXPECT_EQ(completed[2][0].merged_into, 0);
  ASSERT_EQ(completed[3].size(), 1u);
  EXPECT_EQ(completed[3][0].id, 0);
  EXPECT_EQ(completed[3][0].pixels, 17);
  EXPECT_EQ(completed[3][0].column_max, 8);
}

TEST(PartTracker, APieceEndingInsideAnOpenPartsFootprintJoinsIt) {
  // A horn cut off from the body by shadows along its whole length: when it ends, the body
  // has grown around it within the link gaps.
  PartTrackerParameters parameters = small_parts();
  parameters.link_gap_rows = 1;
  PartTracker tracker(parameters, 12);
  const auto completed =
      track(tracker, {"......##....", "#.....##....", "###...##....", "###.........",
                      "#####.......", "............", "............"});
  for (int row = 0; row < 4; ++row) EXPECT_TRUE(completed[row].empty()) << row;
  ASSERT_EQ(completed[4].size(), 1u);
  EXPECT_EQ(completed[4][0].id, 1);
  EXPECT_EQ(completed[4][0].merged_into, 0);
  EXPECT_TRUE(completed[5].empty());
  ASSERT_EQ(completed[6].size(), 1u);
  EXPECT_EQ(completed[6][0].id, 0);
  EXPECT_EQ(completed[6][0].pixels, 18);
  EXPECT_EQ(completed[6][0].first_row, 0);
  EXPECT_EQ(completed[6][0].last_row, 4);
  EXPECT_EQ(completed[6][0].column_min, 0);
  EXPECT_EQ(completed[6][0].column_max, 7);
}

TEST(PartTracker, SpecksAreNoiseAndCapacityIsBounded) {
  PartTrackerParameters parameters = small_parts();
  parameters.max_open_parts = 2;
  PartTracker tracker(parameters, 12);
  const auto completed = track(tracker, {"#...#...#...", "............"});
  EXPECT_EQ(tracker.dropped_runs(), 1);  // the third part found no free slot
  ASSERT_EQ(completed[1].size(), 2u);
  EXPECT_TRUE(completed[1][0].noise);
}

}  // namespace
}  // namespace cosmos
