// The parts by their extent along the belt: an interval visits exactly the parts whose y extent
// meets it, in the order of their starts, however long the belt.
#include "sim/belt_interval_index.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cosmos {
namespace {

Eigen::AlignedBox3d box_along_y(double y_low_mm, double y_high_mm) {
  return Eigen::AlignedBox3d(Eigen::Vector3d(-10.0, y_low_mm, 0.0),
                             Eigen::Vector3d(10.0, y_high_mm, 5.0));
}

std::vector<int> meeting(const BeltIntervalIndex& index, double y_low_mm, double y_high_mm) {
  std::vector<int> items;
  index.for_each_meeting(y_low_mm, y_high_mm, [&](int item) { items.push_back(item); });
  return items;
}

TEST(BeltIntervalIndex, AnIntervalVisitsThePartsItMeetsInTheOrderOfTheirStarts) {
  // Added out of order along the belt; item 3 is empty (never visited); item 4 is long and
  // starts far upstream of where it is met.
  std::vector<Eigen::AlignedBox3d> boxes = {box_along_y(-100.0, -60.0), box_along_y(0.0, 30.0),
                                            box_along_y(-50.0, -10.0), Eigen::AlignedBox3d(),
                                            box_along_y(-400.0, -5.0)};
  BeltIntervalIndex index;
  index.rebuild(boxes);
  EXPECT_EQ(index.size(), 4);
  EXPECT_EQ(meeting(index, -20.0, -20.0), (std::vector<int>{4, 2}));
  EXPECT_EQ(meeting(index, -8.0, 1.0), (std::vector<int>{4, 1}));
  EXPECT_EQ(meeting(index, 30.0, 40.0), (std::vector<int>{1}));  // a touching end meets
  EXPECT_EQ(meeting(index, 31.0, 1000.0), (std::vector<int>{}));
  EXPECT_EQ(meeting(index, -1000.0, -401.0), (std::vector<int>{}));
  EXPECT_EQ(meeting(index, -1000.0, 1000.0), (std::vector<int>{4, 0, 2, 1}));
}

TEST(BeltIntervalIndex, ThousandsOfPartsDownTheBeltVisitOnlyTheFewNearby) {
  std::vector<Eigen::AlignedBox3d> boxes;
  for (int i = 0; i < 5000; ++i) boxes.push_back(box_along_y(-120.0 * i - 80.0, -120.0 * i));
  BeltIntervalIndex index;
  index.rebuild(boxes);
  EXPECT_EQ(meeting(index, -120.0 * 4321 - 10.0, -120.0 * 4321 + 10.0), (std::vector<int>{4321}));
  EXPECT_EQ(meeting(index, -120.0 * 4321 - 100.0, -120.0 * 4321 - 90.0), (std::vector<int>{}));
  EXPECT_EQ(meeting(index, -120.0 * 4322 - 1.0, -120.0 * 4321 - 79.0),
            (std::vector<int>{4322, 4321}));
}

}  // namespace
}  // namespace cosmos
