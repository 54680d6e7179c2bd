// The simulated conveyor's layouts: gaps along the belt (fixed, seeded from a range, 0 for
// touching, groups touching end to end) and pairs side by side across the belt.
#include "sim/source/part_layout.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cosmos {
namespace {

constexpr double kHalfFieldMm = 128.0;

std::vector<Eigen::Vector3d> boxes() {
  return {{40, 30, 10}, {20, 50, 10}, {30, 20, 10}, {50, 40, 10}, {10, 10, 10}};
}

// Belt between the boxes of consecutive slots along y (downstream end of the later one to the
// upstream end of the earlier one).
double gap_between(const PartPlacement& earlier, const Eigen::Vector3d& earlier_box,
                   const PartPlacement& later, const Eigen::Vector3d& later_box) {
  return (earlier.y_mm - 0.5 * earlier_box.y()) - (later.y_mm + 0.5 * later_box.y());
}

TEST(PartLayout, FixedGapsLeaveTheGapBetweenBoxesAfterALeadIn) {
  SimulatedConveyorSettings settings;
  settings.part_gap_mm = 12.0;
  const std::vector<PartPlacement> placed = lay_out_parts(boxes(), settings, kHalfFieldMm);
  ASSERT_EQ(placed.size(), 5u);
  EXPECT_NEAR(placed[0].y_mm + 0.5 * boxes()[0].y(), -12.0, 1e-9);
  for (std::size_t i = 1; i < placed.size(); ++i) {
    EXPECT_NEAR(gap_between(placed[i - 1], boxes()[i - 1], placed[i], boxes()[i]), 12.0, 1e-9);
    EXPECT_EQ(placed[i].x_mm, 0.0);  // centred without random_x_offset
  }
}

TEST(PartLayout, TouchingPartsAreAMicrometreApartAfterTheMinimumLeadIn) {
  SimulatedConveyorSettings settings;
  settings.part_gap_mm = 0.0;
  const std::vector<PartPlacement> placed = lay_out_parts(boxes(), settings, kHalfFieldMm);
  EXPECT_NEAR(placed[0].y_mm + 0.5 * boxes()[0].y(), -kMinLeadInMm, 1e-9);
  for (std::size_t i = 1; i < placed.size(); ++i)
    EXPECT_NEAR(gap_between(placed[i - 1], boxes()[i - 1], placed[i], boxes()[i]), 0.0, 2e-3);
}

TEST(PartLayout, RandomGapsAreSeededAndWithinTheirRange) {
  SimulatedConveyorSettings settings;
  settings.part_gap_mm = 5.0;
  settings.part_gap_max_mm = 30.0;
  std::vector<Eigen::Vector3d> many(200, Eigen::Vector3d(20, 20, 10));
  const std::vector<PartPlacement> placed = lay_out_parts(many, settings, kHalfFieldMm);
  double smallest = 1e9, largest = 0;
  for (std::size_t i = 1; i < placed.size(); ++i) {
    const double gap = gap_between(placed[i - 1], many[i - 1], placed[i], many[i]);
    smallest = std::min(smallest, gap);
    largest = std::max(largest, gap);
  }
  EXPECT_GE(smallest, 5.0);
  EXPECT_LT(smallest, 6.0);  // 199 draws over 25 mm reach near both ends
  EXPECT_LE(largest, 30.0);
  EXPECT_GT(largest, 29.0);
  const std::vector<PartPlacement> again = lay_out_parts(many, settings, kHalfFieldMm);
  EXPECT_EQ(again[57].y_mm, placed[57].y_mm);
  settings.seed += 1;
  EXPECT_NE(lay_out_parts(many, settings, kHalfFieldMm)[57].y_mm, placed[57].y_mm);
}

TEST(PartLayout, GroupsTouchEndToEndAndKeepTheGapBetweenThem) {
  SimulatedConveyorSettings settings;
  settings.part_gap_mm = 40.0;
  settings.group_size = 2;
  const std::vector<PartPlacement> placed = lay_out_parts(boxes(), settings, kHalfFieldMm);
  EXPECT_NEAR(gap_between(placed[0], boxes()[0], placed[1], boxes()[1]), 0.0, 2e-3);
  EXPECT_NEAR(gap_between(placed[1], boxes()[1], placed[2], boxes()[2]), 40.0, 1e-9);
  EXPECT_NEAR(gap_between(placed[2], boxes()[2], placed[3], boxes()[3]), 0.0, 2e-3);
}

TEST(PartLayout, PairsSideBySideAcrossTheBeltTouchOrKeepTheirGap) {
  SimulatedConveyorSettings settings;
  settings.side_by_side = true;
  settings.across_gap_mm = 6.0;
  const std::vector<PartPlacement> placed = lay_out_parts(boxes(), settings, kHalfFieldMm);
  // Pair (0, 1): level downstream ends, 6 mm between the boxes, centred as a pair.
  EXPECT_NEAR(placed[0].y_mm + 0.5 * boxes()[0].y(), placed[1].y_mm + 0.5 * boxes()[1].y(), 1e-9);
  const double between =
      (placed[1].x_mm - 0.5 * boxes()[1].x()) - (placed[0].x_mm + 0.5 * boxes()[0].x());
  EXPECT_NEAR(between, 6.0, 1e-9);
  EXPECT_NEAR(placed[0].x_mm - 0.5 * boxes()[0].x() + placed[1].x_mm + 0.5 * boxes()[1].x(), 0.0,
              1e-9);
  // The next pair starts part_gap_mm behind the longer of the two.
  EXPECT_NEAR((placed[1].y_mm - 0.5 * boxes()[1].y()) - (placed[2].y_mm + 0.5 * boxes()[2].y()),
              settings.part_gap_mm, 1e-9);
  EXPECT_NEAR(placed[4].y_mm + 0.5 * boxes()[4].y(),
              placed[2].y_mm + 0.5 * boxes()[2].y() - 40.0 - settings.part_gap_mm, 1e-9);
}

}  // namespace
}  // namespace cosmos
