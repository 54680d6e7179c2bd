// Widths of a point set (point_set_widths.hpp): along a direction, for a vector and a matrix's
// columns alike; across a direction, a rectangle's diagonal and short side; and the spread
// directions, unit vectors over the whole sphere or its upper half.
#include "core/modelbase/point_set_widths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cosmos {
namespace {

TEST(PointSetWidths, AlongADirectionTheSpanOfThePointsProjections) {
  const std::vector<Eigen::Vector3d> points{{0, 0, 0}, {100, 0, 0}, {0, 40, 0}, {30, 10, 25}};
  EXPECT_DOUBLE_EQ(width_along(points, Eigen::Vector3d::UnitX()), 100);
  EXPECT_DOUBLE_EQ(width_along(points, Eigen::Vector3d::UnitZ()), 25);
  EXPECT_NEAR(width_along(points, Eigen::Vector3d(1, 1, 0).normalized()), 100 / std::sqrt(2.0),
              1e-12);
  Eigen::Matrix3Xd columns(3, 4);
  for (int k = 0; k < 4; ++k) columns.col(k) = points[static_cast<std::size_t>(k)];
  EXPECT_DOUBLE_EQ(width_along(columns.colwise(), Eigen::Vector3d::UnitY()), 40);
  EXPECT_EQ(width_along(std::vector<Eigen::Vector3d>{}, Eigen::Vector3d::UnitX()), 0);
}

TEST(PointSetWidths, AcrossADirectionARectangleIsItsDiagonalWideAndItsShortSideNarrow) {
  const std::vector<Eigen::Vector3d> rectangle{{0, 0, 5}, {100, 0, 5}, {0, 40, 5}, {100, 40, 5}};
  const WidthsAcross across = widths_across(rectangle, Eigen::Vector3d::UnitZ(), 36);
  EXPECT_LE(across.widest_mm, std::sqrt(100.0 * 100 + 40 * 40) + 1e-9);
  EXPECT_GE(across.widest_mm, std::sqrt(100.0 * 100 + 40 * 40) - 0.1);
  EXPECT_NEAR(across.narrowest_mm, 40, 1e-9);
  // Seen along the long side, the rectangle is 40 wide and has no depth.
  const WidthsAcross end_on = widths_across(rectangle, Eigen::Vector3d::UnitX(), 36);
  EXPECT_NEAR(end_on.widest_mm, 40, 1e-9);
  EXPECT_NEAR(end_on.narrowest_mm, 0, 1e-9);
}

TEST(PointSetWidths, SpreadDirectionsAreUnitVectorsOverTheirPartOfTheSphere) {
  constexpr int kCount = 500;
  int lower_half = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < kCount; ++k) {
    const Eigen::Vector3d upper = spread_direction(k, kCount, SphereCover::kUpperHalf);
    const Eigen::Vector3d whole = spread_direction(k, kCount, SphereCover::kWhole);
    EXPECT_NEAR(upper.norm(), 1, 1e-12);
    EXPECT_NEAR(whole.norm(), 1, 1e-12);
    EXPECT_GT(upper.z(), 0);
    lower_half += whole.z() < 0 ? 1 : 0;
    sum += whole;
  }
  EXPECT_EQ(lower_half, kCount / 2);
  EXPECT_LT(sum.norm() / kCount, 0.01);  // evenly spread: no side favoured
}

}  // namespace
}  // namespace cosmos
