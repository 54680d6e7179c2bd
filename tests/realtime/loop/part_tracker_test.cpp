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

TEST(PartTracker, FewPixelsAlongManyRowsAreAPartNotASpeck) {
  PartTrackerParameters parameters;
  parameters.min_pixels = 6;
  parameters.link_gap_rows = 1;
  PartTracker tracker(parameters, 4);
  // 5 pixels, 1 column, over 9 rows (a thin edge with dropouts), then 4 pixels in a 2 x 2 box.
  const auto completed =
      track(tracker, {".#..", "....", ".#..", "....", ".#..", "....", ".#..", "....", ".#..",
                      "....", "....", "##..", "##..", "....", "...."});
  std::vector<TrackedPart> parts;
  for (const auto& row : completed) parts.insert(parts.end(), row.begin(), row.end());
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].pixels, 5);
  EXPECT_FALSE(parts[0].noise);
  EXPECT_EQ(parts[1].pixels, 4);
  EXPECT_TRUE(parts[1].noise);
}

}  // namespace
}  // namespace cosmos

namespace cosmos {
namespace {

// Rows with heights: a digit is data that many tens of mm high ('1' = 10 mm), 'b' the belt
// measured, '.' no data (shadow).
std::vector<TrackedPart> track_with_belt(PartTracker& tracker,
                                         const std::vector<std::string>& rows) {
  std::vector<TrackedPart> completed;
  std::int64_t index = 0;
  for (const std::string& text : rows) {
    std::vector<float> z(text.size(), std::numeric_limits<float>::quiet_NaN());
    std::vector<std::uint8_t> belt(text.size(), 0);
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] >= '1' && text[i] <= '9') z[i] = 10.0f * static_cast<float>(text[i] - '0');
      belt[i] = text[i] == 'b' ? 1 : 0;
    }
    for (const TrackedPart& part : tracker.add_row(z.data(), index++, belt.data()))
      completed.push_back(part);
  }
  return completed;
}

PartTrackerParameters shadow_tracking() {
  PartTrackerParameters parameters;
  parameters.min_pixels = 1;
  parameters.link_gap_rows = 8;
  parameters.hard_link_gap_rows = 1;
  parameters.shadow_rows_per_mm = 0.1;  // 10 mm of height shadows 1 row (+ the margin)
  return parameters;
}

std::vector<std::string> with_gap(const std::string& gap_row, int gap_rows, char height) {
  std::vector<std::string> rows{"..1111..", "..1111.."};
  for (int k = 0; k < gap_rows; ++k) rows.push_back(gap_row);
  rows.push_back(std::string("..") + std::string(4, height) + "..");
  for (int k = 0; k < 10; ++k) rows.push_back("bbbbbbbb");
  return rows;
}

TEST(PartTracker, AGapTheLaterPiecesShadowExplainsIsASoftLink) {
  PartTracker tracker(shadow_tracking(), 8);
  // 40 mm high: shadows ceil(40 x 0.1 x 1.15 + 4) = 9 rows; the gap is 6 rows of no data.
  const std::vector<TrackedPart> completed = track_with_belt(tracker, with_gap("........", 6, '4'));
  ASSERT_EQ(completed.size(), 2u);
  EXPECT_EQ(completed[0].id, 0);
  EXPECT_TRUE(completed[0].has_soft_successor);
  EXPECT_EQ(completed[1].soft_link_of, 0);
  EXPECT_EQ(completed[1].merged_into, -1);
}

TEST(PartTracker, BeltSeenInTheGapOrAGapLongerThanTheShadowMakesTwoParts) {
  {
    PartTracker tracker(shadow_tracking(), 8);
    const std::vector<TrackedPart> completed =
        track_with_belt(tracker, with_gap("bbbbbbbb", 6, '4'));
    ASSERT_EQ(completed.size(), 2u);
    EXPECT_FALSE(completed[0].has_soft_successor);
    EXPECT_EQ(completed[1].soft_link_of, -1);
  }
  {
    PartTracker tracker(shadow_tracking(), 8);
    // 10 mm high shadows 6 rows at most; the gap is 7.
    const std::vector<TrackedPart> completed =
        track_with_belt(tracker, with_gap("........", 7, '1'));
    ASSERT_EQ(completed.size(), 2u);
    EXPECT_EQ(completed[1].soft_link_of, -1);
  }
}

TEST(PartTracker, PiecesTooSmallToBePartsJoinThePieceSoftlyLinkedAfterThem) {
  PartTrackerParameters parameters = shadow_tracking();
  parameters.min_pixels = 5;
  PartTracker tracker(parameters, 8);
  // A thin edge rising along the belt, cut by its shadow into pieces of 2 pixels: alone each
  // would be noise, together they are one part of 6.
  const std::vector<TrackedPart> completed = track_with_belt(
      tracker, {"11......", "........", "........", ".22.....", "........", "........", "..33....",
                "bbbbbbbb", "bbbbbbbb", "bbbbbbbb", "bbbbbbbb", "bbbbbbbb", "bbbbbbbb", "bbbbbbbb",
                "bbbbbbbb", "bbbbbbbb", "bbbbbbbb"});
  ASSERT_EQ(completed.size(), 3u);
  EXPECT_EQ(completed[0].merged_into, 0);
  EXPECT_EQ(completed[1].merged_into, 0);
  EXPECT_EQ(completed[2].id, 0);
  EXPECT_EQ(completed[2].pixels, 6);
  EXPECT_FALSE(completed[2].noise);
  EXPECT_EQ(completed[2].first_row, 0);
  EXPECT_EQ(completed[2].last_row, 6);
  EXPECT_EQ(completed[2].column_max, 3);
  EXPECT_FLOAT_EQ(completed[2].max_z_mm, 30.0f);
  EXPECT_EQ(completed[2].soft_link_of, -1);
  EXPECT_FALSE(completed[2].has_soft_successor);
}

TEST(PartTracker, ADropoutOfHardLinkGapRowsJoinsOutright) {
  PartTracker tracker(shadow_tracking(), 8);
  const std::vector<TrackedPart> completed = track_with_belt(tracker, with_gap("........", 1, '4'));
  ASSERT_EQ(completed.size(), 1u);
  EXPECT_EQ(completed[0].last_row, 3);
  EXPECT_EQ(completed[0].soft_link_of, -1);
  EXPECT_FLOAT_EQ(completed[0].max_z_mm, 40.0f);
}

}  // namespace
}  // namespace cosmos
